// An independent CPU reference of the shadow denoiser's classification and temporal pass,
// written from docs/shadow_denoiser.md ("Classification and temporal accumulation") alone and
// computed in double: the 17x17 Gaussian straight over the visibility image with the exact
// weights exp(-3 i^2 / 81) (not the shader's 2^-20 multiples, not its bit windows), and the
// anti-lag scores from their documented statistics.
//
// Since the device rounds its weights and works in float, the result is a range per value, not
// a value: the documented weight rounding (at most 3e-6 a weight) moves the window mean by at
// most 2 * 17 * 3e-6 = 1.02e-4 (plus float summation, ~1e-6), and the clamp radius, the history
// damping and the variance follow the mean, ill-conditioned where sigma_s is small. So every
// output is evaluated at means across [mu - e, mu + e], e = 1.1e-4, with the bilinear history
// moved by its float error (5e-5: uv_prev * size rounds by ~2e-7 W pixels) and the anti-lag
// score by its (1e-4: 25-term float sums), and the range of the results returned. A pixel whose
// result hinges on a discrete decision within float rounding of its threshold (a floor at a
// pixel edge, the disocclusion or anti-lag depth tests at their bound, the history length at the
// variance boost's step at 16, a tie for the closest receiver of the quad between different
// motions) is marked ambiguous.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace glint::reference {

struct ShadowClassifyInputs {
    std::uint32_t width = 0, height = 0;
    std::vector<float> depth;             // W x H
    std::vector<float> previousDepth;     // W x H
    std::vector<float> normals;           // RGBA, unpacked
    std::vector<float> motion;            // RG, convention A
    std::vector<float> momentsHistory;    // RGBA (mean, M2, n, accumulated shadow)
    std::array<float, 16> reprojection{}; // row-major, column vectors
    std::array<float, 16> inverseViewProjection{};
    std::array<float, 3> eye{};
    float viewDepth[3] = {0.1f, 1.0f, -1.0f};
    float ndcYSign = 1.0f;
    bool reset = false;
    bool antiLag = true;                      // the 5x5 anti-lag test
    float storedVarianceScale = 1.0f / 16.0f; // times the variance of the accumulated mean
    // Hard shadows pass through (docs/shadow_denoiser.md): with penumbraScale >= 0 a receiver
    // whose 9 x 9 neighbourhood (clamped to the image) has no penumbra width
    // penumbraScale * blocker / z above 1 pixel stores (sample, 0) and moments (sample, 0, 1,
    // sample). Negative: no estimate. blockerDistance (W x H) is read only with penumbraScale > 0.
    float penumbraScale = -1.0f;
    std::vector<float> blockerDistance;
};

struct ShadowClassifyRanges {
    std::vector<std::uint32_t> metadata;                       // one per 8x8 tile
    std::vector<double> shadowVarianceLow, shadowVarianceHigh; // RG
    std::vector<double> momentsLow, momentsHigh;               // RGBA (mean, M2, n, accumulated shadow)
    std::vector<std::uint8_t> ambiguous;                       // per pixel: not to be compared
};

// The mean's allowed deviation from the exact-weight window mean (see above).
constexpr double kShadowClassifyMeanSlack = 1.1e-4;

// The statistics come from `visibility` (W x H, >= 0.5 lit, NaN shadowed) with the documented
// addressing: rows outside the image clamp to the border row; columns outside it read the border
// mask tile, whose bits outside the image repeat the nearest pixel. `in.momentsHistory` is the
// history as the device reads it: with rebuildClearHistory, last frame's clear tiles hold their
// documented rebuilt values there.
ShadowClassifyRanges shadowClassifyIndependent(const ShadowClassifyInputs& in,
                                               const std::vector<float>& visibility);

} // namespace glint::reference
