// The error of an effect's final output against the capture's converged reference, over the
// pixels the effect is responsible for, as its descriptor's evaluation says (ScoredOutput,
// glint_effect.h): the first of its `final` outputs the frame has against the output
// "reference" (the capture's reference layer), over its mask, in its metric:
//   RelativeLuminance  per-pixel |out - ref| (luminance of the per-channel difference) divided
//                      by max(luminance(ref), 0.05), the metric the denoiser tests use (the
//                      reflections, over glossy pixels: GGX alpha below roughnessThreshold)
//   Absolute           per-pixel luminance of |out - ref|
//   Visibility         per-pixel |out - ref| (the shadows, over receivers); `penumbra` is the
//                      mean over reference in (0.05, 0.95)
// Masks: Surface is every pixel whose depth is not the background; SurfaceAlphaBelow those of
// them whose GGX alpha is below the setting the mask names.
// Moving edges (Visibility): the mask's pixels where the reference changed by more than
// kMovingEdgeChange since the previous frame of the sequence, at the same pixel; the error of
// the output and of its noisy input over them.
// Non-finite output pixels count in `nonFinite` and as error 1 in the map, never as NaN.
// `maeClamped`: radiance (or visibility) clamped to [0, kMaeClamp] per channel, then the mean of
// |out - ref| over the colour channels and the mask's pixels; bounded, so a few fireflies in
// either image cannot dominate it the way they dominate the relative error. `rmseClamped` is the
// RMSE of the same clamped values.
#pragma once

#include "capture/capture_frame.h"
#include "replay/replay_session.h"

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace glint::replay {

// The upper end of the range `maeClamped` clamps radiance to (the lower end is 0).
inline constexpr double kMaeClamp = 16.0;

// The change of the reference since the previous frame above which a pixel is a moving edge.
inline constexpr float kMovingEdgeChange = 0.25f;

struct ReferenceError {
    std::string effect;       // "reflections"
    std::string image;        // the image compared, "reflections/denoised"
    std::size_t pixels = 0;   // pixels in the mask
    double mean = 0.0;        // mean per-pixel error over the mask
    double rmse = 0.0;        // RMSE of the colour channels over the mask
    double maeClamped = 0.0;  // mean |out - ref| of the colour channels clamped to [0, kMaeClamp]
    double rmseClamped = 0.0; // RMSE of the same clamped colour channels
    double penumbra = -1.0;   // shadows: mean |error| over penumbra pixels (-1 when there are none)
    double noisyMean = -1.0;  // the same mean for the effect's noisy input, when the output is denoised
    double noisyRmse = -1.0;  // and its rmse
    // referenceNoise only: the output's mean error minus its noisy input's, both against the
    // second reference (NaN without a noisy input): what the first reference says of the
    // difference, said again by an independent one.
    double differenceAgainstSecond = std::numeric_limits<double>::quiet_NaN();
    double nonFinite = 0.0;  // fraction of output pixels (all, not only the mask) that are not finite
    bool visibility = false; // ErrorMetric::Visibility (penumbra and moving edges apply)
    // The mask's threshold (ErrorMask::SurfaceAlphaBelow: the value of its setting), -1 without one.
    double maskThreshold = -1.0;
    // Visibility effects: the moving-edge pixels (movingEdgeMask) and the mean |out - ref| over
    // them of the output and of its noisy input; 0 and empty without a previous frame or when no
    // pixel moved.
    std::size_t movingEdgePixels = 0;
    std::optional<double> movingEdge;
    std::optional<double> noisyMovingEdge;
    report::Image map; // per-pixel error, 0 outside the mask
};

// The pixels `mask` covers in `frame`, as above, its threshold read from `settings`: 1 inside,
// 0 outside.
std::vector<std::uint8_t> errorMask(const capture::Frame& frame, const ErrorMask& mask,
                                    const SettingValues& settings);

// The scored output of `effect` (the first of its descriptor's, which every tool scores), or
// none for an effect that is not scored or not known.
const ScoredOutput* scoredOutput(const std::string& effect);

// The pixels of `mask` where the reference's first channel differs from the previous frame's
// at the same pixel by more than `change`: 1 there, 0 elsewhere and where either is not finite.
// Both references must have the mask's pixel count (std::invalid_argument otherwise).
std::vector<std::uint8_t> movingEdgeMask(const report::Image& reference,
                                         const report::Image& previousReference,
                                         const std::vector<std::uint8_t>& mask,
                                         float change = kMovingEdgeChange);

// One entry per scored effect whose output and reference are both in `result`, in the
// registry's order; `settings` give the masks their thresholds. `previous`, the sequence's frame
// before `frame` (none on its first frame), gives the visibility effects their moving edges from
// its reference layer; a `previous` of another size throws std::invalid_argument naming both
// sizes.
std::vector<ReferenceError> referenceErrors(const capture::Frame& frame, const FrameResult& result,
                                            const SettingValues& settings,
                                            const capture::Frame* previous = nullptr);

// The noise of the capture's own references (with differenceAgainstSecond where the effect's
// output has a noisy input): for every effect referenceErrors scores, the
// reference in `result` against `second`'s reference layer (the same frame rendered again with
// an independent seed), in the same metric and over the same mask, taken from `frame`. Its
// `mean` is the floor under which an effect's error cannot be told from zero. An effect whose
// reference `second` lacks is left out; a `second` of another size throws
// std::invalid_argument naming both sizes.
std::vector<ReferenceError> referenceNoise(const capture::Frame& frame, const FrameResult& result,
                                           const capture::Frame& second, const SettingValues& settings);

} // namespace glint::replay
