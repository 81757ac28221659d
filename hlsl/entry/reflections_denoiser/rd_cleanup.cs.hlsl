// Entry for the reflections denoiser's bilateral cleanup (ratio-estimator path,
// glint/reflections_denoiser/glint_reflections_denoiser_cleanup.hlsli).
#include "entry/reflections_denoiser/rd_ratio_common.hlsli"
#include "glint/reflections_denoiser/glint_reflections_denoiser_cleanup.hlsli"

GLINT_BINDING(5, 0) Texture2D<float4> g_glint_resolved;
GLINT_BINDING(6, 0) Texture2D<float> g_glint_variance;
GLINT_BINDING(7, 0) GLINT_FLOAT4_STORAGE(GLINT_RD_HALF_STORAGE) g_glint_output;

float3 GLINT_RD_LoadResolved(int2 pixel) { return g_glint_resolved.Load(int3(pixel, 0)).rgb; }
float GLINT_RD_LoadVariance(int2 pixel) { return g_glint_variance.Load(int3(pixel, 0)); }
float4 GLINT_RD_LoadOutput(int2 pixel) { return g_glint_output[pixel]; }
void GLINT_RD_StoreOutput(int2 pixel, float4 value) { g_glint_output[pixel] = value; }

[numthreads(8, 8, 1)] void main(uint3 groupId : SV_GroupID, uint3 groupThreadId : SV_GroupThreadID)
{
    GLINT_RD_Cleanup(g_glint_rd_ratio, groupId.x, groupThreadId.xy);
}
