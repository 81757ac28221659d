// Entry for the shadow denoiser's prepare pass: bindings, callbacks, main. Engines read this
// file as the integration example for glint/shadow_denoiser/glint_shadow_denoiser_prepare.hlsli.
#include "entry/common/glint_entry_common.hlsli"
#include "glint/shadow_denoiser/glint_shadow_denoiser_constants.h"
#include "glint/shadow_denoiser/glint_shadow_denoiser_prepare.hlsli"

GLINT_BINDING(0, 0) ConstantBuffer<GLINT_ShadowDenoiserPrepareConstants> g_glint_constants;
GLINT_BINDING(1, 0) Texture2D<float> g_glint_visibility;
GLINT_BINDING(2, 0) RWStructuredBuffer<uint> g_glint_shadow_mask;

#if GLINT_SHADOW_DENOISER_TILE_LIST
// Permutation "list": resets the filter's tile list for classification to append to.
GLINT_BINDING(3, 0) RWStructuredBuffer<uint> g_glint_filter_args;

void GLINT_SHADOW_DENOISER_ResetFilterTiles()
{
    g_glint_filter_args[0] = 0u;
    g_glint_filter_args[1] = 1u;
    g_glint_filter_args[2] = 1u;
}
#endif

float GLINT_SHADOW_DENOISER_LoadVisibility(int2 pixel)
{
    return g_glint_visibility.Load(int3(pixel, 0));
}

void GLINT_SHADOW_DENOISER_StoreMask(uint tileIndex, uint mask)
{
    g_glint_shadow_mask[tileIndex] = mask;
}

[numthreads(32, 8, 1)] void main(uint3 groupId : SV_GroupID, uint3 groupThreadId : SV_GroupThreadID,
                                 uint groupIndex : SV_GroupIndex)
{
    GLINT_SHADOW_DENOISER_Prepare(groupId.xy, groupThreadId.xy, groupIndex, g_glint_constants.inputSize,
                                  uint2(g_glint_constants.maskTilesX, g_glint_constants.maskTilesY));
}
