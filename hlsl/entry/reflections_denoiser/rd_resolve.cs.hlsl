// Entry for the reflections denoiser's temporal resolve
// (glint/reflections_denoiser/glint_reflections_denoiser_resolve.hlsli).
#include "entry/reflections_denoiser/rd_common.hlsli"
#include "entry/reflections_denoiser/rd_average.hlsli"
#include "glint/reflections_denoiser/glint_reflections_denoiser_resolve.hlsli"

GLINT_BINDING(7, 0) Texture2D<float4> g_glint_prefiltered;
GLINT_BINDING(8, 0) Texture2D<float4> g_glint_reprojected;
// Read, and written back after the anti-lag.
GLINT_BINDING(9, 0) GLINT_FLOAT_STORAGE(GLINT_RD_HALF_STORAGE) g_glint_length;
GLINT_BINDING(10, 0) GLINT_FLOAT4_STORAGE(GLINT_RD_HALF_STORAGE) g_glint_output;
GLINT_BINDING(11, 0) GLINT_FLOAT4_STORAGE(GLINT_RD_HALF_STORAGE) g_glint_radiance_history;
GLINT_BINDING(12, 0) GLINT_FLOAT_STORAGE(GLINT_RD_HALF_STORAGE) g_glint_variance;

float4 GLINT_RD_LoadPrefiltered(int2 pixel) { return g_glint_prefiltered.Load(int3(pixel, 0)); }
float4 GLINT_RD_LoadReprojected(int2 pixel) { return g_glint_reprojected.Load(int3(pixel, 0)); }
float GLINT_RD_LoadLength(int2 pixel) { return g_glint_length[pixel]; }
void GLINT_RD_StoreLength(int2 pixel, float value) { g_glint_length[pixel] = value; }
float4 GLINT_RD_LoadNoisy(int2 pixel) { return g_glint_output[pixel]; }
void GLINT_RD_StoreOutput(int2 pixel, float4 value) { g_glint_output[pixel] = value; }
void GLINT_RD_StoreRadianceHistory(int2 pixel, float4 value) { g_glint_radiance_history[pixel] = value; }
void GLINT_RD_StoreVariance(int2 pixel, float value) { g_glint_variance[pixel] = value; }

[numthreads(8, 8, 1)] void main(uint3 groupId : SV_GroupID, uint3 groupThreadId : SV_GroupThreadID)
{
    GLINT_RD_Resolve(g_glint_rd, groupId.x, groupThreadId.xy);
}
