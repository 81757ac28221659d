#include "report/report_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace glint::report {

namespace {

std::string sizeText(const Image& image) {
    return std::to_string(image.width) + "x" + std::to_string(image.height) + "x" +
           std::to_string(image.channels);
}

std::size_t pixelCount(const Image& image) {
    return std::size_t{image.width} * image.height;
}

void checkConsistent(const Image& image) {
    if (image.pixels.size() != pixelCount(image) * image.channels)
        throw std::runtime_error("image of " + sizeText(image) + " holds " +
                                 std::to_string(image.pixels.size()) + " samples");
}

void checkSameSize(const Image& a, const Image& b) {
    checkConsistent(a);
    checkConsistent(b);
    if (a.width != b.width || a.height != b.height || a.channels != b.channels)
        throw std::runtime_error("images differ in size: " + sizeText(a) + " vs " + sizeText(b));
}

std::uint32_t colourChannels(const Image& image) {
    return std::min(image.channels, 3u);
}

bool allFinite(const float* px, std::uint32_t count) {
    for (std::uint32_t c = 0; c < count; ++c)
        if (!std::isfinite(px[c])) return false;
    return true;
}

// Luminance as defined in the header, from doubles (so |a - b| is exact before weighting).
double luminance(const double* v, std::uint32_t channels) {
    if (channels == 1) return v[0];
    if (channels == 2) return std::hypot(v[0], v[1]);
    return 0.2126 * v[0] + 0.7152 * v[1] + 0.0722 * v[2];
}

double luminanceOf(const float* px, std::uint32_t channels) {
    const double v[3] = {px[0], channels > 1 ? double{px[1]} : 0.0, channels > 2 ? double{px[2]} : 0.0};
    return luminance(v, channels);
}

} // namespace

double rmse(const Image& a, const Image& b, const Image* mask) {
    checkSameSize(a, b);
    if (mask != nullptr) {
        checkConsistent(*mask);
        if (mask->width != a.width || mask->height != a.height || mask->channels != 1)
            throw std::runtime_error("mask of " + sizeText(*mask) + " does not fit images of " + sizeText(a) +
                                     " (it needs 1 channel)");
    }
    const std::uint32_t used = colourChannels(a);
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < pixelCount(a); ++i) {
        if (mask != nullptr && !(mask->pixels[i] > 0.0f)) continue;
        const float* pa = a.pixels.data() + i * a.channels;
        const float* pb = b.pixels.data() + i * b.channels;
        if (!allFinite(pa, used) || !allFinite(pb, used)) continue;
        for (std::uint32_t c = 0; c < used; ++c) {
            const double d = double{pa[c]} - double{pb[c]};
            sum += d * d;
        }
        count += used;
    }
    if (count == 0) return 0.0;
    // Finite floats differ by at most ~6.8e38, whose square fits in a double; the sum of
    // at most 2^29 of them still does, so the result is finite.
    return std::sqrt(sum / static_cast<double>(count));
}

Image relativeErrorMap(const Image& a, const Image& reference, float eps) {
    checkSameSize(a, reference);
    const double floor = std::isfinite(eps) && eps > 0.0f ? double{eps} : 1e-3;
    const std::uint32_t used = colourChannels(a);
    Image map;
    map.width = a.width;
    map.height = a.height;
    map.channels = 1;
    map.pixels.resize(pixelCount(a));
    for (std::size_t i = 0; i < pixelCount(a); ++i) {
        const float* pa = a.pixels.data() + i * a.channels;
        const float* pr = reference.pixels.data() + i * reference.channels;
        if (!allFinite(pa, used) || !allFinite(pr, used)) {
            map.pixels[i] = std::numeric_limits<float>::infinity();
            continue;
        }
        double diff[3] = {0.0, 0.0, 0.0};
        for (std::uint32_t c = 0; c < used; ++c) diff[c] = std::abs(double{pa[c]} - double{pr[c]});
        const double error = luminance(diff, used) / std::max(std::abs(luminanceOf(pr, used)), floor);
        // Clamped to FLT_MAX (huge differences over a tiny reference) so that only a non-finite
        // input reads as +Inf in the map.
        map.pixels[i] = static_cast<float>(std::min(error, double{std::numeric_limits<float>::max()}));
    }
    return map;
}

double nonFiniteFraction(const Image& image) {
    checkConsistent(image);
    const std::size_t pixels = pixelCount(image);
    if (pixels == 0 || image.channels == 0) return 0.0;
    std::size_t bad = 0;
    for (std::size_t i = 0; i < pixels; ++i)
        if (!allFinite(image.pixels.data() + i * image.channels, image.channels)) ++bad;
    return static_cast<double>(bad) / static_cast<double>(pixels);
}

double meanLuminance(const Image& image) {
    checkConsistent(image);
    if (image.channels == 0) return 0.0;
    const std::uint32_t used = colourChannels(image);
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < pixelCount(image); ++i) {
        const float* px = image.pixels.data() + i * image.channels;
        if (!allFinite(px, used)) continue;
        const double y = luminanceOf(px, used);
        if (!std::isfinite(y)) continue; // hypot or the weighted sum of huge values can overflow
        sum += y;
        ++count;
    }
    if (count == 0) return 0.0;
    const double mean = sum / static_cast<double>(count);
    return std::isfinite(mean) ? mean : 0.0;
}

ImageDiff diffImages(const Image& actual, const Image& expected, double absTolerance, double relTolerance) {
    checkSameSize(actual, expected);
    if (!(absTolerance >= 0.0) || !(relTolerance >= 0.0) || !std::isfinite(absTolerance) ||
        !std::isfinite(relTolerance))
        throw std::runtime_error("tolerances must be finite and >= 0, got absolute " +
                                 std::to_string(absTolerance) + ", relative " + std::to_string(relTolerance));
    ImageDiff diff;
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < pixelCount(actual); ++i) {
        const float* pa = actual.pixels.data() + i * actual.channels;
        const float* pe = expected.pixels.data() + i * expected.channels;
        bool differs = false, nonFinite = false;
        for (std::uint32_t c = 0; c < actual.channels; ++c) {
            const float a = pa[c], e = pe[c];
            if (!std::isfinite(a)) nonFinite = true;
            if (std::isfinite(a) && std::isfinite(e)) {
                const double d = std::abs(double{a} - double{e});
                diff.maxAbs = std::max(diff.maxAbs, d);
                sum += d * d;
                ++count;
                if (d > absTolerance + relTolerance * std::abs(double{e})) differs = true;
            } else if (std::isnan(a) && std::isnan(e)) {
                // equal: both NaN
            } else if (a != e) {
                differs = true; // finite vs non-finite, or opposite infinities
            }
        }
        if (differs) ++diff.differing;
        if (nonFinite) ++diff.nonFinite;
    }
    diff.rmse = count == 0 ? 0.0 : std::sqrt(sum / static_cast<double>(count));
    return diff;
}

} // namespace glint::report
