// Stub callbacks for the header check of glint_hybrid_intersect.hlsli.
cbuffer g_glint_check_constants { GLINT_SssrConstants g_glint_sssr; GLINT_HybridConstants g_glint_hybrid; };
RWStructuredBuffer<float4> g_glint_check;
RWStructuredBuffer<uint> g_glint_check_words;

float GLINT_SSSR_LoadDepth(int2 texel, int mip) { return g_glint_check[texel.x + mip].x; }
float3 GLINT_SSSR_LoadNormal(int2 pixel) { return g_glint_check[pixel.y].xyz; }
float GLINT_SSSR_LoadRoughness(int2 pixel) { return g_glint_check[pixel.x].y; }
float2 GLINT_SSSR_LoadBlueNoise(int2 pixel) { return g_glint_check[pixel.x & 127].zw; }
float3 GLINT_SSSR_LoadColor(int2 pixel) { return g_glint_check[pixel.x + pixel.y].xyz; }
float3 GLINT_SSSR_SampleColor(float2 uv) { return g_glint_check[uint(uv.x * 4.0)].xyz; }
float2 GLINT_SSSR_LoadMotion(int2 pixel) { return g_glint_check[pixel.y + 2].xy; }
float3 GLINT_SSSR_SampleEnvironment(float3 direction, float lod) { return direction * lod; }
uint GLINT_SSSR_LoadRayCount() { return g_glint_check_words[1]; }
uint GLINT_SSSR_LoadRay(uint index) { return g_glint_check_words[index + 4]; }
void GLINT_SSSR_StoreRadiance(int2 pixel, float4 value) { g_glint_check[pixel.x] = value; }
void GLINT_SSSR_StoreConfidence(int2 pixel, float confidence) { g_glint_check[pixel.y].w = confidence; }

uint GLINT_HYBRID_AddRayTracedRays(uint count)
{
    uint previous;
    InterlockedAdd(g_glint_check_words[4], count, previous);
    return previous;
}
uint GLINT_HYBRID_AddReshadedHits(uint count)
{
    uint previous;
    InterlockedAdd(g_glint_check_words[6], count, previous);
    return previous;
}
void GLINT_HYBRID_CountScreenSpaceAnswers(uint count) { InterlockedAdd(g_glint_check_words[7], count); }
void GLINT_HYBRID_StoreRayTracedRay(uint index, uint entry) { g_glint_check_words[index + 64] = entry; }
void GLINT_HYBRID_StoreHit(uint index, uint4 record) { g_glint_check[index + 32] = asfloat(record); }
void GLINT_HYBRID_AddFeedback(int2 tile, uint value) { InterlockedAdd(g_glint_check_words[tile.x + 8], value); }

[numthreads(64, 1, 1)] void main(uint3 groupId : SV_GroupID, uint groupIndex : SV_GroupIndex)
{
    GLINT_HYBRID_IntersectScreenSpace(g_glint_sssr, g_glint_hybrid, groupIndex, groupId.x * 64 + groupIndex);
}
