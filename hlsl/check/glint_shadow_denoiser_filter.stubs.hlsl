// Header check of glint_shadow_denoiser_filter.hlsli: its callbacks are the shared stubs in
// check/stubs/shadow_denoiser.stubs.hlsli (each defined once for every check).
// The check compiles the header without tile skipping; the entry's "list" permutations compile
// it with.
#include "check/stubs/shadow_denoiser.stubs.hlsli"

[numthreads(8, 8, 1)] void main(uint3 groupId : SV_GroupID, uint3 groupThreadId : SV_GroupThreadID,
                                uint groupIndex : SV_GroupIndex)
{
    GLINT_SHADOW_DENOISER_Filter(groupId.xy, groupThreadId.xy, groupIndex, uint2(13, 7), 2, true,
                                 float4(0.1, 1.0, -1.0, 0.0), 0.02, 32.0, 40.0);
}
