// glint hybrid reflections, pass 4: screen-space intersection with feedback (docs/hybrid.md).
// The SSSR traversal (glint_sssr_intersect.hlsli) over the padded screen-space list. A ray
// whose screen-space answer is not confident enough (confidence below the threshold: escaped,
// out of budget, stopped for occupancy, rejected, behind, or a hit on the background) is a
// miss; below the ray-tracing roughness threshold it is appended to the ray-traced list
// instead of being written, otherwise its screen-space result (blended with the environment)
// stands. Each ray counts 1 + its quad copies into its tile's feedback counter, as a hit or a
// miss: summed per 32-entry block (one tile, by the list's construction) in groupshared
// memory, one atomic per block and field.
//
// Integration: the callbacks of glint_sssr_intersect.hlsli, with GLINT_SSSR_LoadRayCount
// returning counter 1 (the screen-space list's length, padding included) and
// GLINT_SSSR_LoadRay reading the screen-space list, and these:
//
//   uint GLINT_HYBRID_AddRayTracedRays(uint count);    atomic add to counter 4, returns the old value
//   void GLINT_HYBRID_StoreRayTracedRay(uint index, uint entry);
//   void GLINT_HYBRID_AddFeedback(int2 tile, uint value);  atomic add into this frame's counter image
//
// Entry: from main, GLINT_HYBRID_IntersectScreenSpace(c, h, SV_GroupIndex, rayIndex) with the
// SSSR intersection's ray index formula. Dispatch: [numthreads(64, 1, 1)], indirect from the
// arguments buffer at byte 0 (written by the SSSR indirect-arguments pass over counter 0).
// Padding entries touch no memory.
#ifndef GLINT_HYBRID_INTERSECT_HLSLI
#define GLINT_HYBRID_INTERSECT_HLSLI

#include "glint/hybrid/glint_hybrid_common.hlsli"
#include "glint/sssr/glint_sssr_intersect.hlsli"

uint GLINT_HYBRID_AddRayTracedRays(uint count);
void GLINT_HYBRID_StoreRayTracedRay(uint index, uint entry);
void GLINT_HYBRID_AddFeedback(int2 tile, uint value);

#define GLINT_HYBRID_BLOCKS_PER_GROUP (GLINT_SSSR_RAYS_PER_GROUP / GLINT_HYBRID_RAY_BLOCK)

groupshared uint g_glint_hybrid_block_feedback[GLINT_HYBRID_BLOCKS_PER_GROUP];
groupshared uint g_glint_hybrid_traced_count;
groupshared uint g_glint_hybrid_traced_base;

void GLINT_HYBRID_IntersectScreenSpace(GLINT_SssrConstants c, GLINT_HybridConstants h, uint groupIndex, uint rayIndex)
{
    if (groupIndex < GLINT_HYBRID_BLOCKS_PER_GROUP)
        g_glint_hybrid_block_feedback[groupIndex] = 0;
    if (groupIndex == 0)
        g_glint_hybrid_traced_count = 0;
    bool listed = rayIndex < GLINT_SSSR_LoadRayCount();
    uint entry = GLINT_HYBRID_PADDING_ENTRY;
    if (listed)
        entry = GLINT_SSSR_LoadRay(rayIndex);
    bool valid = listed && entry != GLINT_HYBRID_PADDING_ENTRY;
    // Its barriers also order the initialization above before the atomics below.
    GLINT_SSSR_RayResult r = GLINT_SSSR_TraceEntry(c, groupIndex, valid, valid ? entry : 0u);

    bool rayTracing = (h.flags & GLINT_HYBRID_FLAG_RAY_TRACING) != 0;
    bool miss = r.valid && rayTracing && !(r.confidence >= h.confidenceThreshold);
    bool toRayTracer = miss && r.alpha < h.rayTracingThreshold;
    if (r.valid && !toRayTracer)
        GLINT_SSSR_StoreResult(r.entry, r.result, r.confidence, r);
    if (r.valid)
    {
        uint weight = 1u + countbits(r.entry & (GLINT_SSSR_RAY_COPY_H | GLINT_SSSR_RAY_COPY_V | GLINT_SSSR_RAY_COPY_D));
        uint field = miss ? GLINT_HYBRID_FEEDBACK_MISSES_SHIFT : GLINT_HYBRID_FEEDBACK_HITS_SHIFT;
        InterlockedAdd(g_glint_hybrid_block_feedback[groupIndex / GLINT_HYBRID_RAY_BLOCK], weight << field);
    }
    uint waveTraced = WaveActiveCountBits(toRayTracer);
    uint waveBase = 0;
    if (WaveIsFirstLane() && waveTraced > 0)
        InterlockedAdd(g_glint_hybrid_traced_count, waveTraced, waveBase);
    uint slot = WaveReadLaneFirst(waveBase) + WavePrefixCountBits(toRayTracer);
    GroupMemoryBarrierWithGroupSync();
    if (groupIndex == 0 && g_glint_hybrid_traced_count > 0)
        g_glint_hybrid_traced_base = GLINT_HYBRID_AddRayTracedRays(g_glint_hybrid_traced_count);
    // The first entry of a block is its tile's (a tile's real entries come first in its
    // allocation), and a block with any ray has a real first entry.
    uint blockFeedback = g_glint_hybrid_block_feedback[groupIndex / GLINT_HYBRID_RAY_BLOCK];
    if (groupIndex % GLINT_HYBRID_RAY_BLOCK == 0 && blockFeedback != 0 && valid)
        GLINT_HYBRID_AddFeedback(int2(GLINT_SSSR_UnpackRayPixel(entry) / GLINT_SSSR_TILE), blockFeedback);
    GroupMemoryBarrierWithGroupSync();
    if (toRayTracer)
        GLINT_HYBRID_StoreRayTracedRay(g_glint_hybrid_traced_base + slot, r.entry);
}

#endif // GLINT_HYBRID_INTERSECT_HLSLI
