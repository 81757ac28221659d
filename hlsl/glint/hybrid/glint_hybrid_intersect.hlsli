// glint hybrid reflections, pass 4: screen-space intersection with feedback (docs/hybrid.md).
// The SSSR traversal (glint_sssr_intersect.hlsli) over the padded screen-space list, with a
// thickness that grows with roughness and ray length. A ray whose screen-space answer is not
// confident enough (confidence below the threshold: escaped, out of budget, stopped for
// occupancy, rejected, behind, or a hit on the background) is a miss; below the ray-tracing
// roughness threshold it is appended to the ray-traced list instead of being written, otherwise
// its screen-space result (blended with the environment) stands. With re-shading on, every
// screen-space result with any confidence is appended instead to the re-shaded list (the end of
// the ray-traced list, growing down) with its hit, for the shading pass to shade with the same
// callbacks as ray-traced hits. Each ray counts 1 + its quad copies into its tile's feedback
// counter, as a hit or a miss: summed per 32-entry block (one tile, by the list's construction)
// in groupshared memory, one atomic per block and field.
//
// Integration: the callbacks of glint_sssr_intersect.hlsli, with GLINT_SSSR_LoadRayCount
// returning counter 1 (the screen-space list's length, padding included) and
// GLINT_SSSR_LoadRay reading the screen-space list, and these:
//
//   uint GLINT_HYBRID_AddRayTracedRays(uint count);    atomic add to counter 4, returns the old value
//   uint GLINT_HYBRID_AddReshadedHits(uint count);     atomic add to counter 6, returns the old value
//   void GLINT_HYBRID_CountScreenSpaceAnswers(uint count);  atomic add to counter 8 (statistics)
//   void GLINT_HYBRID_StoreRayTracedRay(uint index, uint entry);   the ray-traced list
//   void GLINT_HYBRID_StoreHit(uint index, uint4 record);          the hit records
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
uint GLINT_HYBRID_AddReshadedHits(uint count);
void GLINT_HYBRID_CountScreenSpaceAnswers(uint count);
void GLINT_HYBRID_StoreRayTracedRay(uint index, uint entry);
void GLINT_HYBRID_StoreHit(uint index, uint4 record);
void GLINT_HYBRID_AddFeedback(int2 tile, uint value);

#define GLINT_HYBRID_BLOCKS_PER_GROUP (GLINT_SSSR_RAYS_PER_GROUP / GLINT_HYBRID_RAY_BLOCK)

groupshared uint g_glint_hybrid_block_feedback[GLINT_HYBRID_BLOCKS_PER_GROUP];
// [0]: rays for the ray tracer, [1]: screen-space hits to re-shade, [2]: rays answered in
// screen space (counted only).
groupshared uint g_glint_hybrid_append_count[3];
groupshared uint g_glint_hybrid_append_base[2];

// This lane's slot among the group's appends to list `list`: one shared atomic per wave.
uint GLINT_HYBRID_WaveAppendSlot(bool append, uint list)
{
    uint waveCount = WaveActiveCountBits(append);
    uint waveBase = 0;
    if (WaveIsFirstLane() && waveCount > 0)
        InterlockedAdd(g_glint_hybrid_append_count[list], waveCount, waveBase);
    return WaveReadLaneFirst(waveBase) + WavePrefixCountBits(append);
}

void GLINT_HYBRID_IntersectScreenSpace(GLINT_SssrConstants c, GLINT_HybridConstants h, uint groupIndex, uint rayIndex)
{
    if (groupIndex < GLINT_HYBRID_BLOCKS_PER_GROUP)
        g_glint_hybrid_block_feedback[groupIndex] = 0;
    if (groupIndex < 3)
        g_glint_hybrid_append_count[groupIndex] = 0;
    bool listed = rayIndex < GLINT_SSSR_LoadRayCount();
    uint entry = GLINT_HYBRID_PADDING_ENTRY;
    if (listed)
        entry = GLINT_SSSR_LoadRay(rayIndex);
    bool valid = listed && entry != GLINT_HYBRID_PADDING_ENTRY;
    // Its barriers also order the initialization above before the atomics below.
    GLINT_SSSR_RayResult r = GLINT_SSSR_TraceEntry(c, groupIndex, valid, valid ? entry : 0u,
                                                   float2(h.thicknessRoughnessGrowth, h.thicknessDistanceGrowth));

    bool rayTracing = (h.flags & GLINT_HYBRID_FLAG_RAY_TRACING) != 0;
    bool miss = r.valid && rayTracing && !(r.confidence >= h.confidenceThreshold);
    bool toRayTracer = miss && r.alpha < h.rayTracingThreshold;
    bool toShading = r.valid && !toRayTracer && (h.flags & GLINT_HYBRID_FLAG_RESHADE) != 0 && r.confidence > 0.0;
    if (r.valid && !toRayTracer && !toShading)
        GLINT_SSSR_StoreResult(r.entry, r.result, r.confidence, r);
    if (r.valid)
    {
        uint weight = 1u + countbits(r.entry & (GLINT_SSSR_RAY_COPY_H | GLINT_SSSR_RAY_COPY_V | GLINT_SSSR_RAY_COPY_D));
        uint field = miss ? GLINT_HYBRID_FEEDBACK_MISSES_SHIFT : GLINT_HYBRID_FEEDBACK_HITS_SHIFT;
        InterlockedAdd(g_glint_hybrid_block_feedback[groupIndex / GLINT_HYBRID_RAY_BLOCK], weight << field);
    }
    uint tracedSlot = GLINT_HYBRID_WaveAppendSlot(toRayTracer, 0);
    uint shadedSlot = GLINT_HYBRID_WaveAppendSlot(toShading, 1);
    GLINT_HYBRID_WaveAppendSlot(r.valid && !toRayTracer, 2);
    GroupMemoryBarrierWithGroupSync();
    if (groupIndex == 0 && g_glint_hybrid_append_count[0] > 0)
        g_glint_hybrid_append_base[0] = GLINT_HYBRID_AddRayTracedRays(g_glint_hybrid_append_count[0]);
    if (groupIndex == 0 && g_glint_hybrid_append_count[1] > 0)
        g_glint_hybrid_append_base[1] = GLINT_HYBRID_AddReshadedHits(g_glint_hybrid_append_count[1]);
    if (groupIndex == 0 && g_glint_hybrid_append_count[2] > 0)
        GLINT_HYBRID_CountScreenSpaceAnswers(g_glint_hybrid_append_count[2]);
    // The first entry of a block is its tile's (a tile's real entries come first in its
    // allocation), and a block with any ray has a real first entry.
    uint blockFeedback = g_glint_hybrid_block_feedback[groupIndex / GLINT_HYBRID_RAY_BLOCK];
    if (groupIndex % GLINT_HYBRID_RAY_BLOCK == 0 && blockFeedback != 0 && valid)
        GLINT_HYBRID_AddFeedback(int2(GLINT_SSSR_UnpackRayPixel(entry) / GLINT_SSSR_TILE), blockFeedback);
    GroupMemoryBarrierWithGroupSync();
    if (toRayTracer)
        GLINT_HYBRID_StoreRayTracedRay(g_glint_hybrid_append_base[0] + tracedSlot, r.entry);
    if (toShading)
    {
        uint index = GLINT_HYBRID_ReshadedSlot(c.inputSize, g_glint_hybrid_append_base[1] + shadedSlot);
        GLINT_HYBRID_ScreenHit hit;
        hit.pixel = clamp(int2(floor(r.info.xy)), int2(0, 0), int2(c.inputSize) - 1);
        hit.distance = r.result.w;
        hit.confidence = r.confidence;
        GLINT_HYBRID_StoreRayTracedRay(index, r.entry);
        GLINT_HYBRID_StoreHit(index, GLINT_HYBRID_PackScreenHit(hit));
    }
}

#endif // GLINT_HYBRID_INTERSECT_HLSLI
