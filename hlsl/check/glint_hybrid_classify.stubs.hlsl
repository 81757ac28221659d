// Header check of glint_hybrid_classify.hlsli: its callbacks are the shared stubs in
// check/stubs/hybrid.stubs.hlsli (each defined once for every check).
#include "check/stubs/hybrid.stubs.hlsli"

cbuffer g_glint_check_constants { GLINT_SssrConstants g_glint_sssr; GLINT_HybridConstants g_glint_hybrid; };

[numthreads(8, 8, 1)] void main(uint3 groupId : SV_GroupID, uint3 groupThreadId : SV_GroupThreadID)
{
    GLINT_HYBRID_Classify(g_glint_sssr, g_glint_hybrid, groupId.xy, groupThreadId.xy);
}
