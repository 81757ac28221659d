// Entry for the hybrid ray tracing pass in an engine: GLINT_HYBRID_TraceRay by an inline ray
// query (Shader Model 6.5, DXC only: glslang's HLSL front end has no ray query), over the
// engine's top-level acceleration structure, opaque geometry. Compile with
//   dxc -T cs_6_5 -HV 2021 -WX -E main -I <glint hlsl root> (DXIL), or add
//   -spirv -fspv-target-env=vulkan1.2 (SPIR-V: SPV_KHR_ray_query needs SPIR-V 1.4).
// The other callbacks and bindings are those of harness/shaders/hybrid_trace_bvh.cs.hlsl.
#include "entry/common/glint_entry_common.hlsli"
#include "glint/sssr/glint_sssr_constants.h"
#include "glint/hybrid/glint_hybrid_constants.h"
#include "glint/hybrid/glint_hybrid_trace.hlsli"

GLINT_BINDING(0, 0) cbuffer g_glint_constants : register(b0) { GLINT_SssrConstants g_glint_sssr; GLINT_HybridConstants g_glint_hybrid; };
GLINT_BINDING(1, 0) Texture2D<float> g_glint_depth : register(t1);
GLINT_BINDING(2, 0) Texture2D<float4> g_glint_normals : register(t2);
GLINT_BINDING(3, 0) Texture2D<float> g_glint_roughness : register(t3);
GLINT_BINDING(4, 0) Texture2D<float2> g_glint_blue_noise : register(t4);
GLINT_BINDING(5, 0) StructuredBuffer<uint> g_glint_counters : register(t5);
GLINT_BINDING(6, 0) StructuredBuffer<uint> g_glint_hw_ray_list : register(t6);
GLINT_BINDING(7, 0) RWStructuredBuffer<uint4> g_glint_hits : register(u7);
GLINT_BINDING(8, 0) RaytracingAccelerationStructure g_glint_scene : register(t8);

float GLINT_SSSR_LoadDepth(int2 texel, int mip) { return g_glint_depth.Load(int3(texel, 0)); }
float3 GLINT_SSSR_LoadNormal(int2 pixel) { return g_glint_normals.Load(int3(pixel, 0)).xyz; }
float GLINT_SSSR_LoadRoughness(int2 pixel) { return g_glint_roughness.Load(int3(pixel, 0)); }
float2 GLINT_SSSR_LoadBlueNoise(int2 pixel) { return g_glint_blue_noise.Load(int3(pixel & 127, 0)); }
uint GLINT_HYBRID_LoadRayTracedCount() { return g_glint_counters[GLINT_HYBRID_COUNTER_HW_RAYS_COPY]; }
uint GLINT_HYBRID_LoadRayTracedRay(uint index) { return g_glint_hw_ray_list[index]; }
void GLINT_HYBRID_StoreHit(uint index, uint4 record) { g_glint_hits[index] = record; }

GLINT_HYBRID_Hit GLINT_HYBRID_TraceRay(float3 origin, float3 direction, float tMin, float tMax)
{
    RayDesc ray;
    ray.Origin = origin;
    ray.Direction = direction;
    ray.TMin = tMin;
    ray.TMax = tMax;
    RayQuery<RAY_FLAG_FORCE_OPAQUE> query;
    query.TraceRayInline(g_glint_scene, RAY_FLAG_NONE, 0xFF, ray);
    while (query.Proceed())
    {
        // Opaque geometry only: traversal needs no candidate decisions.
    }
    GLINT_HYBRID_Hit hit;
    hit.t = -1.0;
    hit.primitive = 0;
    hit.barycentrics = float2(0.0, 0.0);
    hit.instance = 0;
    if (query.CommittedStatus() == COMMITTED_TRIANGLE_HIT)
    {
        hit.t = query.CommittedRayT();
        hit.primitive = query.CommittedPrimitiveIndex();
        hit.barycentrics = query.CommittedTriangleBarycentrics();
        hit.instance = query.CommittedInstanceID();
    }
    return hit;
}

[numthreads(64, 1, 1)] void main(uint3 groupId : SV_GroupID, uint groupIndex : SV_GroupIndex)
{
    GLINT_HYBRID_TraceRays(g_glint_sssr, g_glint_hybrid,
                           (groupId.y * GLINT_SSSR_GROUPS_PER_ROW + groupId.x) * GLINT_SSSR_RAYS_PER_GROUP + groupIndex);
}
