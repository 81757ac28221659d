// glint shadow denoiser, pass 1 (prepare): packs 1-sample-per-pixel visibility into one
// 32-bit word per 8x4 pixel tile (docs/shadow_denoiser.md).
//
// Integration: define these callbacks before or after including this header.
//
//   float GLINT_SHADOW_DENOISER_LoadVisibility(int2 pixel);
//       Visibility of an in-image pixel, 1 = lit. Only called with 0 <= pixel < inputSize.
//       A pixel is lit when the value is >= 0.5; NaN counts as shadowed.
//   void  GLINT_SHADOW_DENOISER_StoreMask(uint tileIndex, uint mask);
//       Writes the word of mask tile tileIndex = tile.y * maskTilesX + tile.x.
//
// Mask layout: tile = (x >> 3, y >> 2); bit (y & 3) * 8 + (x & 7), so each byte is one pixel
// row of the tile with the leftmost pixel in the least significant bit; bit set = lit.
// Out-of-image bits (tiles on the right and bottom borders of sizes that are not multiples of
// 8 x 4) repeat the nearest in-image pixel (clamp to edge), so a border tile of a uniform
// region is uniform too.
//
// Dispatch: [numthreads(32, 8, 1)], ceil(W / 32) x ceil(H / 16) x 1 groups. Each group packs
// 4 x 4 mask tiles through groupshared atomics: no assumption on the subgroup size.
#ifndef GLINT_SHADOW_DENOISER_PREPARE_HLSLI
#define GLINT_SHADOW_DENOISER_PREPARE_HLSLI

#include "glint/shadow_denoiser/glint_shadow_denoiser_constants.h"

float GLINT_SHADOW_DENOISER_LoadVisibility(int2 pixel);
void GLINT_SHADOW_DENOISER_StoreMask(uint tileIndex, uint mask);

groupshared uint g_glint_shadow_denoiser_prepare_masks[16];

uint GLINT_SHADOW_DENOISER_VisibilityBit(int2 pixel, uint2 inputSize)
{
    int2 clamped = clamp(pixel, int2(0, 0), int2(inputSize) - 1);
    float visibility = GLINT_SHADOW_DENOISER_LoadVisibility(clamped);
    // NaN compares false: shadowed.
    return visibility >= 0.5 ? 1u : 0u;
}

void GLINT_SHADOW_DENOISER_Prepare(uint2 groupId, uint2 groupThreadId, uint groupIndex, uint2 inputSize,
                                   uint2 maskTiles)
{
    if (groupIndex < 16)
        g_glint_shadow_denoiser_prepare_masks[groupIndex] = 0u;
    GroupMemoryBarrierWithGroupSync();

    // Two pixels per thread: rows y and y + 8 of the 32 x 16 block.
    uint2 blockOrigin = groupId * uint2(GLINT_SHADOW_DENOISER_PREPARE_GROUP_WIDTH,
                                        GLINT_SHADOW_DENOISER_PREPARE_BLOCK_HEIGHT);
    [unroll] for (uint part = 0; part < 2; ++part)
    {
        uint2 local = groupThreadId + uint2(0, part * GLINT_SHADOW_DENOISER_PREPARE_GROUP_HEIGHT);
        uint2 pixel = blockOrigin + local;
        uint2 tile = pixel / uint2(GLINT_SHADOW_DENOISER_MASK_TILE_WIDTH, GLINT_SHADOW_DENOISER_MASK_TILE_HEIGHT);
        if (all(tile < maskTiles))
        {
            uint bit = GLINT_SHADOW_DENOISER_VisibilityBit(int2(pixel), inputSize);
            uint2 localTile = local / uint2(GLINT_SHADOW_DENOISER_MASK_TILE_WIDTH, GLINT_SHADOW_DENOISER_MASK_TILE_HEIGHT);
            uint shift = (pixel.y & 3u) * 8u + (pixel.x & 7u);
            uint previous;
            InterlockedOr(g_glint_shadow_denoiser_prepare_masks[localTile.y * 4u + localTile.x], bit << shift,
                          previous);
        }
    }
    GroupMemoryBarrierWithGroupSync();

    if (groupIndex < 16)
    {
        uint2 localTile = uint2(groupIndex & 3u, groupIndex >> 2);
        uint2 tile = groupId * 4u + localTile;
        if (all(tile < maskTiles))
            GLINT_SHADOW_DENOISER_StoreMask(tile.y * maskTiles.x + tile.x,
                                            g_glint_shadow_denoiser_prepare_masks[groupIndex]);
    }
}

#endif // GLINT_SHADOW_DENOISER_PREPARE_HLSLI
