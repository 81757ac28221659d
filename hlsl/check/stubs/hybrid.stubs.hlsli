// Stub definitions of the hybrid's callbacks that need no hit record (classification,
// intersection, shading's counters), for the hybrid header checks; the SSSR callbacks they
// also call are sssr.stubs.hlsli's. Include after glint_hybrid_common.hlsli (route values).
#ifndef GLINT_CHECK_HYBRID_STUBS_HLSLI
#define GLINT_CHECK_HYBRID_STUBS_HLSLI

#include "check/stubs/sssr.stubs.hlsli"

uint GLINT_HYBRID_LoadFeedbackHistory(int2 tile) { return g_glint_check_words[tile.x + 16]; }
void GLINT_HYBRID_StoreFeedback(int2 tile, uint counter) { g_glint_check_words[tile.y + 24] = counter; }
void GLINT_HYBRID_AddFeedback(int2 tile, uint value) { InterlockedAdd(g_glint_check_words[tile.x + 8], value); }
void GLINT_HYBRID_StoreTileClass(int2 tile, uint tileClass) { g_glint_check_words[tile.x + 32] = tileClass; }
uint GLINT_HYBRID_MaterialRoute(int2 pixel, float alpha)
{
    return alpha < 0.01 ? GLINT_HYBRID_ROUTE_RAY_TRACED : GLINT_HYBRID_ROUTE_AUTO;
}
uint GLINT_HYBRID_AddScreenSpaceRays(uint count) { return GLINT_CHECK_Add(0, count); }
void GLINT_HYBRID_StoreScreenSpaceRay(uint index, uint entry) { g_glint_check_words[index + 40] = entry; }
uint GLINT_HYBRID_AddRayTracedRays(uint count) { return GLINT_CHECK_Add(4, count); }
void GLINT_HYBRID_StoreRayTracedRay(uint index, uint entry) { g_glint_check_words[index + 48] = entry; }
uint GLINT_HYBRID_AddReshadedHits(uint count) { return GLINT_CHECK_Add(6, count); }
void GLINT_HYBRID_CountScreenSpaceAnswers(uint count) { InterlockedAdd(g_glint_check_words[7], count); }
uint GLINT_HYBRID_LoadRayTracedCount() { return g_glint_check_words[5]; }
uint GLINT_HYBRID_LoadRayTracedRay(uint index) { return g_glint_check_words[index + 8]; }
uint GLINT_HYBRID_LoadReshadedCount() { return g_glint_check_words[7]; }
void GLINT_HYBRID_StoreHit(uint index, uint4 record) { g_glint_check_words[index + 64] = record.x ^ record.y ^ record.z ^ record.w; }
uint4 GLINT_HYBRID_LoadHit(uint index) { return uint4(g_glint_check_words[index + 64], index, 0u, 1u); }
float3 GLINT_HYBRID_ShadeScreenHit(int2 hitPixel, float3 hitPosition, float3 origin, float3 direction)
{
    return g_glint_check[hitPixel.x + hitPixel.y].xyz + hitPosition * dot(origin, direction);
}

#endif // GLINT_CHECK_HYBRID_STUBS_HLSLI
