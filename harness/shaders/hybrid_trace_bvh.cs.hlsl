// The hybrid effect's ray tracing pass in the harness: GLINT_HYBRID_TraceRay by the
// simulator's BVH traversal over the scene's own geometry (an engine implements it with
// RayQuery: hlsl/entry/hybrid/hybrid_trace_rayquery.cs.hlsl).
#include "entry/common/glint_entry_common.hlsli"
#include "glint/sssr/glint_sssr_constants.h"
#include "glint/hybrid/glint_hybrid_constants.h"
#include "glint/hybrid/glint_hybrid_trace.hlsli"

#include "../harness/shaders/hybrid_ray_bindings.hlsli"
GLINT_BINDING(7, 0) RWStructuredBuffer<uint4> g_glint_hits;

#include "../harness/shaders/hybrid_scene_bindings.hlsli"

void GLINT_HYBRID_StoreHit(uint index, uint4 record) { g_glint_hits[index] = record; }

[numthreads(64, 1, 1)] void main(uint3 groupId : SV_GroupID, uint groupIndex : SV_GroupIndex)
{
    GLINT_HYBRID_TraceRays(g_glint_sssr, g_glint_hybrid, HybridRayIndex(groupId, groupIndex));
}
