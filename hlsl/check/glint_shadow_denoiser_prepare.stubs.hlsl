// Stub callbacks for the header check of glint_shadow_denoiser_prepare.hlsli.
RWStructuredBuffer<uint> g_glint_check;

float GLINT_SHADOW_DENOISER_LoadVisibility(int2 pixel)
{
    return asfloat(g_glint_check[pixel.x + pixel.y]);
}

void GLINT_SHADOW_DENOISER_StoreMask(uint tileIndex, uint mask)
{
    g_glint_check[tileIndex] = mask;
}

[numthreads(32, 8, 1)] void main(uint3 groupId : SV_GroupID, uint3 groupThreadId : SV_GroupThreadID,
                                 uint groupIndex : SV_GroupIndex)
{
    GLINT_SHADOW_DENOISER_Prepare(groupId.xy, groupThreadId.xy, groupIndex, uint2(13, 7), uint2(2, 2));
}
