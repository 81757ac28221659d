// Entry for the SSSR blue-noise pass, which also writes the indirect arguments: bindings,
// callbacks, main (glint/sssr/glint_sssr_blue_noise.hlsli, glint_sssr_indirect_args.hlsli).
// The two are one dispatch because each is far below a dispatch's fixed cost; the
// arguments are written by one thread after classification, as the separate pass would.
#include "entry/common/glint_entry_common.hlsli"
#include "glint/sssr/glint_sssr_constants.h"
#include "glint/sssr/glint_sssr_blue_noise.hlsli"
#include "glint/sssr/glint_sssr_indirect_args.hlsli"

// A cbuffer holding the struct (not ConstantBuffer<T>) so that glslang can pass it by value.
GLINT_BINDING(0, 0) cbuffer g_glint_constants { GLINT_SssrConstants g_glint_sssr; };
GLINT_BINDING(1, 0) Texture2D<float2> g_glint_blue_noise_source;
GLINT_BINDING(2, 0) GLINT_IMAGE_FORMAT(rg32f) RWTexture2D<float2> g_glint_blue_noise;

float2 GLINT_SSSR_LoadBlueNoiseSource(int2 texel) { return g_glint_blue_noise_source.Load(int3(texel, 0)); }
void GLINT_SSSR_StoreBlueNoise(int2 texel, float2 sample) { g_glint_blue_noise[texel] = sample; }

GLINT_BINDING(3, 0) RWStructuredBuffer<uint> g_glint_counters;
GLINT_BINDING(4, 0) RWStructuredBuffer<uint> g_glint_arguments;

uint GLINT_SSSR_LoadCounter(uint index) { return g_glint_counters[index]; }
void GLINT_SSSR_StoreCounter(uint index, uint value) { g_glint_counters[index] = value; }
void GLINT_SSSR_StoreArgument(uint index, uint value) { g_glint_arguments[index] = value; }

[numthreads(8, 8, 1)] void main(uint3 dispatchId : SV_DispatchThreadID)
{
    GLINT_SSSR_AnimateBlueNoise(g_glint_sssr, dispatchId.xy);
    if (all(dispatchId.xy == 0))
        GLINT_SSSR_WriteIndirectArguments();
}
