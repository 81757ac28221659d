// Stub callbacks for the header check of glint_hybrid_indirect_args.hlsli.
RWStructuredBuffer<uint> g_glint_check;

uint GLINT_SSSR_LoadCounter(uint index) { return g_glint_check[index]; }
void GLINT_SSSR_StoreCounter(uint index, uint value) { g_glint_check[index] = value; }
void GLINT_SSSR_StoreArgument(uint index, uint value) { g_glint_check[index + 8] = value; }

[numthreads(1, 1, 1)] void main()
{
    GLINT_HYBRID_WriteRayTracedArguments();
}
