// Entry for the SSSR blue-noise pass, which also writes the indirect arguments and, in the
// `compact` permutation (GLINT_SSSR_BLUE_NOISE_COMPACT=1, the reflections plan), compacts the
// ray list: bindings, callbacks, main (glint/sssr/glint_sssr_blue_noise.hlsli,
// glint_sssr_indirect_args.hlsli, glint_sssr_compact.hlsli). They are one dispatch because
// each is far below a dispatch's fixed cost and each needs only classification to have
// finished; the arguments are written by one thread, as the separate pass would.
//
// Dispatch: [numthreads(8, 8, 1)]; 16 x 16 groups without compaction; with it, n = max(256, B)
// groups for B = GLINT_WIRE_RayBlocks(tiles) in rows of GLINT_SSSR_GROUPS_PER_ROW: (min(n, 1024),
// ceil(n / 1024), 1). Group g < 256 animates texels (g mod 16, g / 16) * 8 + thread; every
// group g < B compacts block g with its 64 threads.
#ifndef GLINT_SSSR_BLUE_NOISE_COMPACT
#define GLINT_SSSR_BLUE_NOISE_COMPACT 0
#endif
#include "entry/common/glint_entry_common.hlsli"
#include "glint/sssr/glint_sssr_constants.h"
#include "glint/sssr/glint_sssr_blue_noise.hlsli"
#include "glint/sssr/glint_sssr_indirect_args.hlsli"
#if GLINT_SSSR_BLUE_NOISE_COMPACT
#include "glint/sssr/glint_sssr_compact.hlsli"
#endif

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

#if GLINT_SSSR_BLUE_NOISE_COMPACT
GLINT_BINDING(5, 0) RWStructuredBuffer<uint> g_glint_ray_scratch;
GLINT_BINDING(6, 0) RWStructuredBuffer<uint> g_glint_ray_list;

uint GLINT_SSSR_LoadRayScratch(uint word) { return g_glint_ray_scratch[word]; }
void GLINT_SSSR_StoreRayScratch(uint word, uint value) { g_glint_ray_scratch[word] = value; }
uint GLINT_SSSR_AddRayScratch(uint word, uint value)
{
    uint previous;
    InterlockedAdd(g_glint_ray_scratch[word], value, previous);
    return previous;
}
void GLINT_SSSR_StoreRay(uint index, uint entry) { g_glint_ray_list[index] = entry; }

[numthreads(8, 8, 1)] void main(uint3 groupId : SV_GroupID, uint3 groupThreadId : SV_GroupThreadID,
                                uint groupIndex : SV_GroupIndex)
{
    uint group = groupId.y * GLINT_SSSR_GROUPS_PER_ROW + groupId.x;
    uint noiseGroups = GLINT_SSSR_BLUE_NOISE_SIZE / 8;
    if (group < noiseGroups * noiseGroups)
        GLINT_SSSR_AnimateBlueNoise(g_glint_sssr, uint2(group % noiseGroups, group / noiseGroups) * 8u + groupThreadId.xy);
    if (group == 0 && groupIndex == 0)
        GLINT_SSSR_WriteIndirectArguments();
    GLINT_SSSR_CompactRays(g_glint_sssr, group, groupIndex); // group-uniform: returns past the last block
}
#else
[numthreads(8, 8, 1)] void main(uint3 dispatchId : SV_DispatchThreadID)
{
    GLINT_SSSR_AnimateBlueNoise(g_glint_sssr, dispatchId.xy);
    if (all(dispatchId.xy == 0))
        GLINT_SSSR_WriteIndirectArguments();
}
#endif
