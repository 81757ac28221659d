// Stub callbacks for the header check of glint_hybrid_classify.hlsli.
cbuffer g_glint_check_constants { GLINT_SssrConstants g_glint_sssr; GLINT_HybridConstants g_glint_hybrid; };
RWStructuredBuffer<float4> g_glint_check;
RWStructuredBuffer<uint> g_glint_check_words;

float GLINT_SSSR_LoadDepth(int2 pixel, int mip) { return g_glint_check[pixel.x + mip].x; }
float3 GLINT_SSSR_LoadNormal(int2 pixel) { return g_glint_check[pixel.y].xyz; }
float4 GLINT_SSSR_LoadMaterial(int2 pixel) { return g_glint_check[pixel.x * 2]; }
float2 GLINT_SSSR_LoadMotion(int2 pixel) { return g_glint_check[pixel.x + 1].zw; }
float GLINT_SSSR_SampleVarianceHistory(float2 uv) { return g_glint_check[uint(uv.x * 8.0)].w; }
float3 GLINT_SSSR_SampleEnvironment(float3 direction, float lod) { return direction * lod; }
void GLINT_SSSR_StoreRoughness(int2 pixel, float alpha) { g_glint_check[pixel.x].x = alpha; }
void GLINT_SSSR_StoreRadiance(int2 pixel, float4 value) { g_glint_check[pixel.y] = value; }
void GLINT_SSSR_StoreConfidence(int2 pixel, float confidence) { g_glint_check[pixel.x].w = confidence; }
uint GLINT_SSSR_AddTile()
{
    uint previous;
    InterlockedAdd(g_glint_check_words[2], 1u, previous);
    return previous;
}
void GLINT_SSSR_StoreTile(uint index, uint entry) { g_glint_check_words[index + 8] = entry; }
uint GLINT_HYBRID_LoadFeedbackHistory(int2 tile) { return g_glint_check_words[tile.x + 16]; }
void GLINT_HYBRID_StoreFeedback(int2 tile, uint counter) { g_glint_check_words[tile.y + 24] = counter; }
void GLINT_HYBRID_StoreTileClass(int2 tile, uint tileClass) { g_glint_check_words[tile.x + 32] = tileClass; }
uint GLINT_HYBRID_MaterialRoute(int2 pixel, float alpha) { return alpha < 0.01 ? GLINT_HYBRID_ROUTE_RAY_TRACED : GLINT_HYBRID_ROUTE_AUTO; }
uint GLINT_HYBRID_AddScreenSpaceRays(uint count)
{
    uint previous;
    InterlockedAdd(g_glint_check_words[0], count, previous);
    return previous;
}
void GLINT_HYBRID_StoreScreenSpaceRay(uint index, uint entry) { g_glint_check_words[index + 40] = entry; }
uint GLINT_HYBRID_AddRayTracedRays(uint count)
{
    uint previous;
    InterlockedAdd(g_glint_check_words[4], count, previous);
    return previous;
}
void GLINT_HYBRID_StoreRayTracedRay(uint index, uint entry) { g_glint_check_words[index + 48] = entry; }

[numthreads(8, 8, 1)] void main(uint3 groupId : SV_GroupID, uint3 groupThreadId : SV_GroupThreadID)
{
    GLINT_HYBRID_Classify(g_glint_sssr, g_glint_hybrid, groupId.xy, groupThreadId.xy);
}
