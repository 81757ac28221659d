// Stub definitions of every shadow-denoiser callback (prepare, classification, filter, the
// tile-list permutations' included), for its header checks: one definition each.
#ifndef GLINT_CHECK_SHADOW_DENOISER_STUBS_HLSLI
#define GLINT_CHECK_SHADOW_DENOISER_STUBS_HLSLI

#include "check/stubs/check_buffers.hlsli"

float GLINT_SHADOW_DENOISER_LoadVisibility(int2 pixel) { return g_glint_check[pixel.x + pixel.y].x; }
void GLINT_SHADOW_DENOISER_StoreMask(uint tileIndex, uint mask) { g_glint_check_words[tileIndex] = mask; }
void GLINT_SHADOW_DENOISER_ResetFilterTiles() { g_glint_check_words[0] = 0; }
uint GLINT_SHADOW_DENOISER_LoadMask(int2 tile) { return g_glint_check_words[tile.x + tile.y]; }
float GLINT_SHADOW_DENOISER_LoadDepth(int2 pixel) { return g_glint_check[pixel.x].y; }
float GLINT_SHADOW_DENOISER_LoadPreviousDepth(int2 pixel) { return g_glint_check[pixel.y].z; }
float3 GLINT_SHADOW_DENOISER_LoadNormal(int2 pixel) { return g_glint_check[pixel.x + 1].xyz; }
float2 GLINT_SHADOW_DENOISER_LoadMotion(int2 pixel) { return g_glint_check[pixel.y + 2].xy; }
float3 GLINT_SHADOW_DENOISER_LoadMomentsHistory(int2 pixel) { return g_glint_check[pixel.x + 3].xyz; }
float GLINT_SHADOW_DENOISER_LoadShadowHistory(int2 pixel) { return g_glint_check[pixel.y + 4].w; }
uint GLINT_SHADOW_DENOISER_LoadPreviousMetadata(uint tileIndex) { return g_glint_check_words[tileIndex + 5]; }
float GLINT_SHADOW_DENOISER_LoadBlockerDistance(int2 pixel) { return g_glint_check[pixel.x + 6].w; }
float2 GLINT_SHADOW_DENOISER_LoadMeanVariance(int2 pixel) { return g_glint_check[pixel.x].xy; }
uint2 GLINT_SHADOW_DENOISER_LoadFilterTile(uint listIndex) { return uint2(g_glint_check_words[listIndex + 8], listIndex); }
uint GLINT_SHADOW_DENOISER_LoadTileMetadata(uint tileIndex) { return g_glint_check_words[tileIndex + 9]; }
void GLINT_SHADOW_DENOISER_CountFilteredTile() { InterlockedAdd(g_glint_check_words[1], 1u); }
void GLINT_SHADOW_DENOISER_AppendFilterTile(uint2 tile) { g_glint_check_words[GLINT_CHECK_Add(2, 1u) + 16] = tile.x; }
void GLINT_SHADOW_DENOISER_StoreMetadata(uint tileIndex, uint metadata) { g_glint_check_words[tileIndex] = metadata; }
void GLINT_SHADOW_DENOISER_StoreShadowVariance(int2 pixel, float2 value) { g_glint_check[pixel.x].xy = value; }
void GLINT_SHADOW_DENOISER_StoreMoments(int2 pixel, float4 moments) { g_glint_check[pixel.y] = moments; }
void GLINT_SHADOW_DENOISER_StoreClearOutput(int2 pixel, float2 value) { g_glint_check[pixel.x + 7].xy = value; }
void GLINT_SHADOW_DENOISER_StoreFiltered(int2 pixel, float2 meanVariance) { g_glint_check[pixel.x].zw = meanVariance; }

#endif // GLINT_CHECK_SHADOW_DENOISER_STUBS_HLSLI
