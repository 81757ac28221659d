// glint SSSR, ray-list compaction (docs/sssr.md, "The ray list"). Gathers the rays the
// classification left in each tile's slots of the ray scratch buffer into the ray list, in a
// fixed order: tiles row-major, each tile's rays in its pixels' row-major order. The order
// does not depend on how the GPU schedules groups, so the intersection's groups of 64 rays,
// and with them the low-occupancy exit, are the same on every run.
//
// Integration: define these callbacks before or after including this header.
//
//   uint GLINT_SSSR_LoadRayScratch(uint word);               the buffer the classification wrote
//   void GLINT_SSSR_StoreRayScratch(uint word, uint value);
//   uint GLINT_SSSR_AddRayScratch(uint word, uint value);     atomic add, returns the previous value
//   void GLINT_SSSR_StoreRay(uint index, uint entry);         the ray list (W H entries)
//
// Entry: from main, GLINT_SSSR_CompactRays(c, block, SV_GroupIndex), c the GLINT_SssrConstants
// in a cbuffer (glint_sssr_common.hlsli; only c.inputSize is read), in group-uniform control
// flow, with 64 threads a group and block = SV_GroupID.y * GLINT_SSSR_GROUPS_PER_ROW +
// SV_GroupID.x: (min(n, 1024), ceil(n / 1024), 1) groups for any n >= B =
// GLINT_WIRE_RayBlocks(ceil(W / 8) ceil(H / 8)); groups past B return at once. It runs after
// the classification and before the intersection. glint's entry (entry/sssr/sssr_blue_noise.cs.hlsl,
// permutation `compact`) runs it in the blue-noise and arguments dispatch, [numthreads(8, 8, 1)],
// n = max(256, B); it can also be a dispatch of its own.
//
// Each group finds its first ray from the superblock counts before its superblock and the
// block counts before it in its superblock (each thread loads at most two counts up to 16.7
// million pixels, 17 at the largest size), scans its 64 tile counts, and copies its rays with
// all 64 threads, four at a time each. The group that finishes its reads last (a completion counter) clears the block and superblock counts for
// the next frame: the classification only adds to them, and the host never resets them.
#ifndef GLINT_SSSR_COMPACT_HLSLI
#define GLINT_SSSR_COMPACT_HLSLI

#include "glint/sssr/glint_sssr_common.hlsli"

uint GLINT_SSSR_LoadRayScratch(uint word);
void GLINT_SSSR_StoreRayScratch(uint word, uint value);
uint GLINT_SSSR_AddRayScratch(uint word, uint value);
void GLINT_SSSR_StoreRay(uint index, uint entry);

#define GLINT_SSSR_COMPACT_GROUP 64u
#define GLINT_SSSR_COMPACT_BATCH 4u

groupshared uint g_glint_sssr_compact_rays[GLINT_SSSR_COMPACT_GROUP];  // inclusive prefix of the tile counts
groupshared uint g_glint_sssr_compact_first[GLINT_SSSR_COMPACT_GROUP]; // inclusive prefix of the partial offsets
groupshared uint g_glint_sssr_compact_last_group;

// The first tile of the block whose inclusive prefix exceeds ray (ray < the block's total).
uint GLINT_SSSR_CompactTileOf(uint ray)
{
    uint low = 0;
    uint high = GLINT_SSSR_COMPACT_GROUP - 1u;
    while (low < high)
    {
        uint middle = (low + high) / 2u;
        if (g_glint_sssr_compact_rays[middle] > ray)
            high = middle;
        else
            low = middle + 1u;
    }
    return low;
}

void GLINT_SSSR_CompactRays(GLINT_SssrConstants c, uint block, uint lane)
{
    uint tiles = GLINT_SSSR_TileCount(c);
    uint blocks = GLINT_WIRE_RayBlocks(tiles);
    if (block >= blocks)
        return; // the whole group: rows of 1024 groups can overshoot
    uint firstTile = block * GLINT_WIRE_RAY_BLOCK_TILES;
    uint tile = firstTile + lane;
    uint count = tile < tiles ? GLINT_SSSR_LoadRayScratch(GLINT_WIRE_RayScratchTileCount(tiles, tile)) : 0u;

    // This lane's share of the rays before the block.
    uint superblock = block / GLINT_WIRE_RAY_SUPERBLOCK_BLOCKS;
    uint before = 0;
    for (uint s = lane; s < superblock; s += GLINT_SSSR_COMPACT_GROUP)
        before += GLINT_SSSR_LoadRayScratch(GLINT_WIRE_RayScratchSuperblockCount(tiles, s));
    uint firstBlock = superblock * GLINT_WIRE_RAY_SUPERBLOCK_BLOCKS;
    if (firstBlock + lane < block)
        before += GLINT_SSSR_LoadRayScratch(GLINT_WIRE_RayScratchBlockCount(tiles, firstBlock + lane));

    // Inclusive scans of both (Hillis-Steele; integer sums, so any wave size gives the same).
    g_glint_sssr_compact_rays[lane] = count;
    g_glint_sssr_compact_first[lane] = before;
    GroupMemoryBarrierWithGroupSync();
    for (uint offset = 1; offset < GLINT_SSSR_COMPACT_GROUP; offset <<= 1)
    {
        uint rays = lane >= offset ? g_glint_sssr_compact_rays[lane - offset] : 0u;
        uint first = lane >= offset ? g_glint_sssr_compact_first[lane - offset] : 0u;
        GroupMemoryBarrierWithGroupSync();
        g_glint_sssr_compact_rays[lane] += rays;
        g_glint_sssr_compact_first[lane] += first;
        GroupMemoryBarrierWithGroupSync();
    }
    uint blockFirstRay = g_glint_sssr_compact_first[GLINT_SSSR_COMPACT_GROUP - 1u];
    uint blockRays = g_glint_sssr_compact_rays[GLINT_SSSR_COMPACT_GROUP - 1u];

    // Every group has read its counts (the values above are in groupshared memory): the last
    // group to get here clears them for the next frame.
    if (lane == 0)
    {
        uint finished = GLINT_SSSR_AddRayScratch(GLINT_WIRE_RayScratchCompletion(tiles), 1u);
        g_glint_sssr_compact_last_group = finished + 1u == blocks ? 1u : 0u;
    }
    GroupMemoryBarrierWithGroupSync();
    if (g_glint_sssr_compact_last_group != 0)
    {
        uint firstCount = GLINT_WIRE_RayScratchBlockCount(tiles, 0);
        uint counts = GLINT_WIRE_RayScratchCompletion(tiles) + 1u - firstCount; // the counter too
        for (uint word = lane; word < counts; word += GLINT_SSSR_COMPACT_GROUP)
            GLINT_SSSR_StoreRayScratch(firstCount + word, 0u);
    }

    // Four rays a thread at a time: the four loads are issued before any store waits on them,
    // so a block of many rays (a mirror-filled one holds 4,096) pays a quarter of the latency.
    for (uint first = lane; first < blockRays; first += GLINT_SSSR_COMPACT_BATCH * GLINT_SSSR_COMPACT_GROUP)
    {
        uint entries[GLINT_SSSR_COMPACT_BATCH];
        [unroll] for (uint k = 0; k < GLINT_SSSR_COMPACT_BATCH; ++k)
        {
            uint ray = first + k * GLINT_SSSR_COMPACT_GROUP;
            entries[k] = 0u;
            if (ray < blockRays)
            {
                uint tileInBlock = GLINT_SSSR_CompactTileOf(ray);
                uint tileFirstRay = tileInBlock == 0 ? 0u : g_glint_sssr_compact_rays[tileInBlock - 1u];
                entries[k] = GLINT_SSSR_LoadRayScratch(GLINT_WIRE_RayScratchSlot(firstTile + tileInBlock, ray - tileFirstRay));
            }
        }
        [unroll] for (uint k = 0; k < GLINT_SSSR_COMPACT_BATCH; ++k)
        {
            uint ray = first + k * GLINT_SSSR_COMPACT_GROUP;
            if (ray < blockRays)
                GLINT_SSSR_StoreRay(blockFirstRay + ray, entries[k]);
        }
    }
}

#endif // GLINT_SSSR_COMPACT_HLSLI
