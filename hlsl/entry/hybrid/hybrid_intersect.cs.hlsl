// Entry for the hybrid screen-space intersection: the SSSR intersection's bindings and
// callbacks (entry/sssr/sssr_intersect_bindings.hlsli, over the padded screen-space list) plus
// the ray-traced list (with the re-shaded hits at its end), the hit records and the feedback
// counters. Engines read it as the integration example
// for glint/hybrid/glint_hybrid_intersect.hlsli.
// Permutation GLINT_SSSR_HALF_STORAGE=1: radiance and confidence stored in 16-bit float.
#define SSSR_ENTRY_EXTRA_CONSTANTS GLINT_HybridConstants g_glint_hybrid;
#define SSSR_ENTRY_WRITABLE_COUNTERS 1
#include "entry/common/glint_entry_common.hlsli"
#include "glint/sssr/glint_sssr_constants.h"
#include "glint/hybrid/glint_hybrid_constants.h"
#include "glint/hybrid/glint_hybrid_intersect.hlsli"
#include "entry/sssr/sssr_environment.hlsli"
#include "entry/sssr/sssr_intersect_bindings.hlsli"
#include "entry/hybrid/hybrid_entry_counters.hlsli"

GLINT_BINDING(16, 0) RWStructuredBuffer<uint> g_glint_hw_ray_list;
GLINT_BINDING(17, 0) GLINT_IMAGE_FORMAT(r32ui) RWTexture2D<uint> g_glint_feedback;
GLINT_BINDING(18, 0) RWStructuredBuffer<uint4> g_glint_hits;

uint GLINT_HYBRID_AddRayTracedRays(uint count) { return HybridEntryAddToCounter(GLINT_HYBRID_COUNTER_HW_RAYS, count); }
uint GLINT_HYBRID_AddReshadedHits(uint count) { return HybridEntryAddToCounter(GLINT_HYBRID_COUNTER_RESHADED, count); }
void GLINT_HYBRID_CountScreenSpaceAnswers(uint count)
{
    HybridEntryAddToCounter(GLINT_HYBRID_COUNTER_SCREEN_SPACE_ANSWERS, count);
}
void GLINT_HYBRID_StoreRayTracedRay(uint index, uint entry) { g_glint_hw_ray_list[index] = entry; }
void GLINT_HYBRID_StoreHit(uint index, uint4 record) { g_glint_hits[index] = record; }
void GLINT_HYBRID_AddFeedback(int2 tile, uint value) { InterlockedAdd(g_glint_feedback[tile], value); }

[numthreads(64, 1, 1)] void main(uint3 groupId : SV_GroupID, uint groupIndex : SV_GroupIndex)
{
    GLINT_HYBRID_IntersectScreenSpace(g_glint_sssr, g_glint_hybrid, groupIndex,
                                      (groupId.y * GLINT_SSSR_GROUPS_PER_ROW + groupId.x) * GLINT_SSSR_RAYS_PER_GROUP +
                                          groupIndex);
}
