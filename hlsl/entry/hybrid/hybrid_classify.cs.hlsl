// Entry for the hybrid tile classification: bindings, callbacks, main. Engines read this file
// as the integration example for glint/hybrid/glint_hybrid_classify.hlsli.
// Permutation GLINT_SSSR_HALF_STORAGE=1: roughness, radiance and confidence stored in 16-bit
// float (the header clamps radiance to the fp16 range first).
#include "entry/common/glint_entry_common.hlsli"
#include "glint/sssr/glint_sssr_constants.h"
#include "glint/hybrid/glint_hybrid_constants.h"
#include "glint/hybrid/glint_hybrid_classify.hlsli"
#include "entry/sssr/sssr_environment.hlsli"

// A cbuffer holding the structs (not ConstantBuffer<T>) so that glslang can pass them by value.
GLINT_BINDING(0, 0) cbuffer g_glint_constants { GLINT_SssrConstants g_glint_sssr; GLINT_HybridConstants g_glint_hybrid; };
GLINT_BINDING(1, 0) Texture2D<float> g_glint_depth;
GLINT_BINDING(2, 0) Texture2D<float4> g_glint_normals;
GLINT_BINDING(3, 0) Texture2D<float4> g_glint_material;
GLINT_BINDING(4, 0) Texture2D<float2> g_glint_motion;
GLINT_BINDING(5, 0) Texture2D<float> g_glint_variance_history;
GLINT_BINDING(6, 0) Texture2D<float4> g_glint_environment;
GLINT_BINDING(7, 0) SamplerState g_glint_linear_clamp;
#if GLINT_SSSR_HALF_STORAGE
GLINT_BINDING(8, 0) GLINT_IMAGE_FORMAT(r16f) RWTexture2D<float> g_glint_roughness;
GLINT_BINDING(9, 0) GLINT_IMAGE_FORMAT(rgba16f) RWTexture2D<float4> g_glint_radiance;
GLINT_BINDING(10, 0) GLINT_IMAGE_FORMAT(r16f) RWTexture2D<float> g_glint_confidence;
#else
GLINT_BINDING(8, 0) GLINT_IMAGE_FORMAT(r32f) RWTexture2D<float> g_glint_roughness;
GLINT_BINDING(9, 0) GLINT_IMAGE_FORMAT(rgba32f) RWTexture2D<float4> g_glint_radiance;
GLINT_BINDING(10, 0) GLINT_IMAGE_FORMAT(r32f) RWTexture2D<float> g_glint_confidence;
#endif
GLINT_BINDING(11, 0) RWStructuredBuffer<uint> g_glint_counters;
GLINT_BINDING(12, 0) RWStructuredBuffer<uint> g_glint_sw_ray_list;
GLINT_BINDING(13, 0) RWStructuredBuffer<uint> g_glint_hw_ray_list;
GLINT_BINDING(14, 0) RWStructuredBuffer<uint> g_glint_tile_list;
GLINT_BINDING(15, 0) Texture2D<uint> g_glint_feedback_history;
GLINT_BINDING(16, 0) GLINT_IMAGE_FORMAT(r32ui) RWTexture2D<uint> g_glint_feedback;
GLINT_BINDING(17, 0) GLINT_IMAGE_FORMAT(r32ui) RWTexture2D<uint> g_glint_tile_class;

float GLINT_SSSR_LoadDepth(int2 pixel, int mip) { return g_glint_depth.Load(int3(pixel, 0)); }
float3 GLINT_SSSR_LoadNormal(int2 pixel) { return g_glint_normals.Load(int3(pixel, 0)).xyz; }
float4 GLINT_SSSR_LoadMaterial(int2 pixel) { return g_glint_material.Load(int3(pixel, 0)); }
float2 GLINT_SSSR_LoadMotion(int2 pixel) { return g_glint_motion.Load(int3(pixel, 0)); }
float GLINT_SSSR_SampleVarianceHistory(float2 uv) { return g_glint_variance_history.SampleLevel(g_glint_linear_clamp, uv, 0); }
float3 GLINT_SSSR_SampleEnvironment(float3 direction, float lod)
{
    return SSSR_EntrySampleLatLong(g_glint_environment, g_glint_linear_clamp, direction, lod);
}
void GLINT_SSSR_StoreRoughness(int2 pixel, float alpha) { g_glint_roughness[pixel] = alpha; }
void GLINT_SSSR_StoreRadiance(int2 pixel, float4 value) { g_glint_radiance[pixel] = value; }
void GLINT_SSSR_StoreConfidence(int2 pixel, float confidence) { g_glint_confidence[pixel] = confidence; }
uint GLINT_SSSR_AddTile()
{
    uint previous;
    InterlockedAdd(g_glint_counters[2], 1u, previous);
    return previous;
}
void GLINT_SSSR_StoreTile(uint index, uint entry) { g_glint_tile_list[index] = entry; }

uint GLINT_HYBRID_LoadFeedbackHistory(int2 tile) { return g_glint_feedback_history.Load(int3(tile, 0)); }
void GLINT_HYBRID_StoreFeedback(int2 tile, uint counter) { g_glint_feedback[tile] = counter; }
void GLINT_HYBRID_StoreTileClass(int2 tile, uint tileClass) { g_glint_tile_class[tile] = tileClass; }
uint GLINT_HYBRID_MaterialRoute(int2 pixel, float alpha)
{
    bool mirror = alpha < g_glint_sssr.mirrorThreshold;
    return mirror && (g_glint_hybrid.flags & GLINT_HYBRID_FLAG_MIRRORS_RAY_TRACED) != 0 ? GLINT_HYBRID_ROUTE_RAY_TRACED
                                                                                        : GLINT_HYBRID_ROUTE_AUTO;
}
uint GLINT_HYBRID_AddScreenSpaceRays(uint count)
{
    uint previous;
    InterlockedAdd(g_glint_counters[0], count, previous);
    return previous;
}
void GLINT_HYBRID_StoreScreenSpaceRay(uint index, uint entry) { g_glint_sw_ray_list[index] = entry; }
uint GLINT_HYBRID_AddRayTracedRays(uint count)
{
    uint previous;
    InterlockedAdd(g_glint_counters[GLINT_HYBRID_COUNTER_HW_RAYS], count, previous);
    return previous;
}
void GLINT_HYBRID_StoreRayTracedRay(uint index, uint entry) { g_glint_hw_ray_list[index] = entry; }

[numthreads(8, 8, 1)] void main(uint3 groupId : SV_GroupID, uint3 groupThreadId : SV_GroupThreadID)
{
    GLINT_HYBRID_Classify(g_glint_sssr, g_glint_hybrid, groupId.xy, groupThreadId.xy);
}
