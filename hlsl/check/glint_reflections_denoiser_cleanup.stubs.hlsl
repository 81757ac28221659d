// Stub callbacks for the header check of glint_reflections_denoiser_cleanup.hlsli.
cbuffer g_glint_check_constants { GLINT_ReflectionsDenoiserRatioConstants g_glint_rd_ratio; };
RWStructuredBuffer<float4> g_glint_check;
uint GLINT_RD_LoadTile(uint index) { return asuint(g_glint_check[index].x); }
float GLINT_RD_LoadDepth(int2 pixel) { return g_glint_check[pixel.x].y; }
float3 GLINT_RD_LoadNormal(int2 pixel) { return g_glint_check[pixel.y].xyz; }
float GLINT_RD_LoadRoughness(int2 pixel) { return g_glint_check[pixel.x].w; }
float3 GLINT_RD_LoadResolved(int2 pixel) { return g_glint_check[pixel.x + 2].xyz; }
float GLINT_RD_LoadVariance(int2 pixel) { return g_glint_check[pixel.y + 1].x; }
float4 GLINT_RD_LoadOutput(int2 pixel) { return g_glint_check[pixel.x + pixel.y]; }
void GLINT_RD_StoreOutput(int2 pixel, float4 value) { g_glint_check[pixel.x] = value; }

[numthreads(8, 8, 1)] void main(uint3 groupId : SV_GroupID, uint3 groupThreadId : SV_GroupThreadID)
{
    GLINT_RD_Cleanup(g_glint_rd_ratio, groupId.x, groupThreadId.xy);
}
