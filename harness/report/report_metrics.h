// Error metrics between two images of the same size (width, height and channels), for
// comparing a pass's output with an expected or reference image.
//
// Luminance: Rec. 709 (0.2126 R + 0.7152 G + 0.0722 B) for 3 or 4 channels (alpha ignored),
// the value itself for 1 channel and the length of (R, G) for 2 channels (motion).
//
// Non-finite samples (NaN, +-Inf): no function here returns NaN. Scalar metrics skip every
// pixel where either image has a non-finite sample among the channels they read, and return
// 0 when nothing is left; nonFiniteFraction and ImageDiff::nonFinite count such pixels so a
// caller can fail on them. relativeErrorMap writes +Inf there (shown magenta by writePng).
//
// Images of different sizes, and masks whose size differs from the images', throw
// std::runtime_error with one line naming both sizes.
#pragma once

#include "report/report_image.h"

#include <cstddef>

namespace glint::report {

// Root mean square difference over the colour channels (the first three of 3 or 4, both of 2,
// the one of 1), averaged over samples. With a mask (1 channel, same width and height), only
// pixels whose mask value is > 0 count (a NaN mask value excludes the pixel).
double rmse(const Image& a, const Image& b, const Image* mask = nullptr);

// Per pixel: luminance(|a - reference|) / max(|luminance(reference)|, eps), as a 1-channel
// image of the same size; |a - reference| is per channel, so a hue error counts even when the
// luminances agree. eps keeps black reference pixels from dividing by zero.
Image relativeErrorMap(const Image& a, const Image& reference, float eps = 1e-3f);

// The fraction of pixels with at least one non-finite sample (any channel); 0 for an empty image.
double nonFiniteFraction(const Image& image);

// Mean luminance over the pixels whose luminance is finite; 0 when there are none.
double meanLuminance(const Image& image);

struct ImageDiff {
    double maxAbs = 0.0;       // largest |actual - expected| over samples finite in both
    double rmse = 0.0;         // over samples finite in both, all channels (alpha included)
    std::size_t differing = 0; // pixels with at least one differing sample
    std::size_t nonFinite = 0; // pixels of `actual` with at least one non-finite sample
};

// Compares every channel of every pixel. A pair of finite samples differs when
// |actual - expected| > absTolerance + relTolerance * |expected|; a NaN matches only a NaN and
// an infinity only the same infinity; finite against non-finite always differs. Tolerances
// must be finite and >= 0.
ImageDiff diffImages(const Image& actual, const Image& expected, double absTolerance, double relTolerance);

} // namespace glint::report
