// Entry for the shadow denoiser's a-trous filter (run three times with step 1, 2, 4):
// bindings, callbacks, main. Engines read this file as the integration example for
// glint/shadow_denoiser/glint_shadow_denoiser_filter.hlsli.
//
// Permutations: GLINT_SHADOW_DENOISER_TILE_LIST=1 dispatches indirectly over the tiles
// classification listed and counts the tiles it filters; GLINT_SHADOW_DENOISER_FILTER_PAIR=1
// runs steps 1 and 2 in one dispatch.
// GLINT_SHADOW_DENOISER_OUTPUT_FORMAT (shadow_denoiser_output.hlsli) picks the output's format:
// rg32f for the scratch images, any for the final output (the plan picks the last step's).
#include "entry/common/glint_entry_common.hlsli"
#include "entry/shadow_denoiser/shadow_denoiser_output.hlsli"
#include "glint/shadow_denoiser/glint_shadow_denoiser_constants.h"
#include "glint/shadow_denoiser/glint_shadow_denoiser_filter.hlsli"

GLINT_BINDING(0, 0) ConstantBuffer<GLINT_ShadowDenoiserFilterConstants> g_glint_constants;
GLINT_BINDING(1, 0) Texture2D<float2> g_glint_filter_input;
GLINT_BINDING(2, 0) Texture2D<float> g_glint_depth;
GLINT_BINDING(3, 0) Texture2D<float4> g_glint_normals;
GLINT_BINDING(4, 0) GLINT_SHADOW_DENOISER_OUTPUT_IMAGE g_glint_filter_output;
// Blocker distance of the visibility sample (< 0: unknown); read only with penumbraScale > 0
// (otherwise the plan binds another R32F image here).
GLINT_BINDING(8, 0) Texture2D<float> g_glint_blocker_distance;
#if GLINT_SHADOW_DENOISER_TILE_LIST
GLINT_BINDING(7, 0) StructuredBuffer<uint> g_glint_filter_tiles;

uint2 GLINT_SHADOW_DENOISER_LoadFilterTile(uint listIndex)
{
    uint packed = g_glint_filter_tiles[listIndex];
    return uint2(GLINT_WIRE_TileEntryX(packed), GLINT_WIRE_TileEntryY(packed));
}

GLINT_BINDING(5, 0) StructuredBuffer<uint> g_glint_tile_metadata;
GLINT_BINDING(6, 0) RWStructuredBuffer<uint> g_glint_filter_work;

uint GLINT_SHADOW_DENOISER_LoadTileMetadata(uint tileIndex)
{
    return g_glint_tile_metadata[tileIndex];
}

void GLINT_SHADOW_DENOISER_CountFilteredTile()
{
    uint previous;
    InterlockedAdd(g_glint_filter_work[0], 1u, previous);
}
#endif

float2 GLINT_SHADOW_DENOISER_LoadMeanVariance(int2 pixel)
{
    return g_glint_filter_input.Load(int3(pixel, 0));
}

float GLINT_SHADOW_DENOISER_LoadDepth(int2 pixel)
{
    return g_glint_depth.Load(int3(pixel, 0));
}

float3 GLINT_SHADOW_DENOISER_LoadNormal(int2 pixel)
{
    float2 unpack = g_glint_constants.normalUnpack;
    return g_glint_normals.Load(int3(pixel, 0)).xyz * unpack.x + unpack.y;
}

float GLINT_SHADOW_DENOISER_LoadBlockerDistance(int2 pixel)
{
    return g_glint_blocker_distance.Load(int3(pixel, 0));
}

void GLINT_SHADOW_DENOISER_StoreFiltered(int2 pixel, float2 meanVariance)
{
    g_glint_filter_output[pixel] = GLINT_SHADOW_DENOISER_OUTPUT_TEXEL(meanVariance);
}

#if GLINT_SHADOW_DENOISER_FILTER_PAIR
[numthreads(8, 8, 1)] void main(uint3 groupId : SV_GroupID, uint3 groupThreadId : SV_GroupThreadID,
                                uint groupIndex : SV_GroupIndex)
{
    GLINT_SHADOW_DENOISER_FilterPair(groupId.xy, groupThreadId.xy, groupIndex, g_glint_constants.inputSize,
                                     g_glint_constants.viewDepth, g_glint_constants.depthSigma,
                                     g_glint_constants.normalPower, g_glint_constants.penumbraScale);
}
#else
[numthreads(8, 8, 1)] void main(uint3 groupId : SV_GroupID, uint3 groupThreadId : SV_GroupThreadID,
                                uint groupIndex : SV_GroupIndex)
{
    GLINT_SHADOW_DENOISER_Filter(groupId.xy, groupThreadId.xy, groupIndex, g_glint_constants.inputSize,
                                 g_glint_constants.step, g_glint_constants.finalPass != 0,
                                 g_glint_constants.viewDepth, g_glint_constants.depthSigma,
                                 g_glint_constants.normalPower, g_glint_constants.penumbraScale);
}
#endif
