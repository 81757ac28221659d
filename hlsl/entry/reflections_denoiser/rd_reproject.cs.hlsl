// Entry for the reflections denoiser's reproject pass: bindings, callbacks, main
// (glint/reflections_denoiser/glint_reflections_denoiser_reproject.hlsli).
#include "entry/reflections_denoiser/rd_common.hlsli"
#include "glint/reflections_denoiser/glint_reflections_denoiser_reproject.hlsli"

GLINT_BINDING(5, 0) Texture2D<float4> g_glint_noisy;
GLINT_BINDING(6, 0) Texture2D<float2> g_glint_motion;
GLINT_BINDING(7, 0) StructuredBuffer<uint> g_glint_history_tile_mask;
GLINT_BINDING(8, 0) Texture2D<float4> g_glint_history_guides;
GLINT_BINDING(9, 0) Texture2D<float4> g_glint_history_radiance;
// The radiance history carries the final variance in alpha (the resolve writes both), so that
// a history tap is one fetch fewer.
GLINT_BINDING(10, 0) Texture2D<float> g_glint_history_length;
GLINT_BINDING(11, 0) GLINT_FLOAT4_STORAGE(GLINT_RD_HALF_STORAGE) g_glint_clamped;
GLINT_BINDING(12, 0) GLINT_FLOAT4_STORAGE(GLINT_RD_HALF_STORAGE) g_glint_reprojected;
GLINT_BINDING(13, 0) GLINT_FLOAT_STORAGE(GLINT_RD_HALF_STORAGE) g_glint_variance;
GLINT_BINDING(14, 0) GLINT_FLOAT_STORAGE(GLINT_RD_HALF_STORAGE) g_glint_length;
GLINT_BINDING(15, 0) GLINT_IMAGE_FORMAT(rgba32f) RWTexture2D<float4> g_glint_guides;
GLINT_BINDING(16, 0) GLINT_IMAGE_FORMAT(rgba32f) RWTexture2D<float4> g_glint_average;
GLINT_BINDING(17, 0) RWStructuredBuffer<uint> g_glint_tile_mask;

float4 GLINT_RD_LoadNoisy(int2 pixel) { return g_glint_noisy.Load(int3(pixel, 0)); }
float2 GLINT_RD_LoadMotion(int2 pixel) { return g_glint_motion.Load(int3(pixel, 0)); }
uint GLINT_RD_LoadHistoryTileMask(uint2 tile) { return g_glint_history_tile_mask[tile.y * g_glint_rd.tiles.x + tile.x]; }
float4 GLINT_RD_LoadHistoryGuides(int2 pixel) { return g_glint_history_guides.Load(int3(pixel, 0)); }
float4 GLINT_RD_LoadHistoryRadianceAndVariance(int2 pixel) { return g_glint_history_radiance.Load(int3(pixel, 0)); }
float GLINT_RD_LoadHistoryLength(int2 pixel) { return g_glint_history_length.Load(int3(pixel, 0)); }
void GLINT_RD_StoreClamped(int2 pixel, float4 value) { g_glint_clamped[pixel] = value; }
void GLINT_RD_StoreReprojected(int2 pixel, float4 value) { g_glint_reprojected[pixel] = value; }
void GLINT_RD_StoreVariance(int2 pixel, float value) { g_glint_variance[pixel] = value; }
void GLINT_RD_StoreHistoryLength(int2 pixel, float value) { g_glint_length[pixel] = value; }
void GLINT_RD_StoreGuides(int2 pixel, float4 value) { g_glint_guides[pixel] = value; }
void GLINT_RD_StoreAverage(uint2 tile, float4 value) { g_glint_average[tile] = value; }
void GLINT_RD_MarkTile(uint2 tile, uint bits)
{
    InterlockedOr(g_glint_tile_mask[tile.y * g_glint_rd.tiles.x + tile.x], bits);
}

[numthreads(8, 8, 1)] void main(uint3 groupId : SV_GroupID, uint3 groupThreadId : SV_GroupThreadID)
{
    GLINT_RD_Reproject(g_glint_rd, groupId.x, groupThreadId.xy);
}
