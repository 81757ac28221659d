// Header check of glint_hybrid_intersect.hlsli: its callbacks are the shared stubs in
// check/stubs/hybrid.stubs.hlsli (each defined once for every check).
#include "check/stubs/hybrid.stubs.hlsli"

cbuffer g_glint_check_constants { GLINT_SssrConstants g_glint_sssr; GLINT_HybridConstants g_glint_hybrid; };

[numthreads(64, 1, 1)] void main(uint3 groupId : SV_GroupID, uint groupIndex : SV_GroupIndex)
{
    GLINT_HYBRID_IntersectScreenSpace(g_glint_sssr, g_glint_hybrid, groupIndex, groupId.x * 64 + groupIndex);
}
