// Header check of glint_reflections_denoiser_reproject.hlsli: its callbacks are the shared stubs in
// check/stubs/reflections_denoiser.stubs.hlsli (each defined once for every check).
#include "check/stubs/reflections_denoiser.stubs.hlsli"

cbuffer g_glint_check_constants { GLINT_ReflectionsDenoiserConstants g_glint_rd; };

[numthreads(8, 8, 1)] void main(uint3 groupId : SV_GroupID, uint3 groupThreadId : SV_GroupThreadID)
{
    GLINT_RD_Reproject(g_glint_rd, groupId.x, groupThreadId.xy);
}
