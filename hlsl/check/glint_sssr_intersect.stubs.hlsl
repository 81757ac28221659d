// Header check of glint_sssr_intersect.hlsli: its callbacks are the shared stubs in
// check/stubs/sssr.stubs.hlsli (each defined once for every check).
// No permutation defines: the entry's permutations compile the thickness-aware, debug and
// stored-ray variants.
#include "check/stubs/sssr.stubs.hlsli"

cbuffer g_glint_check_constants { GLINT_SssrConstants g_glint_sssr; };

[numthreads(64, 1, 1)] void main(uint3 groupId : SV_GroupID, uint groupIndex : SV_GroupIndex)
{
    GLINT_SSSR_Intersect(g_glint_sssr, groupIndex, groupId.x * 64 + groupIndex);
}
