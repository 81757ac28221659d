// Stub callbacks for the header check of glint_gbuffer_roughness.hlsli: the header must
// compile with nothing but its own includes and these definitions.
RWStructuredBuffer<float4> g_glint_check;

float4 GLINT_GBUFFER_LoadMaterial(int2 pixel)
{
    return g_glint_check[pixel.x];
}

void GLINT_GBUFFER_StoreAlpha(int2 pixel, float alpha)
{
    g_glint_check[pixel.y] = alpha.xxxx;
}

[numthreads(8, 8, 1)] void main(uint3 id : SV_DispatchThreadID)
{
    GLINT_GBUFFER_ExtractRoughness(id.xy, uint2(8, 8), 1, true);
}
