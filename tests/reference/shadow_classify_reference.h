// CPU reference of the shadow denoiser's tile classification + temporal pass
// (docs/shadow_denoiser.md) that mirrors the shader: the same 2^-20 weights, bit windows and
// float formulas, so it agrees with the device to a few ulps and shares the shader's bugs.
// shadow_classify_independent.h is the independent one (double, from the documentation).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace glint::reference {

struct ShadowClassifyInputs {
    std::uint32_t width = 0, height = 0;
    std::vector<std::uint32_t> mask;      // ceil(W/8) x ceil(H/4) words
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

struct ShadowClassifyOutputs {
    std::vector<std::uint32_t> metadata; // one per 8x8 tile
    std::vector<float> shadowVariance;   // RG
    std::vector<float> moments;          // RGBA (mean, M2, n, accumulated shadow)
};

ShadowClassifyOutputs shadowClassify(const ShadowClassifyInputs& in);

} // namespace glint::reference
