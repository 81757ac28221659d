// Header check of glint_sssr_blue_noise.hlsli: its callbacks are the shared stubs in
// check/stubs/sssr.stubs.hlsli (each defined once for every check).
#include "check/stubs/sssr.stubs.hlsli"

cbuffer g_glint_check_constants { GLINT_SssrConstants g_glint_sssr; };

[numthreads(8, 8, 1)] void main(uint3 dispatchId : SV_DispatchThreadID)
{
    GLINT_SSSR_AnimateBlueNoise(g_glint_sssr, dispatchId.xy);
}
