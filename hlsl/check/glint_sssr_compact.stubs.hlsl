// Header check of glint_sssr_compact.hlsli: its callbacks are the shared stubs in
// check/stubs/sssr.stubs.hlsli (each defined once for every check).
#include "check/stubs/sssr.stubs.hlsli"

cbuffer g_glint_check_constants { GLINT_SssrConstants g_glint_sssr; };

[numthreads(64, 1, 1)] void main(uint3 groupId : SV_GroupID, uint groupIndex : SV_GroupIndex)
{
    GLINT_SSSR_CompactRays(g_glint_sssr, groupId.x, groupIndex);
}
