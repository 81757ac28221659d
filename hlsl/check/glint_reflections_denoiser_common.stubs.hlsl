// Stub callbacks for the header check of glint_reflections_denoiser_common.hlsli.
RWStructuredBuffer<float4> g_glint_check;
uint GLINT_RD_LoadTile(uint index) { return asuint(g_glint_check[index].x); }
float GLINT_RD_LoadDepth(int2 pixel) { return g_glint_check[pixel.x].y; }
float3 GLINT_RD_LoadNormal(int2 pixel) { return g_glint_check[pixel.y].xyz; }
float GLINT_RD_LoadRoughness(int2 pixel) { return g_glint_check[pixel.x].w; }
