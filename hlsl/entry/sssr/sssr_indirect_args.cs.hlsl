// Entry for the SSSR indirect-arguments pass (glint/sssr/glint_sssr_indirect_args.hlsli).
#include "glint/sssr/glint_sssr_constants.h"
#include "glint/sssr/glint_sssr_indirect_args.hlsli"

[[vk::binding(0, 0)]] RWStructuredBuffer<uint> g_glint_counters;
[[vk::binding(1, 0)]] RWStructuredBuffer<uint> g_glint_arguments;

uint GLINT_SSSR_LoadCounter(uint index) { return g_glint_counters[index]; }
void GLINT_SSSR_StoreCounter(uint index, uint value) { g_glint_counters[index] = value; }
void GLINT_SSSR_StoreArgument(uint index, uint value) { g_glint_arguments[index] = value; }

[numthreads(1, 1, 1)] void main()
{
    GLINT_SSSR_WriteIndirectArguments();
}
