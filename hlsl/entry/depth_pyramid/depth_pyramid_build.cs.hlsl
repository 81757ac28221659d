// Entry for the depth pyramid: bindings, callbacks, main. Engines read this file as the
// integration example for hlsl/glint/depth_pyramid/glint_depth_pyramid.hlsli.
//
// Permutations: GLINT_DEPTH_PYRAMID_REVERSED=1 (closest = max), GLINT_DEPTH_PYRAMID_FARTHEST=1
// (RG32F: closest and farthest).
#include "entry/common/glint_entry_common.hlsli"
#include "glint/depth_pyramid/glint_depth_pyramid_constants.h"
#include "glint/depth_pyramid/glint_depth_pyramid.hlsli"

GLINT_BINDING(0, 0) ConstantBuffer<GLINT_DepthPyramidConstants> g_glint_constants;
GLINT_BINDING(1, 0) Texture2D<float> g_glint_depth;
#if GLINT_DEPTH_PYRAMID_FARTHEST
GLINT_BINDING(2, 0) GLINT_IMAGE_FORMAT(rg32f) globallycoherent RWTexture2D<float2> g_glint_pyramid[GLINT_DEPTH_PYRAMID_MAX_LEVELS];
#else
GLINT_BINDING(2, 0) GLINT_IMAGE_FORMAT(r32f) globallycoherent RWTexture2D<float> g_glint_pyramid[GLINT_DEPTH_PYRAMID_MAX_LEVELS];
#endif
GLINT_BINDING(3, 0) globallycoherent RWStructuredBuffer<uint> g_glint_counter;
// Gather ignores filtering; a nearest sampler keeps formats without linear filtering legal.
GLINT_BINDING(4, 0) SamplerState g_glint_point_clamp;

float4 GLINT_DEPTH_PYRAMID_GatherDepth(int2 pixel)
{
    // The sample point is the corner shared by the four pixels, so Gather returns exactly
    // them; its component order is (0,1), (1,1), (1,0), (0,0) from the top-left.
    float width, height;
    g_glint_depth.GetDimensions(width, height);
    float2 uv = (float2(pixel) + 1.0) / float2(width, height);
    return g_glint_depth.GatherRed(g_glint_point_clamp, uv).wzxy;
}

float2 GLINT_DEPTH_PYRAMID_Reduce(float2 a, float2 b)
{
#if GLINT_DEPTH_PYRAMID_REVERSED
    return float2(max(a.x, b.x), min(a.y, b.y));
#else
    return float2(min(a.x, b.x), max(a.y, b.y));
#endif
}

void GLINT_DEPTH_PYRAMID_StoreLevel(int2 texel, uint level, float2 value)
{
#if GLINT_DEPTH_PYRAMID_FARTHEST
    g_glint_pyramid[level][texel] = value;
#else
    g_glint_pyramid[level][texel] = value.x;
#endif
}

float2 GLINT_DEPTH_PYRAMID_LoadLevelCoherent(int2 texel, uint level)
{
#if GLINT_DEPTH_PYRAMID_FARTHEST
    return g_glint_pyramid[level][texel];
#else
    float closest = g_glint_pyramid[level][texel];
    return float2(closest, closest);
#endif
}

uint GLINT_DEPTH_PYRAMID_IncrementCounter()
{
    uint previous;
    InterlockedAdd(g_glint_counter[0], 1u, previous);
    return previous;
}

void GLINT_DEPTH_PYRAMID_ResetCounter()
{
    uint previous;
    InterlockedExchange(g_glint_counter[0], 0u, previous);
}

[numthreads(256, 1, 1)] void main(uint3 groupId : SV_GroupID, uint groupIndex : SV_GroupIndex)
{
    GLINT_DEPTH_PYRAMID_Build(groupId.xy, groupIndex, g_glint_constants.inputSize, g_glint_constants.level0Size,
                              g_glint_constants.levelCount, g_glint_constants.groupCount, g_glint_constants.farDepth,
                              g_glint_constants.writeLevel0 != 0);
}
