// Entry for the hybrid tile classification: the SSSR classification's bindings and callbacks
// (entry/sssr/sssr_classify_bindings.hlsli) plus the two ray lists, the feedback counters and
// the tile classes. Engines read it as the integration example for
// glint/hybrid/glint_hybrid_classify.hlsli.
// Permutation GLINT_SSSR_HALF_STORAGE=1: roughness, radiance and confidence stored in 16-bit
// float (the header clamps radiance to the fp16 range first).
#define SSSR_ENTRY_EXTRA_CONSTANTS GLINT_HybridConstants g_glint_hybrid;
#include "entry/common/glint_entry_common.hlsli"
#include "glint/sssr/glint_sssr_constants.h"
#include "glint/hybrid/glint_hybrid_constants.h"
#include "glint/hybrid/glint_hybrid_classify.hlsli"
#include "entry/sssr/sssr_environment.hlsli"
#include "entry/sssr/sssr_classify_bindings.hlsli"
#include "entry/hybrid/hybrid_entry_counters.hlsli"

GLINT_BINDING(12, 0) RWStructuredBuffer<uint> g_glint_sw_ray_list;
GLINT_BINDING(14, 0) RWStructuredBuffer<uint> g_glint_hw_ray_list;
GLINT_BINDING(15, 0) Texture2D<uint> g_glint_feedback_history;
GLINT_BINDING(16, 0) GLINT_IMAGE_FORMAT(r32ui) RWTexture2D<uint> g_glint_feedback;
GLINT_BINDING(17, 0) GLINT_IMAGE_FORMAT(r32ui) RWTexture2D<uint> g_glint_tile_class;

uint GLINT_HYBRID_LoadFeedbackHistory(int2 tile) { return g_glint_feedback_history.Load(int3(tile, 0)); }
void GLINT_HYBRID_StoreFeedback(int2 tile, uint counter) { g_glint_feedback[tile] = counter; }
void GLINT_HYBRID_StoreTileClass(int2 tile, uint tileClass) { g_glint_tile_class[tile] = tileClass; }
uint GLINT_HYBRID_MaterialRoute(int2 pixel, float alpha)
{
    bool mirror = alpha < g_glint_sssr.mirrorThreshold;
    return mirror && (g_glint_hybrid.flags & GLINT_HYBRID_FLAG_MIRRORS_RAY_TRACED) != 0 ? GLINT_HYBRID_ROUTE_RAY_TRACED
                                                                                        : GLINT_HYBRID_ROUTE_AUTO;
}
uint GLINT_HYBRID_AddScreenSpaceRays(uint count) { return HybridEntryAddToCounter(0, count); }
void GLINT_HYBRID_StoreScreenSpaceRay(uint index, uint entry) { g_glint_sw_ray_list[index] = entry; }
uint GLINT_HYBRID_AddRayTracedRays(uint count) { return HybridEntryAddToCounter(GLINT_HYBRID_COUNTER_HW_RAYS, count); }
void GLINT_HYBRID_StoreRayTracedRay(uint index, uint entry) { g_glint_hw_ray_list[index] = entry; }

[numthreads(8, 8, 1)] void main(uint3 groupId : SV_GroupID, uint3 groupThreadId : SV_GroupThreadID)
{
    GLINT_HYBRID_Classify(g_glint_sssr, g_glint_hybrid, groupId.xy, groupThreadId.xy);
}
