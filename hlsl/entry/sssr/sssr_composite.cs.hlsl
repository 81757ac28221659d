// Entry for the SSSR composite (glint/sssr/glint_sssr_composite.hlsli).
#include "entry/common/glint_entry_common.hlsli"
#include "glint/sssr/glint_sssr_constants.h"
#include "glint/sssr/glint_sssr_composite.hlsli"

// A cbuffer holding the struct (not ConstantBuffer<T>) so that glslang can pass it by value.
GLINT_BINDING(0, 0) cbuffer g_glint_constants { GLINT_SssrConstants g_glint_sssr; };
GLINT_BINDING(1, 0) Texture2D<float4> g_glint_color;
GLINT_BINDING(2, 0) Texture2D<float4> g_glint_reflection;
GLINT_BINDING(3, 0) Texture2D<float> g_glint_depth;
GLINT_BINDING(4, 0) Texture2D<float4> g_glint_normals;
GLINT_BINDING(5, 0) Texture2D<float> g_glint_roughness;
GLINT_BINDING(6, 0) Texture2D<float4> g_glint_base_color_metallic;
GLINT_BINDING(7, 0) Texture2D<float2> g_glint_brdf_lut;
GLINT_BINDING(8, 0) SamplerState g_glint_linear_clamp;
GLINT_BINDING(9, 0) GLINT_IMAGE_FORMAT(rgba32f) RWTexture2D<float4> g_glint_composite;

float3 GLINT_SSSR_LoadColor(int2 pixel) { return g_glint_color.Load(int3(pixel, 0)).rgb; }
float3 GLINT_SSSR_LoadReflection(int2 pixel) { return g_glint_reflection.Load(int3(pixel, 0)).rgb; }
float GLINT_SSSR_LoadDepth(int2 pixel, int mip) { return g_glint_depth.Load(int3(pixel, 0)); }
float3 GLINT_SSSR_LoadNormal(int2 pixel) { return g_glint_normals.Load(int3(pixel, 0)).xyz; }
float GLINT_SSSR_LoadRoughness(int2 pixel) { return g_glint_roughness.Load(int3(pixel, 0)); }
float4 GLINT_SSSR_LoadBaseColorMetallic(int2 pixel) { return g_glint_base_color_metallic.Load(int3(pixel, 0)); }
float2 GLINT_SSSR_SampleBrdfLut(float2 uv) { return g_glint_brdf_lut.SampleLevel(g_glint_linear_clamp, uv, 0); }
void GLINT_SSSR_StoreComposite(int2 pixel, float4 color) { g_glint_composite[pixel] = color; }

[numthreads(8, 8, 1)] void main(uint3 dispatchId : SV_DispatchThreadID)
{
    GLINT_SSSR_Composite(g_glint_sssr, dispatchId.xy);
}
