// Stub callbacks for the header check of glint_shadow_denoiser_filter.hlsli. The check compiles
// the header without tile skipping; the entry's "list" permutations compile it with.
RWStructuredBuffer<float4> g_glint_check;

float2 GLINT_SHADOW_DENOISER_LoadMeanVariance(int2 pixel)
{
    return g_glint_check[pixel.x].xy;
}

float GLINT_SHADOW_DENOISER_LoadDepth(int2 pixel)
{
    return g_glint_check[pixel.y].z;
}

float3 GLINT_SHADOW_DENOISER_LoadNormal(int2 pixel)
{
    return g_glint_check[pixel.x + pixel.y].xyz;
}

float GLINT_SHADOW_DENOISER_LoadBlockerDistance(int2 pixel)
{
    return g_glint_check[pixel.x].w;
}

void GLINT_SHADOW_DENOISER_StoreFiltered(int2 pixel, float2 meanVariance)
{
    g_glint_check[pixel.x] = float4(meanVariance, 0.0, 0.0);
}

[numthreads(8, 8, 1)] void main(uint3 groupId : SV_GroupID, uint3 groupThreadId : SV_GroupThreadID,
                                uint groupIndex : SV_GroupIndex)
{
    GLINT_SHADOW_DENOISER_Filter(groupId.xy, groupThreadId.xy, groupIndex, uint2(13, 7), 2, true,
                                 float4(0.1, 1.0, -1.0, 0.0), 0.02, 32.0, 40.0);
}
