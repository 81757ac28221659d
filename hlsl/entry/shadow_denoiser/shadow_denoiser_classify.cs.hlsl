// Entry for the shadow denoiser's tile classification + temporal pass: bindings, callbacks,
// main. Engines read this file as the integration example for
// glint/shadow_denoiser/glint_shadow_denoiser_classify.hlsli.
#include "entry/common/glint_entry_common.hlsli"
#include "entry/shadow_denoiser/shadow_denoiser_output.hlsli"
#include "glint/shadow_denoiser/glint_shadow_denoiser_constants.h"
#include "glint/shadow_denoiser/glint_shadow_denoiser_classify.hlsli"

GLINT_BINDING(0, 0) ConstantBuffer<GLINT_ShadowDenoiserClassifyConstants> g_glint_constants;
GLINT_BINDING(1, 0) StructuredBuffer<uint> g_glint_shadow_mask;
GLINT_BINDING(2, 0) Texture2D<float> g_glint_depth;
GLINT_BINDING(3, 0) Texture2D<float> g_glint_previous_depth;
GLINT_BINDING(4, 0) Texture2D<float4> g_glint_normals;
GLINT_BINDING(5, 0) Texture2D<float2> g_glint_motion;
GLINT_BINDING(6, 0) Texture2D<float4> g_glint_moments_history;
GLINT_BINDING(7, 0) StructuredBuffer<uint> g_glint_previous_metadata;
GLINT_BINDING(8, 0) RWStructuredBuffer<uint> g_glint_tile_metadata;
GLINT_BINDING(9, 0) GLINT_IMAGE_FORMAT(rg32f) RWTexture2D<float2> g_glint_shadow_variance;
GLINT_BINDING(10, 0) GLINT_IMAGE_FORMAT(rgba32f) RWTexture2D<float4> g_glint_moments;
// Blocker distance of the visibility sample (< 0: unknown); read only with penumbraScale > 0
// (the host binds the depth in its place otherwise).
GLINT_BINDING(14, 0) Texture2D<float> g_glint_blocker_distance;

#if GLINT_SHADOW_DENOISER_TILE_LIST
// Permutations "list", "tiles" and "listed": the filter's tile list (indirect arguments first
// written by prepare); "tiles" appends to it, "listed" (dispatched from it) reads it.
// g_glint_filter_output is the final output ("shadow_output"), in the format
// GLINT_SHADOW_DENOISER_OUTPUT_FORMAT picks (shadow_denoiser_output.hlsli).
GLINT_BINDING(11, 0) RWStructuredBuffer<uint> g_glint_filter_args;
GLINT_BINDING(12, 0) RWStructuredBuffer<uint> g_glint_filter_tiles;
GLINT_BINDING(13, 0) GLINT_SHADOW_DENOISER_OUTPUT_IMAGE g_glint_filter_output;

void GLINT_SHADOW_DENOISER_AppendFilterTile(uint2 tile)
{
    uint index;
    InterlockedAdd(g_glint_filter_args[0], 1u, index);
    g_glint_filter_tiles[index] = GLINT_WIRE_PackTileEntry(tile.x, tile.y);
}

void GLINT_SHADOW_DENOISER_StoreClearOutput(int2 pixel, float2 value)
{
    g_glint_filter_output[pixel] = GLINT_SHADOW_DENOISER_OUTPUT_TEXEL(value);
}

uint2 GLINT_SHADOW_DENOISER_LoadFilterTile(uint listIndex)
{
    uint packed = g_glint_filter_tiles[listIndex];
    return uint2(GLINT_WIRE_TileEntryX(packed), GLINT_WIRE_TileEntryY(packed));
}
#endif

uint GLINT_SHADOW_DENOISER_LoadMask(int2 tile)
{
    return g_glint_shadow_mask[uint(tile.y) * g_glint_constants.maskTiles.x + uint(tile.x)];
}

float GLINT_SHADOW_DENOISER_LoadDepth(int2 pixel)
{
    return g_glint_depth.Load(int3(pixel, 0));
}

float GLINT_SHADOW_DENOISER_LoadPreviousDepth(int2 pixel)
{
    return g_glint_previous_depth.Load(int3(pixel, 0));
}

float3 GLINT_SHADOW_DENOISER_LoadNormal(int2 pixel)
{
    float2 unpack = g_glint_constants.normalUnpack;
    return g_glint_normals.Load(int3(pixel, 0)).xyz * unpack.x + unpack.y;
}

float2 GLINT_SHADOW_DENOISER_LoadMotion(int2 pixel)
{
    return g_glint_motion.Load(int3(pixel, 0));
}

float3 GLINT_SHADOW_DENOISER_LoadMomentsHistory(int2 pixel)
{
    return g_glint_moments_history.Load(int3(pixel, 0)).xyz;
}

float GLINT_SHADOW_DENOISER_LoadShadowHistory(int2 pixel)
{
    return g_glint_moments_history.Load(int3(pixel, 0)).w;
}

uint GLINT_SHADOW_DENOISER_LoadPreviousMetadata(uint tileIndex)
{
    return g_glint_previous_metadata[tileIndex];
}

void GLINT_SHADOW_DENOISER_StoreMetadata(uint tileIndex, uint metadata)
{
    g_glint_tile_metadata[tileIndex] = metadata;
}

void GLINT_SHADOW_DENOISER_StoreShadowVariance(int2 pixel, float2 value)
{
    g_glint_shadow_variance[pixel] = value;
}

void GLINT_SHADOW_DENOISER_StoreMoments(int2 pixel, float4 moments)
{
    g_glint_moments[pixel] = moments;
}

float GLINT_SHADOW_DENOISER_LoadBlockerDistance(int2 pixel)
{
    return g_glint_blocker_distance.Load(int3(pixel, 0));
}

[numthreads(8, 8, GLINT_SHADOW_DENOISER_CLASSIFY_BLOCKS)] void main(uint3 groupId : SV_GroupID,
                                                                   uint3 groupThreadId : SV_GroupThreadID)
{
    // glslang passes no ConstantBuffer to a function: copy it into the plain struct.
    GLINT_ShadowDenoiserClassifyParams c;
    c.inputSize = g_glint_constants.inputSize;
    c.maskTiles = g_glint_constants.maskTiles;
    c.reproject = float4x4(g_glint_constants.reproject[0], g_glint_constants.reproject[1], g_glint_constants.reproject[2], g_glint_constants.reproject[3]);
    c.inverseViewProj = float4x4(g_glint_constants.inverseViewProj[0], g_glint_constants.inverseViewProj[1], g_glint_constants.inverseViewProj[2],
                                 g_glint_constants.inverseViewProj[3]);
    c.eyePosition = g_glint_constants.eyePosition;
    c.viewDepth = g_glint_constants.viewDepth;
    c.ndcYSign = g_glint_constants.ndcYSign;
    c.flags = g_glint_constants.flags;
    c.storedVarianceScale = g_glint_constants.storedVarianceScale;
    c.penumbraScale = g_glint_constants.penumbraScale;
    GLINT_SHADOW_DENOISER_Classify(groupId.xy, groupThreadId, c);
}
