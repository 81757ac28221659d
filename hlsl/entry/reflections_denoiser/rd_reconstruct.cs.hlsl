// Entry for the reflections denoiser's ratio-estimator reconstruction
// (glint/reflections_denoiser/glint_reflections_denoiser_reconstruct.hlsli).
#include "entry/reflections_denoiser/rd_ratio_common.hlsli"
#include "glint/reflections_denoiser/glint_reflections_denoiser_reconstruct.hlsli"

GLINT_BINDING(5, 0) Texture2D<float4> g_glint_clamped;
GLINT_BINDING(6, 0) Texture2D<float4> g_glint_rays;
GLINT_BINDING(7, 0) Texture2D<float> g_glint_variance;
GLINT_BINDING(8, 0) GLINT_FLOAT4_STORAGE(GLINT_RD_HALF_STORAGE) g_glint_reconstructed;

float4 GLINT_RD_LoadClamped(int2 pixel) { return g_glint_clamped.Load(int3(pixel, 0)); }
float4 GLINT_RD_LoadRay(int2 pixel) { return g_glint_rays.Load(int3(pixel, 0)); }
float GLINT_RD_LoadVariance(int2 pixel) { return g_glint_variance.Load(int3(pixel, 0)); }
void GLINT_RD_StoreReconstructed(int2 pixel, float4 value) { g_glint_reconstructed[pixel] = value; }

[numthreads(8, 8, 1)] void main(uint3 groupId : SV_GroupID, uint3 groupThreadId : SV_GroupThreadID)
{
    GLINT_RD_Reconstruct(g_glint_rd_ratio, groupId.x, groupThreadId.xy);
}
