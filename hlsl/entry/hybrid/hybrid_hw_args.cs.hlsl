// Entry for the ray tracer's indirect arguments (glint/hybrid/glint_hybrid_indirect_args.hlsli).
#include "entry/common/glint_entry_common.hlsli"
#include "glint/hybrid/glint_hybrid_indirect_args.hlsli"

GLINT_BINDING(0, 0) RWStructuredBuffer<uint> g_glint_counters;
GLINT_BINDING(1, 0) RWStructuredBuffer<uint> g_glint_arguments;

uint GLINT_SSSR_LoadCounter(uint index) { return g_glint_counters[index]; }
void GLINT_SSSR_StoreCounter(uint index, uint value) { g_glint_counters[index] = value; }
void GLINT_SSSR_StoreArgument(uint index, uint value) { g_glint_arguments[index] = value; }

[numthreads(1, 1, 1)] void main()
{
    GLINT_HYBRID_WriteRayTracedArguments();
}
