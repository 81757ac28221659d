// Header check of glint_shadow_denoiser_prepare.hlsli: its callbacks are the shared stubs in
// check/stubs/shadow_denoiser.stubs.hlsli (each defined once for every check).
#include "check/stubs/shadow_denoiser.stubs.hlsli"

[numthreads(32, 8, 1)] void main(uint3 groupId : SV_GroupID, uint3 groupThreadId : SV_GroupThreadID,
                                 uint groupIndex : SV_GroupIndex)
{
    GLINT_SHADOW_DENOISER_Prepare(groupId.xy, groupThreadId.xy, groupIndex, uint2(13, 7), uint2(2, 2));
}
