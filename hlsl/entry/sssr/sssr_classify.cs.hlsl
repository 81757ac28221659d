// Permutation GLINT_SSSR_HALF_STORAGE=1: roughness, radiance and confidence stored in 16-bit
// float (the header clamps radiance to the fp16 range first).
// Entry for the SSSR tile classification: the ray scratch buffer and main here, the other bindings and
// callbacks in sssr_classify_bindings.hlsli. Engines read the two as the integration example
// for glint/sssr/glint_sssr_classify.hlsli.
#include "entry/common/glint_entry_common.hlsli"
#include "glint/sssr/glint_sssr_constants.h"
#include "glint/sssr/glint_sssr_classify.hlsli"
#include "entry/sssr/sssr_environment.hlsli"
#include "entry/sssr/sssr_classify_bindings.hlsli"

GLINT_BINDING(12, 0) RWStructuredBuffer<uint> g_glint_ray_scratch;

uint GLINT_SSSR_AddRays(uint count)
{
    uint previous;
    InterlockedAdd(g_glint_counters[0], count, previous);
    return previous;
}
void GLINT_SSSR_StoreRayScratch(uint word, uint value) { g_glint_ray_scratch[word] = value; }
uint GLINT_SSSR_AddRayScratch(uint word, uint value)
{
    uint previous;
    InterlockedAdd(g_glint_ray_scratch[word], value, previous);
    return previous;
}

[numthreads(8, 8, 1)] void main(uint3 groupId : SV_GroupID, uint3 groupThreadId : SV_GroupThreadID)
{
    GLINT_SSSR_Classify(g_glint_sssr, groupId.xy, groupThreadId.xy);
}
