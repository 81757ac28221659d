// Bindings and callbacks of the SSSR classification's entry, shared by the hybrid
// classification's entry (entry/hybrid/hybrid_classify.cs.hlsl); each adds its ray lists at
// bindings 12 and 14 and up. Included after the headers.
#ifndef SSSR_CLASSIFY_BINDINGS_HLSLI
#define SSSR_CLASSIFY_BINDINGS_HLSLI

// A cbuffer holding the struct (not ConstantBuffer<T>) so that glslang can pass it by value;
// the hybrid entry adds its own constants after SSSR's (SSSR_ENTRY_EXTRA_CONSTANTS).
#ifndef SSSR_ENTRY_EXTRA_CONSTANTS
#define SSSR_ENTRY_EXTRA_CONSTANTS
#endif
GLINT_BINDING(0, 0) cbuffer g_glint_constants { GLINT_SssrConstants g_glint_sssr; SSSR_ENTRY_EXTRA_CONSTANTS };
GLINT_BINDING(1, 0) Texture2D<float> g_glint_depth;
GLINT_BINDING(2, 0) Texture2D<float4> g_glint_normals;
GLINT_BINDING(3, 0) Texture2D<float4> g_glint_material;
GLINT_BINDING(4, 0) Texture2D<float2> g_glint_motion;
GLINT_BINDING(5, 0) Texture2D<float> g_glint_variance_history;
GLINT_BINDING(6, 0) Texture2D<float4> g_glint_environment;
GLINT_BINDING(7, 0) SamplerState g_glint_linear_clamp;
GLINT_BINDING(8, 0) GLINT_FLOAT_STORAGE(GLINT_SSSR_HALF_STORAGE) g_glint_roughness;
GLINT_BINDING(9, 0) GLINT_FLOAT4_STORAGE(GLINT_SSSR_HALF_STORAGE) g_glint_radiance;
GLINT_BINDING(10, 0) GLINT_FLOAT_STORAGE(GLINT_SSSR_HALF_STORAGE) g_glint_confidence;
GLINT_BINDING(11, 0) RWStructuredBuffer<uint> g_glint_counters;
GLINT_BINDING(13, 0) RWStructuredBuffer<uint> g_glint_tile_list;

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

#endif // SSSR_CLASSIFY_BINDINGS_HLSLI
