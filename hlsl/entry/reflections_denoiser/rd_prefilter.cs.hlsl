// Entry for the reflections denoiser's prefilter pass
// (glint/reflections_denoiser/glint_reflections_denoiser_prefilter.hlsli).
#include "entry/reflections_denoiser/rd_common.hlsli"
#include "entry/reflections_denoiser/rd_average.hlsli"
#include "glint/reflections_denoiser/glint_reflections_denoiser_prefilter.hlsli"

// The clamped sample carries the temporal variance in alpha (reproject writes both), so the
// prefilter needs no variance image.
GLINT_BINDING(7, 0) Texture2D<float4> g_glint_clamped;
GLINT_BINDING(8, 0) GLINT_FLOAT4_STORAGE(GLINT_RD_HALF_STORAGE) g_glint_prefiltered;

float4 GLINT_RD_LoadClamped(int2 pixel) { return g_glint_clamped.Load(int3(pixel, 0)); }
void GLINT_RD_StorePrefiltered(int2 pixel, float4 value) { g_glint_prefiltered[pixel] = value; }

[numthreads(8, 8, 1)] void main(uint3 groupId : SV_GroupID, uint3 groupThreadId : SV_GroupThreadID)
{
    GLINT_RD_Prefilter(g_glint_rd, groupId.x, groupThreadId.xy);
}
