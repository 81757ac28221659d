// glint depth pyramid: one dispatch builds a closest (and optionally farthest) depth mip
// chain that is conservative at every input size (docs/depth_pyramid.md).
//
// Integration: define these callbacks before or after including this header.
//
//   float4 GLINT_DEPTH_PYRAMID_GatherDepth(int2 pixel);
//       Device depths of the 2x2 input block whose top-left pixel is `pixel`, in the order
//       (pixel, pixel + (1, 0), pixel + (0, 1), pixel + (1, 1)). Pixels outside the input may
//       return anything (they are replaced by far here); any value is allowed, non-finite and
//       out-of-range ones are sanitized here. A Gather with a clamp-to-edge sampler at
//       (pixel + 1) / inputSize, swizzled .wzxy, implements it in one fetch.
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
// Entry: from main, GLINT_DEPTH_PYRAMID_Build(SV_GroupID.xy, SV_GroupIndex, c.inputSize,
// c.level0Size, c.levelCount, c.groupCount, c.farDepth, c.writeLevel0 != 0), c a
// GLINT_DepthPyramidConstants (glint_depth_pyramid_constants.h; filled by
// host/src/core/depth_pyramid_passes.cpp).
// Dispatch: [numthreads(256, 1, 1)] in every variant (reversed and closest+farthest only
// change the callbacks), (W0 / 64) x (H0 / 64) x 1 groups, where (W0, H0) is the input size
// rounded up to multiples of 64. Integration guide: docs/integration.md.
//
// Non-finite depth becomes the far plane, values outside [0, 1] are clamped, and -0 and
// denormals become +0, so no NaN or Inf reaches any level, min/max never see an undefined
// operand, and GPUs that flush denormals agree bit for bit with GPUs that keep them.
#ifndef GLINT_DEPTH_PYRAMID_HLSLI
#define GLINT_DEPTH_PYRAMID_HLSLI

#include "glint/common/glint_math.hlsli"
#include "glint/depth_pyramid/glint_depth_pyramid_constants.h"

float4 GLINT_DEPTH_PYRAMID_GatherDepth(int2 pixel);
float2 GLINT_DEPTH_PYRAMID_Reduce(float2 a, float2 b);
void GLINT_DEPTH_PYRAMID_StoreLevel(int2 texel, uint level, float2 value);
float2 GLINT_DEPTH_PYRAMID_LoadLevelCoherent(int2 texel, uint level);
uint GLINT_DEPTH_PYRAMID_IncrementCounter();
void GLINT_DEPTH_PYRAMID_ResetCounter();

#define GLINT_DEPTH_PYRAMID_GROUP_SIZE 256

// Level 1 of the tile (32x32), then levels 3 and 5 reuse it; levels 2, 4 and 6 go to the
// second array. Alternating keeps every step's reads and writes in different arrays, so one
// barrier per level is enough.
// The last group reuses both arrays for the coarse levels (see BuildCoarseLevels), which is
// why "even" holds 512 texels: a level of at most 1024 texels halves to at most 512.
groupshared float2 g_glint_depth_pyramid_odd[1024];
groupshared float2 g_glint_depth_pyramid_even[512];
groupshared uint g_glint_depth_pyramid_arrivals;

float GLINT_DEPTH_PYRAMID_Sanitize(float depth, float farDepth)
{
    if (!GLINT_IsFinite(depth))
        return farDepth;
    // After the clamp, clearing the sign bit turns -0 into +0, and anything below the smallest
    // normal float becomes +0: GPUs that flush denormals (NVIDIA does in min/max) and GPUs
    // that keep them then store the same bits. Bit operations, unlike "x + 0.0", cannot be
    // folded away when signed zeros are not preserved.
    uint bits = asuint(clamp(depth, 0.0, 1.0)) & 0x7FFFFFFFu;
    return bits < 0x00800000u ? 0.0 : asfloat(bits);
}

float2 GLINT_DEPTH_PYRAMID_Reduce4(float2 a, float2 b, float2 c, float2 d)
{
    return GLINT_DEPTH_PYRAMID_Reduce(GLINT_DEPTH_PYRAMID_Reduce(a, b), GLINT_DEPTH_PYRAMID_Reduce(c, d));
}

// One gathered 2x2 block, sanitized. Pixels in the padding beyond the input are far: empty
// for the closest channel, and the most pessimistic value for the farthest one.
float4 GLINT_DEPTH_PYRAMID_LoadBlock(int2 pixel, uint2 inputSize, float farDepth)
{
    float4 depth = GLINT_DEPTH_PYRAMID_GatherDepth(pixel);
    bool2 inside0 = uint2(pixel) < inputSize;
    bool2 inside1 = uint2(pixel + 1) < inputSize;
    depth.x = (inside0.x && inside0.y) ? GLINT_DEPTH_PYRAMID_Sanitize(depth.x, farDepth) : farDepth;
    depth.y = (inside1.x && inside0.y) ? GLINT_DEPTH_PYRAMID_Sanitize(depth.y, farDepth) : farDepth;
    depth.z = (inside0.x && inside1.y) ? GLINT_DEPTH_PYRAMID_Sanitize(depth.z, farDepth) : farDepth;
    depth.w = (inside1.x && inside1.y) ? GLINT_DEPTH_PYRAMID_Sanitize(depth.w, farDepth) : farDepth;
    return depth;
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

float2 GLINT_DEPTH_PYRAMID_LoadCoarse(uint2 texel, uint width, uint level, uint source)
{
    // source 0: the level is only in the (coherent) image; 1 / 2: it is also in the odd /
    // even groupshared array, row-major with `width` texels per row.
    if (source == 1)
        return g_glint_depth_pyramid_odd[texel.y * width + texel.x];
    if (source == 2)
        return g_glint_depth_pyramid_even[texel.y * width + texel.x];
    return GLINT_DEPTH_PYRAMID_LoadLevelCoherent(int2(texel), level);
}

// Levels 7 and up, built by the last group from level 6 with every group's texel in place.
// The last row and column of each level also take the previous level's leftover odd row
// and column, so the chain stays conservative without padding beyond 64. Level 6 comes from
// the image; every level small enough (at most 1024 texels) is also kept in groupshared
// memory, so the levels after it need only group barriers instead of device-scope round
// trips through coherent memory.
void GLINT_DEPTH_PYRAMID_BuildCoarseLevels(uint localIndex, uint2 level0Size, uint levelCount)
{
    uint source = 0;
    for (uint level = GLINT_DEPTH_PYRAMID_TILE_LEVELS; level < levelCount; ++level)
    {
        uint2 previousSize = max(level0Size >> (level - 1), uint2(1, 1));
        uint2 size = max(level0Size >> level, uint2(1, 1));
        uint target = size.x * size.y <= 1024 ? (source == 1 ? 2 : 1) : 0;
        for (uint index = localIndex; index < size.x * size.y; index += GLINT_DEPTH_PYRAMID_GROUP_SIZE)
        {
            uint2 texel = uint2(index % size.x, index / size.x);
            uint2 first = texel * 2;
            uint2 last = min(first + 1, previousSize - 1);
            if (texel.x == size.x - 1)
                last.x = previousSize.x - 1;
            if (texel.y == size.y - 1)
                last.y = previousSize.y - 1;
            float2 value = GLINT_DEPTH_PYRAMID_LoadCoarse(first, previousSize.x, level - 1, source);
            for (uint y = first.y; y <= last.y; ++y)
                for (uint x = first.x; x <= last.x; ++x)
                    value = GLINT_DEPTH_PYRAMID_Reduce(value,
                                                       GLINT_DEPTH_PYRAMID_LoadCoarse(uint2(x, y), previousSize.x, level - 1, source));
            GLINT_DEPTH_PYRAMID_StoreLevel(int2(texel), level, value);
            if (target == 1)
                g_glint_depth_pyramid_odd[index] = value;
            else if (target == 2)
                g_glint_depth_pyramid_even[index] = value;
        }
        // With the level in groupshared memory a group barrier suffices; otherwise this
        // level's image stores from every thread must reach the next level's coherent loads.
        if (target != 0)
            GroupMemoryBarrierWithGroupSync();
        else
            DeviceMemoryBarrierWithGroupSync();
        source = target;
    }
}

void GLINT_DEPTH_PYRAMID_Build(uint2 groupId, uint localIndex, uint2 inputSize, uint2 level0Size, uint levelCount,
                               uint groupCount, float farDepth, bool writeLevel0)
{
    // Levels 0 and 1: each thread gathers four 2x2 blocks. Warp-sized runs of threads take
    // consecutive blocks of one block row, so every fetch and store of a warp covers whole
    // rows of the tile. The 32x32 level-1 texels go to groupshared memory.
    [unroll] for (uint pass = 0; pass < 4; ++pass)
    {
        uint blockIndex = pass * GLINT_DEPTH_PYRAMID_GROUP_SIZE + localIndex;
        uint2 block = uint2(blockIndex % 32, blockIndex / 32);
        int2 pixel = int2(groupId * 64 + block * 2);
        float4 depth = GLINT_DEPTH_PYRAMID_LoadBlock(pixel, inputSize, farDepth);
        if (writeLevel0)
        {
            GLINT_DEPTH_PYRAMID_StoreLevel(pixel, 0, depth.xx);
            GLINT_DEPTH_PYRAMID_StoreLevel(pixel + int2(1, 0), 0, depth.yy);
            GLINT_DEPTH_PYRAMID_StoreLevel(pixel + int2(0, 1), 0, depth.zz);
            GLINT_DEPTH_PYRAMID_StoreLevel(pixel + int2(1, 1), 0, depth.ww);
        }
        float2 level1 = GLINT_DEPTH_PYRAMID_Reduce4(depth.xx, depth.yy, depth.zz, depth.ww);
        GLINT_DEPTH_PYRAMID_Store(pixel / 2, 1, level1, levelCount);
        g_glint_depth_pyramid_odd[blockIndex] = level1;
    }
    GroupMemoryBarrierWithGroupSync();

    // Levels 2-6 through groupshared memory; correct for any subgroup size.
    {
        uint2 p = uint2(localIndex % 16, localIndex / 16);
        float2 value = GLINT_DEPTH_PYRAMID_ReduceShared(false, p, 32);
        GLINT_DEPTH_PYRAMID_Store(int2(groupId * 16 + p), 2, value, levelCount);
        g_glint_depth_pyramid_even[localIndex] = value;
    }
    GroupMemoryBarrierWithGroupSync();
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
