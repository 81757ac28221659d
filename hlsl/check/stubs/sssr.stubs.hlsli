// Stub definitions of every SSSR callback (classification, compaction, blue noise, indirect arguments,
// intersection, composite), for the SSSR and hybrid header checks. One definition each:
// a callback several headers declare is defined here once.
#ifndef GLINT_CHECK_SSSR_STUBS_HLSLI
#define GLINT_CHECK_SSSR_STUBS_HLSLI

#include "check/stubs/check_buffers.hlsli"

float GLINT_SSSR_LoadDepth(int2 texel, int mip) { return g_glint_check[texel.x + mip].x; }
float GLINT_SSSR_LoadFarthestDepth(int2 texel, int mip) { return g_glint_check[texel.y + mip].x; }
float3 GLINT_SSSR_LoadNormal(int2 pixel) { return g_glint_check[pixel.y].xyz; }
float GLINT_SSSR_LoadRoughness(int2 pixel) { return g_glint_check[pixel.x].y; }
float4 GLINT_SSSR_LoadMaterial(int2 pixel) { return g_glint_check[pixel.x * 2]; }
float2 GLINT_SSSR_LoadMotion(int2 pixel) { return g_glint_check[pixel.y + 2].xy; }
float GLINT_SSSR_SampleVarianceHistory(float2 uv) { return g_glint_check[uint(uv.x * 8.0)].w; }
float3 GLINT_SSSR_SampleEnvironment(float3 direction, float lod) { return direction * lod; }
float2 GLINT_SSSR_LoadBlueNoise(int2 pixel) { return g_glint_check[pixel.x & 127].zw; }
float2 GLINT_SSSR_LoadBlueNoiseSource(int2 texel) { return g_glint_check[texel.x * 128 + texel.y].xy; }
float3 GLINT_SSSR_LoadColor(int2 pixel) { return g_glint_check[pixel.x + pixel.y].xyz; }
float3 GLINT_SSSR_SampleColor(float2 uv) { return g_glint_check[uint(uv.x * 4.0)].xyz; }
float3 GLINT_SSSR_LoadReflection(int2 pixel) { return g_glint_check[pixel.y + 3].xyz; }
float4 GLINT_SSSR_LoadBaseColorMetallic(int2 pixel) { return g_glint_check[pixel.x + 2]; }
float2 GLINT_SSSR_SampleBrdfLut(float2 uv) { return uv; }
uint GLINT_SSSR_LoadCounter(uint index) { return g_glint_check_words[index]; }
uint GLINT_SSSR_LoadRayCount() { return g_glint_check_words[1]; }
uint GLINT_SSSR_LoadRay(uint index) { return g_glint_check_words[index + 4]; }
uint GLINT_SSSR_AddRays(uint count) { return GLINT_CHECK_Add(0, count); }
uint GLINT_SSSR_AddTile() { return GLINT_CHECK_Add(2, 1u); }
void GLINT_SSSR_StoreRay(uint index, uint entry) { g_glint_check_words[index + 4] = entry; }
uint GLINT_SSSR_LoadRayScratch(uint word) { return g_glint_check_words[word + 16]; }
void GLINT_SSSR_StoreRayScratch(uint word, uint value) { g_glint_check_words[word + 16] = value; }
uint GLINT_SSSR_AddRayScratch(uint word, uint value) { return GLINT_CHECK_Add(word + 16, value); }
void GLINT_SSSR_StoreRay(int2 pixel, float4 directionAndPdf) { g_glint_check[pixel.x + 4] = directionAndPdf; }
void GLINT_SSSR_StoreTile(uint index, uint entry) { g_glint_check_words[index + 8] = entry; }
void GLINT_SSSR_StoreCounter(uint index, uint value) { g_glint_check_words[index] = value; }
void GLINT_SSSR_StoreArgument(uint index, uint value) { g_glint_check_words[index + 12] = value; }
void GLINT_SSSR_StoreBlueNoise(int2 texel, float2 sample) { g_glint_check[texel.y * 128 + texel.x].xy = sample; }
void GLINT_SSSR_StoreRoughness(int2 pixel, float alpha) { g_glint_check[pixel.x].x = alpha; }
void GLINT_SSSR_StoreRadiance(int2 pixel, float4 value) { g_glint_check[pixel.x] = value; }
void GLINT_SSSR_StoreConfidence(int2 pixel, float confidence) { g_glint_check[pixel.y].w = confidence; }
void GLINT_SSSR_StoreRayInfo(int2 pixel, float4 info) { g_glint_check[pixel.y + 5] = info; }
void GLINT_SSSR_StoreComposite(int2 pixel, float4 color) { g_glint_check[pixel.x + 6] = color; }

#endif // GLINT_CHECK_SSSR_STUBS_HLSLI
