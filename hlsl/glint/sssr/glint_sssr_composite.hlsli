// glint SSSR, pass 7 (optional, for demos and pictures): applies a reflection to the lit
// scene with the split-sum approximation, L = L_lit + R (F0 A + B), where (A, B) is the
// DFG table at (N.V, r) (glint::sssrBrdfLut) and F0 = lerp(0.04, baseColor, metallic).
// V is the pixel's own view vector (docs/conventions.md, defect SS16: the reference used the
// camera's forward vector for every pixel). The lit input must not already hold specular IBL
// for the same pixels.
//
// Integration: define these callbacks before or after including this header.
//
//   float3 GLINT_SSSR_LoadColor(int2 pixel);            lit colour
//   float3 GLINT_SSSR_LoadReflection(int2 pixel);       the reflection (raw or denoised)
//   float  GLINT_SSSR_LoadDepth(int2 pixel, int mip);   device depth (mip 0)
//   float3 GLINT_SSSR_LoadNormal(int2 pixel);           stored world-space normal (unpacked by the header)
//   float  GLINT_SSSR_LoadRoughness(int2 pixel);        GGX alpha (classification output)
//   float4 GLINT_SSSR_LoadBaseColorMetallic(int2 pixel);
//   float2 GLINT_SSSR_SampleBrdfLut(float2 uv);         bilinear, uv = (N.V, r), texel centres at (i + 0.5) / size
//   void   GLINT_SSSR_StoreComposite(int2 pixel, float4 color);
//
// Entry: from main, GLINT_SSSR_Composite(c, SV_DispatchThreadID.xy), c the GLINT_SssrConstants
// in a cbuffer (glint_sssr_common.hlsli; filled by host/src/core/sssr_passes.cpp).
// Dispatch: [numthreads(8, 8, 1)], ceil(W / 8) x ceil(H / 8) groups. Guide: docs/integration.md.
#ifndef GLINT_SSSR_COMPOSITE_HLSLI
#define GLINT_SSSR_COMPOSITE_HLSLI

#include "glint/sssr/glint_sssr_common.hlsli"

float3 GLINT_SSSR_LoadColor(int2 pixel);
float3 GLINT_SSSR_LoadReflection(int2 pixel);
float GLINT_SSSR_LoadDepth(int2 pixel, int mip);
float3 GLINT_SSSR_LoadNormal(int2 pixel);
float GLINT_SSSR_LoadRoughness(int2 pixel);
float4 GLINT_SSSR_LoadBaseColorMetallic(int2 pixel);
float2 GLINT_SSSR_SampleBrdfLut(float2 uv);
void GLINT_SSSR_StoreComposite(int2 pixel, float4 color);

void GLINT_SSSR_Composite(GLINT_SssrConstants c, uint2 pixel)
{
    if (any(pixel >= c.inputSize))
        return;
    int2 ipixel = int2(pixel);
    float3 color = GLINT_SSSR_SanitizeRadiance(GLINT_SSSR_LoadColor(ipixel));
    float depth = GLINT_SSSR_LoadDepth(ipixel, 0);
    float3 normal = GLINT_SSSR_UnpackNormal(c, GLINT_SSSR_LoadNormal(ipixel));
    if (!GLINT_SSSR_IsBackground(depth, GLINT_SSSR_Reversed(c)) && dot(normal, normal) > 0.0)
    {
        float2 uv = (float2(pixel) + 0.5) * c.inverseInputSize;
        float3 viewPosition = GLINT_SSSR_ViewPosition(c, uv, depth);
        float3 view = -normalize(GLINT_SSSR_MulDirection(c.worldFromView, viewPosition));
        float NdotV = GLINT_Saturate(dot(normal, view));
        float alpha = GLINT_Saturate(GLINT_FiniteOr(GLINT_SSSR_LoadRoughness(ipixel), 1.0));
        float2 dfg = GLINT_SSSR_SampleBrdfLut(float2(NdotV, GLINT_PerceptualRoughnessFromAlpha(alpha)));
        float4 material = GLINT_SSSR_LoadBaseColorMetallic(ipixel);
        float3 baseColor = GLINT_SSSR_SanitizeRadiance(material.xyz);
        float metallic = GLINT_Saturate(GLINT_FiniteOr(material.w, 0.0));
        float3 f0 = lerp(float3(0.04, 0.04, 0.04), baseColor, metallic);
        float3 reflection = GLINT_SSSR_SanitizeRadiance(GLINT_SSSR_LoadReflection(ipixel));
        color += reflection * (f0 * dfg.x + dfg.y);
    }
    GLINT_SSSR_StoreComposite(ipixel, float4(GLINT_SSSR_SanitizeRadiance(color), 1.0));
}

#endif // GLINT_SSSR_COMPOSITE_HLSLI
