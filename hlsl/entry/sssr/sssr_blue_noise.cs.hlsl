// Entry for the SSSR blue-noise pass: bindings, callbacks, main
// (glint/sssr/glint_sssr_blue_noise.hlsli).
#include "entry/common/glint_entry_common.hlsli"
#include "glint/sssr/glint_sssr_constants.h"
#include "glint/sssr/glint_sssr_blue_noise.hlsli"

// A cbuffer holding the struct (not ConstantBuffer<T>) so that glslang can pass it by value.
[[vk::binding(0, 0)]] cbuffer g_glint_constants { GLINT_SssrConstants g_glint_sssr; };
[[vk::binding(1, 0)]] Texture2D<float2> g_glint_blue_noise_source;
[[vk::binding(2, 0)]] GLINT_IMAGE_FORMAT(rg32f) RWTexture2D<float2> g_glint_blue_noise;

float2 GLINT_SSSR_LoadBlueNoiseSource(int2 texel) { return g_glint_blue_noise_source.Load(int3(texel, 0)); }
void GLINT_SSSR_StoreBlueNoise(int2 texel, float2 sample) { g_glint_blue_noise[texel] = sample; }

[numthreads(8, 8, 1)] void main(uint3 dispatchId : SV_DispatchThreadID)
{
    GLINT_SSSR_AnimateBlueNoise(g_glint_sssr, dispatchId.xy);
}
