// CPU references of the shadow denoiser passes (docs/shadow_denoiser.md), written from the
// documented algorithm, independent of the shaders.
#pragma once

#include <cstdint>
#include <vector>

namespace glint::reference {

// One word per 8 x 4 tile, bit (y & 3) * 8 + (x & 7), set when visibility >= 0.5; bits of
// out-of-image pixels repeat the nearest in-image pixel.
std::vector<std::uint32_t> packShadowMask(const std::vector<float>& visibility, std::uint32_t width,
                                          std::uint32_t height);

struct ShadowFilterInputs {
    std::uint32_t width = 0, height = 0;
    std::vector<float> meanVariance; // RG per pixel
    std::vector<float> depth;        // device depth per pixel
    std::vector<float> normals;      // RGBA per pixel, already unpacked (xyz used)
    float viewDepth[3] = {0.1f, 1.0f, -1.0f};
    float depthSigma = 0.02f;
    float normalPower = 32.0f;
    bool contrastRemap = false; // the last pass applies mean^max(1.2 - variance, 1)
    // Penumbra footprint (docs/shadow_denoiser.md, "Penumbra-aware filtering"): with
    // penumbraScale >= 0, a pass of step s weighs every neighbour by clamp((W - 1) / s, 0, 1), W the
    // widest penumbraScale * blocker / z over the pixel's 5 x 5 (unknown blockers: 64 pixels; a
    // light of size 0, penumbraScale 0: W = 0, no taps). Negative: no estimate, the full filter.
    float penumbraScale = -1.0f;
    std::vector<float> blockerDistance; // per pixel; read only with penumbraScale > 0
};

// One a-trous iteration; returns RG per pixel.
std::vector<float> shadowFilterPass(const ShadowFilterInputs& inputs, const std::vector<float>& meanVariance,
                                    std::uint32_t step, bool finalPass);

// Three iterations (steps 1, 2, 4); the last with the contrast remap when asked.
std::vector<float> shadowFilter(const ShadowFilterInputs& inputs);

} // namespace glint::reference
