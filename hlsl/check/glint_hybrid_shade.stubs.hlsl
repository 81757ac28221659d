// Stub callbacks for the header check of glint_hybrid_shade.hlsli.
cbuffer g_glint_check_constants { GLINT_SssrConstants g_glint_sssr; GLINT_HybridConstants g_glint_hybrid; };
RWStructuredBuffer<float4> g_glint_check;
RWStructuredBuffer<uint> g_glint_check_words;

float GLINT_SSSR_LoadDepth(int2 texel, int mip) { return g_glint_check[texel.x + mip].x; }
float3 GLINT_SSSR_LoadNormal(int2 pixel) { return g_glint_check[pixel.y].xyz; }
float GLINT_SSSR_LoadRoughness(int2 pixel) { return g_glint_check[pixel.x].y; }
float2 GLINT_SSSR_LoadBlueNoise(int2 pixel) { return g_glint_check[pixel.x & 127].zw; }
float3 GLINT_SSSR_SampleEnvironment(float3 direction, float lod) { return direction * lod; }
void GLINT_SSSR_StoreRadiance(int2 pixel, float4 value) { g_glint_check[pixel.x] = value; }
void GLINT_SSSR_StoreConfidence(int2 pixel, float confidence) { g_glint_check[pixel.y].w = confidence; }
uint GLINT_HYBRID_LoadRayTracedCount() { return g_glint_check_words[5]; }
uint GLINT_HYBRID_LoadRayTracedRay(uint index) { return g_glint_check_words[index + 8]; }
uint GLINT_HYBRID_LoadReshadedCount() { return g_glint_check_words[7]; }
uint4 GLINT_HYBRID_LoadHit(uint index) { return uint4(g_glint_check_words[index + 64], index, 0u, 1u); }
float3 GLINT_HYBRID_ShadeHit(GLINT_HYBRID_Hit hit, float3 origin, float3 direction)
{
    return origin * hit.t + direction * float(hit.primitive) + float3(hit.barycentrics, float(hit.instance));
}

float3 GLINT_HYBRID_ShadeScreenHit(int2 hitPixel, float3 hitPosition, float3 origin, float3 direction)
{
    return g_glint_check[hitPixel.x + hitPixel.y].xyz + hitPosition * dot(origin, direction);
}

[numthreads(64, 1, 1)] void main(uint3 groupId : SV_GroupID, uint groupIndex : SV_GroupIndex)
{
    GLINT_HYBRID_ShadeRays(g_glint_sssr, g_glint_hybrid, groupId.x * 64 + groupIndex);
}
