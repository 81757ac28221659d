// Bindings and callbacks of the SSSR intersection's entry, shared by the hybrid screen-space
// intersection's entry (entry/hybrid/hybrid_intersect.cs.hlsl). Included after the headers.
#ifndef SSSR_INTERSECT_BINDINGS_HLSLI
#define SSSR_INTERSECT_BINDINGS_HLSLI

// A cbuffer holding the struct (not ConstantBuffer<T>) so that glslang can pass it by value;
// the hybrid entry adds its own constants after SSSR's (SSSR_ENTRY_EXTRA_CONSTANTS).
#ifndef SSSR_ENTRY_EXTRA_CONSTANTS
#define SSSR_ENTRY_EXTRA_CONSTANTS
#endif
GLINT_BINDING(0, 0) cbuffer g_glint_constants { GLINT_SssrConstants g_glint_sssr; SSSR_ENTRY_EXTRA_CONSTANTS };
GLINT_BINDING(1, 0) Texture2D<float> g_glint_depth;
#if GLINT_SSSR_THICKNESS_AWARE
GLINT_BINDING(2, 0) Texture2D<float2> g_glint_depth_pyramid;
#else
GLINT_BINDING(2, 0) Texture2D<float> g_glint_depth_pyramid;
#endif
GLINT_BINDING(3, 0) Texture2D<float4> g_glint_normals;
GLINT_BINDING(4, 0) Texture2D<float> g_glint_roughness;
GLINT_BINDING(5, 0) Texture2D<float2> g_glint_blue_noise;
GLINT_BINDING(6, 0) Texture2D<float4> g_glint_color;
GLINT_BINDING(7, 0) Texture2D<float2> g_glint_motion;
GLINT_BINDING(8, 0) Texture2D<float4> g_glint_environment;
GLINT_BINDING(9, 0) SamplerState g_glint_linear_clamp;
// The hybrid entry appends to the ray-traced count (SSSR_ENTRY_WRITABLE_COUNTERS).
#if SSSR_ENTRY_WRITABLE_COUNTERS
GLINT_BINDING(10, 0) RWStructuredBuffer<uint> g_glint_counters;
#else
GLINT_BINDING(10, 0) StructuredBuffer<uint> g_glint_counters;
#endif
GLINT_BINDING(11, 0) StructuredBuffer<uint> g_glint_ray_list;
GLINT_BINDING(12, 0) GLINT_FLOAT4_STORAGE(GLINT_SSSR_HALF_STORAGE) g_glint_radiance;
GLINT_BINDING(13, 0) GLINT_FLOAT_STORAGE(GLINT_SSSR_HALF_STORAGE) g_glint_confidence;
#if GLINT_SSSR_DEBUG_OUTPUT
GLINT_BINDING(14, 0) GLINT_IMAGE_FORMAT(rgba32f) RWTexture2D<float4> g_glint_ray_info;
void GLINT_SSSR_StoreRayInfo(int2 pixel, float4 info) { g_glint_ray_info[pixel] = info; }
#endif
#if GLINT_SSSR_STORE_RAY
#if GLINT_SSSR_HALF_STORAGE
GLINT_BINDING(15, 0) GLINT_IMAGE_FORMAT(rgba16f) RWTexture2D<float4> g_glint_rays;
// The pdf of a near-mirror sample exceeds the fp16 range: clamped before narrowing.
void GLINT_SSSR_StoreRay(int2 pixel, float4 ray) { g_glint_rays[pixel] = float4(ray.xyz, min(ray.w, 65504.0)); }
#else
GLINT_BINDING(15, 0) GLINT_IMAGE_FORMAT(rgba32f) RWTexture2D<float4> g_glint_rays;
void GLINT_SSSR_StoreRay(int2 pixel, float4 ray) { g_glint_rays[pixel] = ray; }
#endif
#endif

// Level 0 is the input depth itself: the pyramid is built without its level-0 copy. Both
// textures are read unconditionally and the result selected, so that rays of one wave at
// different levels issue their loads together instead of one texture after the other.
float GLINT_SSSR_LoadDepth(int2 texel, int mip)
{
    float level0 = g_glint_depth.Load(int3(texel, 0)); // in range at every mip: texel <= pixel
    int coarseMip = max(mip, 1);
#if GLINT_SSSR_THICKNESS_AWARE
    float coarse = g_glint_depth_pyramid.Load(int3(texel >> (coarseMip - mip), coarseMip)).x;
#else
    float coarse = g_glint_depth_pyramid.Load(int3(texel >> (coarseMip - mip), coarseMip));
#endif
    return mip == 0 ? level0 : coarse;
}
#if GLINT_SSSR_THICKNESS_AWARE
float GLINT_SSSR_LoadFarthestDepth(int2 texel, int mip) { return g_glint_depth_pyramid.Load(int3(texel, mip)).y; }
#endif
float3 GLINT_SSSR_LoadNormal(int2 pixel) { return g_glint_normals.Load(int3(pixel, 0)).xyz; }
float GLINT_SSSR_LoadRoughness(int2 pixel) { return g_glint_roughness.Load(int3(pixel, 0)); }
float2 GLINT_SSSR_LoadBlueNoise(int2 pixel) { return g_glint_blue_noise.Load(int3(pixel & 127, 0)); }
float3 GLINT_SSSR_LoadColor(int2 pixel) { return g_glint_color.Load(int3(pixel, 0)).rgb; }
float3 GLINT_SSSR_SampleColor(float2 uv) { return g_glint_color.SampleLevel(g_glint_linear_clamp, uv, 0).rgb; }
float2 GLINT_SSSR_LoadMotion(int2 pixel) { return g_glint_motion.Load(int3(pixel, 0)); }
float3 GLINT_SSSR_SampleEnvironment(float3 direction, float lod)
{
    return SSSR_EntrySampleLatLong(g_glint_environment, g_glint_linear_clamp, direction, lod);
}
uint GLINT_SSSR_LoadRayCount() { return g_glint_counters[1]; }
uint GLINT_SSSR_LoadRay(uint index) { return g_glint_ray_list[index]; }
void GLINT_SSSR_StoreRadiance(int2 pixel, float4 value) { g_glint_radiance[pixel] = value; }
void GLINT_SSSR_StoreConfidence(int2 pixel, float confidence) { g_glint_confidence[pixel] = confidence; }

#endif // SSSR_INTERSECT_BINDINGS_HLSLI
