// The hybrid effect's ray tracing pass in the harness: GLINT_HYBRID_TraceRay by the
// simulator's BVH traversal over the scene's own geometry (an engine implements it with
// RayQuery: hlsl/entry/hybrid/hybrid_trace_rayquery.cs.hlsl).
#include "entry/common/glint_entry_common.hlsli"
#include "glint/sssr/glint_sssr_constants.h"
#include "glint/hybrid/glint_hybrid_constants.h"
#include "glint/hybrid/glint_hybrid_trace.hlsli"

GLINT_BINDING(0, 0) cbuffer g_glint_constants { GLINT_SssrConstants g_glint_sssr; GLINT_HybridConstants g_glint_hybrid; };
GLINT_BINDING(1, 0) Texture2D<float> g_glint_depth;
GLINT_BINDING(2, 0) Texture2D<float4> g_glint_normals;
GLINT_BINDING(3, 0) Texture2D<float> g_glint_roughness;
GLINT_BINDING(4, 0) Texture2D<float2> g_glint_blue_noise;
GLINT_BINDING(5, 0) StructuredBuffer<uint> g_glint_counters;
GLINT_BINDING(6, 0) StructuredBuffer<uint> g_glint_hw_ray_list;
GLINT_BINDING(7, 0) RWStructuredBuffer<uint4> g_glint_hits;

#include "../harness/shaders/hybrid_scene_bindings.hlsli"

float GLINT_SSSR_LoadDepth(int2 texel, int mip) { return g_glint_depth.Load(int3(texel, 0)); }
float3 GLINT_SSSR_LoadNormal(int2 pixel) { return g_glint_normals.Load(int3(pixel, 0)).xyz; }
float GLINT_SSSR_LoadRoughness(int2 pixel) { return g_glint_roughness.Load(int3(pixel, 0)); }
float2 GLINT_SSSR_LoadBlueNoise(int2 pixel) { return g_glint_blue_noise.Load(int3(pixel & 127, 0)); }
uint GLINT_HYBRID_LoadRayTracedCount() { return g_glint_counters[GLINT_HYBRID_COUNTER_HW_RAYS_COPY]; }
uint GLINT_HYBRID_LoadRayTracedRay(uint index) { return g_glint_hw_ray_list[index]; }
void GLINT_HYBRID_StoreHit(uint index, uint4 record) { g_glint_hits[index] = record; }

[numthreads(64, 1, 1)] void main(uint3 groupId : SV_GroupID, uint groupIndex : SV_GroupIndex)
{
    GLINT_HYBRID_TraceRays(g_glint_sssr, g_glint_hybrid,
                           (groupId.y * GLINT_SSSR_GROUPS_PER_ROW + groupId.x) * GLINT_SSSR_RAYS_PER_GROUP + groupIndex);
}
