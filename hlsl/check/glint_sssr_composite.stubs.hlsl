// Stub callbacks for the header check of glint_sssr_composite.hlsli.
cbuffer g_glint_check_constants { GLINT_SssrConstants g_glint_sssr; };
RWStructuredBuffer<float4> g_glint_check;

float3 GLINT_SSSR_LoadColor(int2 pixel) { return g_glint_check[pixel.x].xyz; }
float3 GLINT_SSSR_LoadReflection(int2 pixel) { return g_glint_check[pixel.y].xyz; }
float GLINT_SSSR_LoadDepth(int2 pixel, int mip) { return g_glint_check[pixel.x + mip].w; }
float3 GLINT_SSSR_LoadNormal(int2 pixel) { return g_glint_check[pixel.x + 1].xyz; }
float GLINT_SSSR_LoadRoughness(int2 pixel) { return g_glint_check[pixel.y + 1].w; }
float4 GLINT_SSSR_LoadBaseColorMetallic(int2 pixel) { return g_glint_check[pixel.x + 2]; }
float2 GLINT_SSSR_SampleBrdfLut(float2 uv) { return uv; }
void GLINT_SSSR_StoreComposite(int2 pixel, float4 color) { g_glint_check[pixel.x] = color; }

[numthreads(8, 8, 1)] void main(uint3 dispatchId : SV_DispatchThreadID)
{
    GLINT_SSSR_Composite(g_glint_sssr, dispatchId.xy);
}
