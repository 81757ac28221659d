// Bindings and callbacks the harness's two ray-traced hybrid passes share (ray tracing,
// deferred shading): the constants, the listed pixels' surfaces and blue noise, and the
// ray-traced list. Each entry adds its hit records at binding 7 and its own bindings after.
#ifndef HYBRID_RAY_BINDINGS_HLSLI
#define HYBRID_RAY_BINDINGS_HLSLI

GLINT_BINDING(0, 0) cbuffer g_glint_constants { GLINT_SssrConstants g_glint_sssr; GLINT_HybridConstants g_glint_hybrid; };
GLINT_BINDING(1, 0) Texture2D<float> g_glint_depth;
GLINT_BINDING(2, 0) Texture2D<float4> g_glint_normals;
GLINT_BINDING(3, 0) Texture2D<float> g_glint_roughness;
GLINT_BINDING(4, 0) Texture2D<float2> g_glint_blue_noise;
GLINT_BINDING(5, 0) StructuredBuffer<uint> g_glint_counters;
GLINT_BINDING(6, 0) StructuredBuffer<uint> g_glint_hw_ray_list;

float GLINT_SSSR_LoadDepth(int2 texel, int mip) { return g_glint_depth.Load(int3(texel, 0)); }
float3 GLINT_SSSR_LoadNormal(int2 pixel) { return g_glint_normals.Load(int3(pixel, 0)).xyz; }
float GLINT_SSSR_LoadRoughness(int2 pixel) { return g_glint_roughness.Load(int3(pixel, 0)); }
float2 GLINT_SSSR_LoadBlueNoise(int2 pixel) { return g_glint_blue_noise.Load(int3(pixel & 127, 0)); }
uint GLINT_HYBRID_LoadRayTracedCount() { return g_glint_counters[GLINT_HYBRID_COUNTER_HW_RAYS_COPY]; }
uint GLINT_HYBRID_LoadRayTracedRay(uint index) { return g_glint_hw_ray_list[index]; }

// The ray index of the SSSR intersection's indirect grid.
uint HybridRayIndex(uint3 groupId, uint groupIndex)
{
    return (groupId.y * GLINT_SSSR_GROUPS_PER_ROW + groupId.x) * GLINT_SSSR_RAYS_PER_GROUP + groupIndex;
}

#endif // HYBRID_RAY_BINDINGS_HLSLI
