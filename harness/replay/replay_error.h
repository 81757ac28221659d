// The error of an effect's final output against the capture's converged reference, over the
// pixels the effect is responsible for:
//   reflections  "denoised" (or "noisy" without the denoiser) against reference.reflection over
//                glossy pixels (GGX alpha below the roughness threshold, depth not background);
//                per-pixel error |out - ref| (luminance of the per-channel difference) divided by
//                max(luminance(ref), 0.05), the metric the denoiser tests use
//   shadows      "denoised" against reference.shadow over receivers (depth not background);
//                per-pixel |out - ref|; `penumbra` is the mean over reference in (0.05, 0.95)
// Non-finite output pixels count in `nonFinite` and as error 1 in the map, never as NaN.
#pragma once

#include "capture/capture_frame.h"
#include "replay/replay_session.h"

#include <cstdint>
#include <string>
#include <vector>

namespace glint::replay {

struct ReferenceError {
    std::string effect;      // "reflections"
    std::string image;       // the image compared, "reflections/denoised"
    std::size_t pixels = 0;  // pixels in the mask
    double mean = 0.0;       // mean per-pixel error over the mask
    double rmse = 0.0;       // RMSE of the colour channels over the mask
    double penumbra = -1.0;  // shadows: mean |error| over penumbra pixels (-1 when there are none)
    double noisyMean = -1.0; // the same mean for the effect's noisy input, when the output is denoised
    double nonFinite = 0.0;  // fraction of output pixels (all, not only the mask) that are not finite
    report::Image map;       // per-pixel error, 0 outside the mask
};

// The pixels the error of `effect` ("reflections" or "shadows") is measured over, as above:
// 1 inside, 0 outside.
std::vector<std::uint8_t> errorMask(const capture::Frame& frame, const std::string& effect,
                                    float roughnessThreshold);

// One entry per effect whose output and reference are both in `result`.
std::vector<ReferenceError> referenceErrors(const capture::Frame& frame, const FrameResult& result,
                                            float roughnessThreshold);

} // namespace glint::replay
