// glint G-buffer roughness extraction: one channel of the engine's material texture to GGX
// alpha, converted exactly once so that no later pass has to know how roughness is stored.
//
// Integration: define these callbacks before or after including this header.
//
//   float4 GLINT_GBUFFER_LoadMaterial(int2 pixel);
//       The material texel at pixel (0..size-1); any float/unorm channels, any range.
//   void GLINT_GBUFFER_StoreAlpha(int2 pixel, float alpha);
//       Receives GGX alpha in [0, 1] for pixel; always finite.
//
// Entry: from main, GLINT_GBUFFER_ExtractRoughness(SV_DispatchThreadID.xy, c.size,
// c.materialChannel, c.inputIsPerceptual != 0), c a GLINT_GBufferRoughnessConstants
// (glint_gbuffer_constants.h; filled by host/src/core/gbuffer_passes.cpp).
// Dispatch: one thread per pixel, [numthreads(8, 8, 1)] (every variant; the fp16 permutation
// only changes the entry file's output format), ceil(width / 8) x ceil(height / 8) x 1 groups.
// Integration guide: docs/integration.md.
//
// Non-finite or out-of-range input: NaN and -Inf become 1 (fully rough), +Inf clamps to 1,
// negative values clamp to 0. Fully rough is the safe side: every effect treats such a pixel
// as diffuse-like and spends no mirror rays on it.
#ifndef GLINT_GBUFFER_ROUGHNESS_HLSLI
#define GLINT_GBUFFER_ROUGHNESS_HLSLI

#include "glint/common/glint_math.hlsli"

float4 GLINT_GBUFFER_LoadMaterial(int2 pixel);
void GLINT_GBUFFER_StoreAlpha(int2 pixel, float alpha);

// The alpha for one raw channel value; exposed so that other passes can convert on the fly.
float GLINT_GBUFFER_AlphaFromStoredRoughness(float stored, bool inputIsPerceptual)
{
    // +Inf must clamp to 1 like any large value; only NaN and -Inf have no order to clamp by.
    float value = (asuint(stored) == 0x7F800000u) ? 1.0 : GLINT_FiniteOr(stored, 1.0);
    value = GLINT_Saturate(value);
    return inputIsPerceptual ? GLINT_AlphaFromPerceptualRoughness(value) : value;
}

void GLINT_GBUFFER_ExtractRoughness(uint2 pixel, uint2 size, uint materialChannel, bool inputIsPerceptual)
{
    if (any(pixel >= size))
        return;
    float4 material = GLINT_GBUFFER_LoadMaterial(int2(pixel));
    // Index with a select chain rather than material[channel]: dynamic vector indexing lowers
    // to a local array on some compilers, and the channel is uniform anyway.
    float stored = materialChannel == 0 ? material.x
                 : materialChannel == 1 ? material.y
                 : materialChannel == 2 ? material.z
                                        : material.w;
    GLINT_GBUFFER_StoreAlpha(int2(pixel), GLINT_GBUFFER_AlphaFromStoredRoughness(stored, inputIsPerceptual));
}

#endif // GLINT_GBUFFER_ROUGHNESS_HLSLI
