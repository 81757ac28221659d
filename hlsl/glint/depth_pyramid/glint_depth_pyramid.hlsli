// glint depth pyramid: one dispatch builds a closest (and optionally farthest) depth mip
// chain that is conservative at every input size (docs/depth_pyramid.md).
//
// Integration: define these callbacks before or after including this header.
//
//   float  GLINT_DEPTH_PYRAMID_LoadDepth(int2 pixel);
//       Device depth of the input at pixel, 0 <= pixel < inputSize. Any value; non-finite
//       and out-of-range values are sanitized here.
//   float2 GLINT_DEPTH_PYRAMID_Reduce(float2 a, float2 b);
//       Combines two (closest, farthest) pairs: (min, max) for standard depth, (max, min)
//       for reversed depth. Must be exact (min/max), so results are bit-reproducible.
//   void   GLINT_DEPTH_PYRAMID_StoreLevel(int2 texel, uint level, float2 value);
//       Writes level `level` (0..levelCount-1) at texel; .x closest, .y farthest (drop .y
//       for a closest-only pyramid). Levels >= 6 must be written through coherent
//       (globallycoherent) storage images: the last group reads them back.
//   float2 GLINT_DEPTH_PYRAMID_LoadLevelCoherent(int2 texel, uint level);
//       Reads back a level >= 6 texel written by any group, through the same coherent images
//       (never through a sampler or a non-coherent view). Only called when levelCount > 7.
//   uint   GLINT_DEPTH_PYRAMID_IncrementCounter();
//       Atomically adds 1 to a device-scope coherent counter and returns the previous value.
//   void   GLINT_DEPTH_PYRAMID_ResetCounter();
//       Sets the counter back to 0 (the host also zeroes it every frame).
//
// Dispatch: [numthreads(256, 1, 1)], (W0 / 64) x (H0 / 64) x 1 groups, where (W0, H0) is the
// input size rounded up to multiples of 64; call GLINT_DEPTH_PYRAMID_Build from main with
// SV_GroupID.xy, SV_GroupIndex and the constants of glint_depth_pyramid_constants.h.
//
// Non-finite depth becomes the far plane, values outside [0, 1] are clamped and -0 becomes
// +0, so no NaN or Inf reaches any level and min/max never see an undefined operand.
#ifndef GLINT_DEPTH_PYRAMID_HLSLI
#define GLINT_DEPTH_PYRAMID_HLSLI

#include "glint/common/glint_math.hlsli"
#include "glint/depth_pyramid/glint_depth_pyramid_constants.h"

float GLINT_DEPTH_PYRAMID_LoadDepth(int2 pixel);
float2 GLINT_DEPTH_PYRAMID_Reduce(float2 a, float2 b);
void GLINT_DEPTH_PYRAMID_StoreLevel(int2 texel, uint level, float2 value);
float2 GLINT_DEPTH_PYRAMID_LoadLevelCoherent(int2 texel, uint level);
uint GLINT_DEPTH_PYRAMID_IncrementCounter();
void GLINT_DEPTH_PYRAMID_ResetCounter();

#define GLINT_DEPTH_PYRAMID_GROUP_SIZE 256

// Level 2 of the tile (16x16), then levels 4 and 6 reuse it; levels 3 and 5 go to the
// second array. Alternating keeps every step's reads and writes in different arrays, so one
// barrier per level is enough.
groupshared float2 g_glint_depth_pyramid_even[256];
groupshared float2 g_glint_depth_pyramid_odd[64];
groupshared uint g_glint_depth_pyramid_arrivals;

float GLINT_DEPTH_PYRAMID_Sanitize(float depth, float farDepth)
{
    if (!GLINT_IsFinite(depth))
        return farDepth;
    // Clearing the sign bit after the clamp turns -0 into +0; a bit operation cannot be
    // folded away the way "x + 0.0" can when signed zeros are not preserved.
    return asfloat(asuint(clamp(depth, 0.0, 1.0)) & 0x7FFFFFFFu);
}

float2 GLINT_DEPTH_PYRAMID_Reduce4(float2 a, float2 b, float2 c, float2 d)
{
    return GLINT_DEPTH_PYRAMID_Reduce(GLINT_DEPTH_PYRAMID_Reduce(a, b), GLINT_DEPTH_PYRAMID_Reduce(c, d));
}

// Pixels in the padding beyond the input are far: empty for the closest channel, and the
// most pessimistic value for the farthest one.
float2 GLINT_DEPTH_PYRAMID_LoadSanitized(int2 pixel, uint2 inputSize, float farDepth)
{
    float depth = farDepth;
    if (all(uint2(pixel) < inputSize))
        depth = GLINT_DEPTH_PYRAMID_Sanitize(GLINT_DEPTH_PYRAMID_LoadDepth(pixel), farDepth);
    return float2(depth, depth);
}

void GLINT_DEPTH_PYRAMID_Store(int2 texel, uint level, float2 value, uint levelCount)
{
    // Levels beyond the requested count are never written: no slot may alias a live level.
    if (level < levelCount)
        GLINT_DEPTH_PYRAMID_StoreLevel(texel, level, value);
}

// The 2x2 reduction of a groupshared square of side `side` (row-major) at output texel p.
float2 GLINT_DEPTH_PYRAMID_ReduceShared(bool fromEven, uint2 p, uint side)
{
    uint i = (2 * p.y) * side + 2 * p.x;
    if (fromEven)
        return GLINT_DEPTH_PYRAMID_Reduce4(g_glint_depth_pyramid_even[i], g_glint_depth_pyramid_even[i + 1],
                                           g_glint_depth_pyramid_even[i + side], g_glint_depth_pyramid_even[i + side + 1]);
    return GLINT_DEPTH_PYRAMID_Reduce4(g_glint_depth_pyramid_odd[i], g_glint_depth_pyramid_odd[i + 1],
                                       g_glint_depth_pyramid_odd[i + side], g_glint_depth_pyramid_odd[i + side + 1]);
}

// Levels 7 and up, built by the last group from level 6 with every group's texel in place.
// The last row and column of each level also take the previous level's leftover odd row
// and column, so the chain stays conservative without padding beyond 64.
void GLINT_DEPTH_PYRAMID_BuildCoarseLevels(uint localIndex, uint2 level0Size, uint levelCount)
{
    for (uint level = GLINT_DEPTH_PYRAMID_TILE_LEVELS; level < levelCount; ++level)
    {
        uint2 previousSize = max(level0Size >> (level - 1), uint2(1, 1));
        uint2 size = max(level0Size >> level, uint2(1, 1));
        for (uint index = localIndex; index < size.x * size.y; index += GLINT_DEPTH_PYRAMID_GROUP_SIZE)
        {
            uint2 texel = uint2(index % size.x, index / size.x);
            uint2 first = texel * 2;
            uint2 last = min(first + 1, previousSize - 1);
            if (texel.x == size.x - 1)
                last.x = previousSize.x - 1;
            if (texel.y == size.y - 1)
                last.y = previousSize.y - 1;
            float2 value = GLINT_DEPTH_PYRAMID_LoadLevelCoherent(int2(first), level - 1);
            for (uint y = first.y; y <= last.y; ++y)
                for (uint x = first.x; x <= last.x; ++x)
                    value = GLINT_DEPTH_PYRAMID_Reduce(value, GLINT_DEPTH_PYRAMID_LoadLevelCoherent(int2(x, y), level - 1));
            GLINT_DEPTH_PYRAMID_StoreLevel(int2(texel), level, value);
        }
        // Makes this level's stores, from every thread of the group, visible to the next
        // level's coherent loads.
        DeviceMemoryBarrierWithGroupSync();
    }
}

void GLINT_DEPTH_PYRAMID_Build(uint2 groupId, uint localIndex, uint2 inputSize, uint2 level0Size, uint levelCount,
                               uint groupCount, float farDepth)
{
    // Levels 0-2 in registers: each thread owns a 4x4 block of the group's 64x64 tile.
    uint2 block = uint2(localIndex % 16, localIndex / 16);
    int2 origin = int2(groupId * 64 + block * 4);
    float2 level1[4];
    [unroll] for (uint quad = 0; quad < 4; ++quad)
    {
        int2 p = origin + int2(quad & 1, quad >> 1) * 2;
        float2 a = GLINT_DEPTH_PYRAMID_LoadSanitized(p, inputSize, farDepth);
        float2 b = GLINT_DEPTH_PYRAMID_LoadSanitized(p + int2(1, 0), inputSize, farDepth);
        float2 c = GLINT_DEPTH_PYRAMID_LoadSanitized(p + int2(0, 1), inputSize, farDepth);
        float2 d = GLINT_DEPTH_PYRAMID_LoadSanitized(p + int2(1, 1), inputSize, farDepth);
        GLINT_DEPTH_PYRAMID_StoreLevel(p, 0, a);
        GLINT_DEPTH_PYRAMID_StoreLevel(p + int2(1, 0), 0, b);
        GLINT_DEPTH_PYRAMID_StoreLevel(p + int2(0, 1), 0, c);
        GLINT_DEPTH_PYRAMID_StoreLevel(p + int2(1, 1), 0, d);
        level1[quad] = GLINT_DEPTH_PYRAMID_Reduce4(a, b, c, d);
        GLINT_DEPTH_PYRAMID_Store(p / 2, 1, level1[quad], levelCount);
    }
    float2 level2 = GLINT_DEPTH_PYRAMID_Reduce4(level1[0], level1[1], level1[2], level1[3]);
    GLINT_DEPTH_PYRAMID_Store(origin / 4, 2, level2, levelCount);
    g_glint_depth_pyramid_even[localIndex] = level2;
    GroupMemoryBarrierWithGroupSync();

    // Levels 3-6 through groupshared memory; correct for any subgroup size.
    if (localIndex < 64)
    {
        uint2 p = uint2(localIndex % 8, localIndex / 8);
        float2 value = GLINT_DEPTH_PYRAMID_ReduceShared(true, p, 16);
        GLINT_DEPTH_PYRAMID_Store(int2(groupId * 8 + p), 3, value, levelCount);
        g_glint_depth_pyramid_odd[localIndex] = value;
    }
    GroupMemoryBarrierWithGroupSync();
    if (localIndex < 16)
    {
        uint2 p = uint2(localIndex % 4, localIndex / 4);
        float2 value = GLINT_DEPTH_PYRAMID_ReduceShared(false, p, 8);
        GLINT_DEPTH_PYRAMID_Store(int2(groupId * 4 + p), 4, value, levelCount);
        g_glint_depth_pyramid_even[localIndex] = value;
    }
    GroupMemoryBarrierWithGroupSync();
    if (localIndex < 4)
    {
        uint2 p = uint2(localIndex % 2, localIndex / 2);
        float2 value = GLINT_DEPTH_PYRAMID_ReduceShared(true, p, 4);
        GLINT_DEPTH_PYRAMID_Store(int2(groupId * 2 + p), 5, value, levelCount);
        g_glint_depth_pyramid_odd[localIndex] = value;
    }
    GroupMemoryBarrierWithGroupSync();
    if (localIndex == 0)
    {
        float2 value = GLINT_DEPTH_PYRAMID_ReduceShared(false, uint2(0, 0), 2);
        GLINT_DEPTH_PYRAMID_Store(int2(groupId), 6, value, levelCount);
    }
    if (levelCount <= GLINT_DEPTH_PYRAMID_TILE_LEVELS)
        return;

    // Last-group pattern: the group that arrives last builds the coarse levels. Release: the
    // level-6 store is made visible device-wide before the count says it exists.
    if (localIndex == 0)
    {
        DeviceMemoryBarrier();
        g_glint_depth_pyramid_arrivals = GLINT_DEPTH_PYRAMID_IncrementCounter();
    }
    GroupMemoryBarrierWithGroupSync();
    if (g_glint_depth_pyramid_arrivals != groupCount - 1)
        return;
    // Acquire: every other group's level-6 store happened before its increment.
    DeviceMemoryBarrierWithGroupSync();
    GLINT_DEPTH_PYRAMID_BuildCoarseLevels(localIndex, level0Size, levelCount);
    if (localIndex == 0)
        GLINT_DEPTH_PYRAMID_ResetCounter();
}

#endif // GLINT_DEPTH_PYRAMID_HLSLI
