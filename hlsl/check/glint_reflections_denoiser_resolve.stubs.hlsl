// Stub callbacks for the header check of glint_reflections_denoiser_resolve.hlsli.
cbuffer g_glint_check_constants { GLINT_ReflectionsDenoiserConstants g_glint_rd; };
RWStructuredBuffer<float4> g_glint_check;
uint GLINT_RD_LoadTile(uint index) { return asuint(g_glint_check[index].x); }
float GLINT_RD_LoadDepth(int2 pixel) { return g_glint_check[pixel.x].y; }
float3 GLINT_RD_LoadNormal(int2 pixel) { return g_glint_check[pixel.y].xyz; }
float GLINT_RD_LoadRoughness(int2 pixel) { return g_glint_check[pixel.x].w; }
float4 GLINT_RD_LoadAverage(uint2 tile) { return g_glint_check[tile.x + 7]; }
bool GLINT_RD_TileListed(uint2 tile) { return g_glint_check[tile.y].z > 0.0; }
float4 GLINT_RD_LoadPrefiltered(int2 pixel) { return g_glint_check[pixel.x + 1]; }
float4 GLINT_RD_LoadReprojected(int2 pixel) { return g_glint_check[pixel.y + 1]; }
float GLINT_RD_LoadLength(int2 pixel) { return g_glint_check[pixel.x + 2].x; }
void GLINT_RD_StoreLength(int2 pixel, float value) { g_glint_check[pixel.x + 2].x = value; }
float4 GLINT_RD_LoadNoisy(int2 pixel) { return g_glint_check[pixel.x + 3]; }
void GLINT_RD_StoreOutput(int2 pixel, float4 value) { g_glint_check[pixel.x] = value; }
void GLINT_RD_StoreRadianceHistory(int2 pixel, float4 value) { g_glint_check[pixel.y] = value; }
void GLINT_RD_StoreVariance(int2 pixel, float value) { g_glint_check[pixel.x].w = value; }

[numthreads(8, 8, 1)] void main(uint3 groupId : SV_GroupID, uint3 groupThreadId : SV_GroupThreadID)
{
    GLINT_RD_Resolve(g_glint_rd, groupId.x, groupThreadId.xy);
}
