// Header check of glint_hybrid_shade.hlsli: its callbacks are the shared stubs in
// check/stubs/hybrid_hit.stubs.hlsli (each defined once for every check).
#include "check/stubs/hybrid_hit.stubs.hlsli"

cbuffer g_glint_check_constants { GLINT_SssrConstants g_glint_sssr; GLINT_HybridConstants g_glint_hybrid; };

[numthreads(64, 1, 1)] void main(uint3 groupId : SV_GroupID, uint groupIndex : SV_GroupIndex)
{
    GLINT_HYBRID_ShadeRays(g_glint_sssr, g_glint_hybrid, groupId.x * 64 + groupIndex);
}
