// Entry for the roughness extraction pass: bindings, callbacks, main. Engines read this file
// as the integration example for hlsl/glint/gbuffer/glint_gbuffer_roughness.hlsli.
//
// Permutation GLINT_GBUFFER_HALF_OUTPUT=1 writes an R16F image instead of R32F.
#include "entry/common/glint_entry_common.hlsli"
#include "glint/gbuffer/glint_gbuffer_constants.h"
#include "glint/gbuffer/glint_gbuffer_roughness.hlsli"

GLINT_BINDING(0, 0) ConstantBuffer<GLINT_GBufferRoughnessConstants> g_glint_constants;
GLINT_BINDING(1, 0) Texture2D<float4> g_glint_material;
#if GLINT_GBUFFER_HALF_OUTPUT
GLINT_BINDING(2, 0) GLINT_IMAGE_FORMAT(r16f) RWTexture2D<float> g_glint_alpha;
#else
GLINT_BINDING(2, 0) GLINT_IMAGE_FORMAT(r32f) RWTexture2D<float> g_glint_alpha;
#endif

float4 GLINT_GBUFFER_LoadMaterial(int2 pixel)
{
    return g_glint_material.Load(int3(pixel, 0));
}

void GLINT_GBUFFER_StoreAlpha(int2 pixel, float alpha)
{
    g_glint_alpha[pixel] = alpha;
}

[numthreads(8, 8, 1)] void main(uint3 dispatchThreadId : SV_DispatchThreadID)
{
    GLINT_GBUFFER_ExtractRoughness(dispatchThreadId.xy, g_glint_constants.size, g_glint_constants.materialChannel,
                                   g_glint_constants.inputIsPerceptual != 0);
}
