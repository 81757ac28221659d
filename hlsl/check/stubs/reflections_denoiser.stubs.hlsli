// Stub definitions of every reflections-denoiser callback (the common ones and each pass's),
// for its header checks: one definition each.
#ifndef GLINT_CHECK_REFLECTIONS_DENOISER_STUBS_HLSLI
#define GLINT_CHECK_REFLECTIONS_DENOISER_STUBS_HLSLI

#include "check/stubs/check_buffers.hlsli"

uint GLINT_RD_LoadTile(uint index) { return asuint(g_glint_check[index].x); }
float GLINT_RD_LoadDepth(int2 pixel) { return g_glint_check[pixel.x].y; }
float3 GLINT_RD_LoadNormal(int2 pixel) { return g_glint_check[pixel.y].xyz; }
float GLINT_RD_LoadRoughness(int2 pixel) { return g_glint_check[pixel.x].w; }
float4 GLINT_RD_LoadAverage(uint2 tile) { return g_glint_check[tile.x + 7]; }
bool GLINT_RD_TileListed(uint2 tile) { return g_glint_check[tile.y].z > 0.0; }
float4 GLINT_RD_LoadNoisy(int2 pixel) { return g_glint_check[pixel.x + 1]; }
float2 GLINT_RD_LoadMotion(int2 pixel) { return g_glint_check[pixel.y + 1].xy; }
uint GLINT_RD_LoadHistoryTileMask(uint2 tile) { return asuint(g_glint_check[tile.x].x); }
float4 GLINT_RD_LoadHistoryGuides(int2 pixel) { return g_glint_check[pixel.x + 2]; }
float4 GLINT_RD_LoadHistoryRadianceAndVariance(int2 pixel) { return g_glint_check[pixel.x + 3]; }
float GLINT_RD_LoadHistoryLength(int2 pixel) { return g_glint_check[pixel.x + 5].x; }
float4 GLINT_RD_LoadClamped(int2 pixel) { return g_glint_check[pixel.x + 1]; }
float GLINT_RD_LoadVariance(int2 pixel) { return g_glint_check[pixel.y + 1].x; }
float4 GLINT_RD_LoadPrefiltered(int2 pixel) { return g_glint_check[pixel.x + 1]; }
float4 GLINT_RD_LoadReprojected(int2 pixel) { return g_glint_check[pixel.y + 1]; }
float GLINT_RD_LoadLength(int2 pixel) { return g_glint_check[pixel.x + 2].x; }
float4 GLINT_RD_LoadRay(int2 pixel) { return g_glint_check[pixel.y + 3]; }
float3 GLINT_RD_LoadResolved(int2 pixel) { return g_glint_check[pixel.x + 2].xyz; }
float4 GLINT_RD_LoadOutput(int2 pixel) { return g_glint_check[pixel.x + pixel.y]; }
void GLINT_RD_StoreClamped(int2 pixel, float4 value) { g_glint_check[pixel.x] = value; }
void GLINT_RD_StoreReprojected(int2 pixel, float4 value) { g_glint_check[pixel.y] = value; }
void GLINT_RD_StoreVariance(int2 pixel, float value) { g_glint_check[pixel.x].x = value; }
void GLINT_RD_StoreHistoryLength(int2 pixel, float value) { g_glint_check[pixel.x].y = value; }
void GLINT_RD_StoreGuides(int2 pixel, float4 value) { g_glint_check[pixel.x + 6] = value; }
void GLINT_RD_StoreAverage(uint2 tile, float4 value) { g_glint_check[tile.x] = value; }
void GLINT_RD_MarkTile(uint2 tile, uint bits) { InterlockedOr(g_glint_check_words[tile.y], bits); }
void GLINT_RD_StorePrefiltered(int2 pixel, float4 value) { g_glint_check[pixel.x] = value; }
void GLINT_RD_StoreLength(int2 pixel, float value) { g_glint_check[pixel.x + 2].x = value; }
void GLINT_RD_StoreOutput(int2 pixel, float4 value) { g_glint_check[pixel.x] = value; }
void GLINT_RD_StoreRadianceHistory(int2 pixel, float4 value) { g_glint_check[pixel.y] = value; }
void GLINT_RD_StoreReconstructed(int2 pixel, float4 value) { g_glint_check[pixel.x] = value; }

#endif // GLINT_CHECK_REFLECTIONS_DENOISER_STUBS_HLSLI
