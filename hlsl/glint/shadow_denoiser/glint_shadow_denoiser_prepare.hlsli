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
// With GLINT_SHADOW_DENOISER_TILE_LIST=1 also
//   void  GLINT_SHADOW_DENOISER_ResetFilterTiles();   writes the filter's arguments (0, 1, 1)
//
// Mask layout (glint/common/glint_wire_formats.h): tile = (x >> 3, y >> 2); bit
// GLINT_WIRE_ShadowMaskBit(x, y) = (y & 3) * 8 + (x & 7), so each byte is one pixel row of the
// tile with the leftmost pixel in the least significant bit; bit set = lit.
// Out-of-image bits (tiles on the right and bottom borders of sizes that are not multiples of
// 8 x 4) repeat the nearest in-image pixel (clamp to edge), so a border tile of a uniform
// region is uniform too.
//
// Entry: from main, GLINT_SHADOW_DENOISER_Prepare(SV_GroupID.xy, SV_GroupThreadID.xy,
// SV_GroupIndex, c.inputSize, uint2(c.maskTilesX, c.maskTilesY)), c a
// GLINT_ShadowDenoiserPrepareConstants (glint_shadow_denoiser_constants.h; filled by
// host/src/core/shadow_denoiser_passes.cpp). Integration guide: docs/integration.md.
//
// Dispatch: [numthreads(32, 8, 1)] with and without the tile list, ceil(maskTilesX / 8) x
// ceil(maskTilesY / 8) x 1 groups. Four consecutive threads pack one word, each from one
// 8-pixel row, and combine the four bytes through groupshared memory after one barrier: 8
// dependent-free loads a thread instead of 32 (one thread a word), and no atomics (OR-ing bits
// into groupshared words would put 32 atomics on each; docs/performance.md). Nothing depends
// on the subgroup size.
#ifndef GLINT_SHADOW_DENOISER_PREPARE_HLSLI
#define GLINT_SHADOW_DENOISER_PREPARE_HLSLI

#include "glint/common/glint_wire_formats.h"
#include "glint/shadow_denoiser/glint_shadow_denoiser_constants.h"

float GLINT_SHADOW_DENOISER_LoadVisibility(int2 pixel);
void GLINT_SHADOW_DENOISER_StoreMask(uint tileIndex, uint mask);
#if GLINT_SHADOW_DENOISER_TILE_LIST
// Writes the filter's indirect arguments (0, 1, 1): classification appends to the list.
void GLINT_SHADOW_DENOISER_ResetFilterTiles();
#endif

uint GLINT_SHADOW_DENOISER_VisibilityBit(int2 pixel, uint2 inputSize)
{
    int2 clamped = clamp(pixel, int2(0, 0), int2(inputSize) - 1);
    float visibility = GLINT_SHADOW_DENOISER_LoadVisibility(clamped);
    // NaN compares false: shadowed.
    return visibility >= 0.5 ? 1u : 0u;
}

// One byte-aligned pixel row of a word per thread (already shifted into place).
groupshared uint g_glint_shadow_denoiser_prepare_rows[GLINT_SHADOW_DENOISER_PREPARE_GROUP_WIDTH *
                                                      GLINT_SHADOW_DENOISER_PREPARE_GROUP_HEIGHT];

void GLINT_SHADOW_DENOISER_Prepare(uint2 groupId, uint2 groupThreadId, uint groupIndex, uint2 inputSize,
                                   uint2 maskTiles)
{
#if GLINT_SHADOW_DENOISER_TILE_LIST
    if (all(groupId == 0u) && groupIndex == 0u)
        GLINT_SHADOW_DENOISER_ResetFilterTiles();
#endif
    // groupIndex = y * 32 + x: threads 4t .. 4t + 3 of a group row are rows 0..3 of one tile.
    uint row = groupThreadId.x % GLINT_SHADOW_DENOISER_MASK_TILE_HEIGHT;
    uint2 tile = uint2(groupId.x * GLINT_SHADOW_DENOISER_PREPARE_GROUP_TILES_X +
                           groupThreadId.x / GLINT_SHADOW_DENOISER_MASK_TILE_HEIGHT,
                       groupId.y * GLINT_SHADOW_DENOISER_PREPARE_GROUP_HEIGHT + groupThreadId.y);
    bool inMask = all(tile < maskTiles);
    uint bits = 0u;
    if (inMask)
    {
        int2 origin = int2(tile * uint2(GLINT_SHADOW_DENOISER_MASK_TILE_WIDTH, GLINT_SHADOW_DENOISER_MASK_TILE_HEIGHT));
        [unroll] for (uint column = 0; column < GLINT_SHADOW_DENOISER_MASK_TILE_WIDTH; ++column)
            bits |= GLINT_SHADOW_DENOISER_VisibilityBit(origin + int2(column, row), inputSize)
                    << GLINT_WIRE_ShadowMaskBit(column, 0u);
    }
    // Pixel (column, row)'s bit is ShadowMaskBit(column, 0) + ShadowMaskBit(0, row).
    g_glint_shadow_denoiser_prepare_rows[groupIndex] = bits << GLINT_WIRE_ShadowMaskBit(0u, row);
    GroupMemoryBarrierWithGroupSync();
    if (inMask && row == 0u)
        GLINT_SHADOW_DENOISER_StoreMask(tile.y * maskTiles.x + tile.x,
                                        g_glint_shadow_denoiser_prepare_rows[groupIndex] |
                                            g_glint_shadow_denoiser_prepare_rows[groupIndex + 1u] |
                                            g_glint_shadow_denoiser_prepare_rows[groupIndex + 2u] |
                                            g_glint_shadow_denoiser_prepare_rows[groupIndex + 3u]);
}

#endif // GLINT_SHADOW_DENOISER_PREPARE_HLSLI
