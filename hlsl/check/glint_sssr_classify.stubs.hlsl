// Header check of glint_sssr_classify.hlsli: its callbacks are the shared stubs in
// check/stubs/sssr.stubs.hlsli (each defined once for every check).
#include "check/stubs/sssr.stubs.hlsli"

cbuffer g_glint_check_constants { GLINT_SssrConstants g_glint_sssr; };

[numthreads(8, 8, 1)] void main(uint3 groupId : SV_GroupID, uint3 groupThreadId : SV_GroupThreadID)
{
    GLINT_SSSR_Classify(g_glint_sssr, groupId.xy, groupThreadId.xy);
}
