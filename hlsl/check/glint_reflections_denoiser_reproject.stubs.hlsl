// Stub callbacks for the header check of glint_reflections_denoiser_reproject.hlsli.
cbuffer g_glint_check_constants { GLINT_ReflectionsDenoiserConstants g_glint_rd; };
RWStructuredBuffer<float4> g_glint_check;
uint GLINT_RD_LoadTile(uint index) { return asuint(g_glint_check[index].x); }
float GLINT_RD_LoadDepth(int2 pixel) { return g_glint_check[pixel.x].y; }
float3 GLINT_RD_LoadNormal(int2 pixel) { return g_glint_check[pixel.y].xyz; }
float GLINT_RD_LoadRoughness(int2 pixel) { return g_glint_check[pixel.x].w; }
float4 GLINT_RD_LoadNoisy(int2 pixel) { return g_glint_check[pixel.x + 1]; }
float2 GLINT_RD_LoadMotion(int2 pixel) { return g_glint_check[pixel.y + 1].xy; }
uint GLINT_RD_LoadHistoryTileMask(uint2 tile) { return asuint(g_glint_check[tile.x].x); }
float4 GLINT_RD_LoadHistoryGuides(int2 pixel) { return g_glint_check[pixel.x + 2]; }
float4 GLINT_RD_LoadHistoryRadianceAndVariance(int2 pixel) { return g_glint_check[pixel.x + 3]; }
float GLINT_RD_LoadHistoryLength(int2 pixel) { return g_glint_check[pixel.x + 5].x; }
void GLINT_RD_StoreClamped(int2 pixel, float4 value) { g_glint_check[pixel.x] = value; }
void GLINT_RD_StoreReprojected(int2 pixel, float4 value) { g_glint_check[pixel.y] = value; }
void GLINT_RD_StoreVariance(int2 pixel, float value) { g_glint_check[pixel.x].x = value; }
void GLINT_RD_StoreHistoryLength(int2 pixel, float value) { g_glint_check[pixel.x].y = value; }
void GLINT_RD_StoreGuides(int2 pixel, float4 value) { g_glint_check[pixel.x + 6] = value; }
void GLINT_RD_StoreAverage(uint2 tile, float4 value) { g_glint_check[tile.x] = value; }
void GLINT_RD_MarkTile(uint2 tile, uint bits) { g_glint_check[tile.y].w = asfloat(bits); }

[numthreads(8, 8, 1)] void main(uint3 groupId : SV_GroupID, uint3 groupThreadId : SV_GroupThreadID)
{
    GLINT_RD_Reproject(g_glint_rd, groupId.x, groupThreadId.xy);
}
