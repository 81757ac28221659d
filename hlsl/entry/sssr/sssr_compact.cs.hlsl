// Entry for the SSSR ray-list compaction: bindings, callbacks, main
// (glint/sssr/glint_sssr_compact.hlsli). Engines read it as the integration example.
#include "entry/common/glint_entry_common.hlsli"
#include "glint/sssr/glint_sssr_constants.h"
#include "glint/sssr/glint_sssr_compact.hlsli"

// A cbuffer holding the struct (not ConstantBuffer<T>) so that glslang can pass it by value.
GLINT_BINDING(0, 0) cbuffer g_glint_constants { GLINT_SssrConstants g_glint_sssr; };
GLINT_BINDING(1, 0) RWStructuredBuffer<uint> g_glint_ray_scratch;
GLINT_BINDING(2, 0) RWStructuredBuffer<uint> g_glint_ray_list;

uint GLINT_SSSR_LoadRayScratch(uint word) { return g_glint_ray_scratch[word]; }
void GLINT_SSSR_StoreRayScratch(uint word, uint value) { g_glint_ray_scratch[word] = value; }
uint GLINT_SSSR_AddRayScratch(uint word, uint value)
{
    uint previous;
    InterlockedAdd(g_glint_ray_scratch[word], value, previous);
    return previous;
}
void GLINT_SSSR_StoreRay(uint index, uint entry) { g_glint_ray_list[index] = entry; }

[numthreads(64, 1, 1)] void main(uint3 groupId : SV_GroupID, uint groupIndex : SV_GroupIndex)
{
    GLINT_SSSR_CompactRays(g_glint_sssr, groupId.y * GLINT_SSSR_GROUPS_PER_ROW + groupId.x, groupIndex);
}
