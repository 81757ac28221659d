// The packed words that passes hand to each other through buffers, compiled by both C++ and
// HLSL so that the shaders that write them and every tool or test that decodes them share
// one definition.
//
//   ray-list entry   (SSSR ray list)        x in bits 0-14, y in bits 15-28 (pixels),
//                                           bits 29-31 the quad-copy flags (GLINT_SSSR_RAY_COPY_*)
//   tile-list entry  (SSSR tile list, read by the reflections denoiser)
//                                           the 8x8 tile's top-left pixel: x in bits 0-15, y in 16-31
//   shadow tile      (shadow filter's list) the 8x8 tile's index: x in bits 0-15, y in 16-31
//   shadow mask word (shadow denoiser)      one word per 8x4 pixels, pixel (x, y) at bit
//                                           (y mod 4) * 8 + (x mod 8); 1 = lit
//   shadow tile metadata                    one word per 8x8 tile: bit 0 CLEAR, bit 1 LIGHT
//   ray scratch      (SSSR classify -> compact)  one buffer of words for T = ceil(W/8) ceil(H/8)
//                                           tiles (row-major): [0, 64 T) each tile's ray entries in
//                                           its pixels' row-major order, 64 slots a tile;
//                                           [64 T, 65 T) each tile's ray count; then the ray
//                                           counts of B = ceil(T / 64) blocks of 64 tiles, of
//                                           ceil(B / 64) superblocks of 64 blocks, and one
//                                           completion counter. Every word after the counts is
//                                           zero between frames (the compaction's last group
//                                           clears them), so the buffer starts zeroed.
#ifndef GLINT_WIRE_FORMATS_H
#define GLINT_WIRE_FORMATS_H

#include "glint/common/glint_shared_types.h"

#ifdef __cplusplus
#define GLINT_WIRE_FUNCTION inline
namespace glint::shared {
#else
#define GLINT_WIRE_FUNCTION
#endif

// The largest pixel coordinates a ray-list entry holds.
#define GLINT_WIRE_RAY_MAX_X 0x7FFFu
#define GLINT_WIRE_RAY_MAX_Y 0x3FFFu

GLINT_WIRE_FUNCTION uint GLINT_WIRE_PackRayEntry(uint x, uint y, uint copyFlags)
{
    return (x & GLINT_WIRE_RAY_MAX_X) | ((y & GLINT_WIRE_RAY_MAX_Y) << 15) | copyFlags;
}
GLINT_WIRE_FUNCTION uint GLINT_WIRE_RayEntryX(uint entry) { return entry & GLINT_WIRE_RAY_MAX_X; }
GLINT_WIRE_FUNCTION uint GLINT_WIRE_RayEntryY(uint entry) { return (entry >> 15) & GLINT_WIRE_RAY_MAX_Y; }

// Tile-list entries of both kinds: two 16-bit coordinates.
GLINT_WIRE_FUNCTION uint GLINT_WIRE_PackTileEntry(uint x, uint y) { return (x & 0xFFFFu) | (y << 16); }
GLINT_WIRE_FUNCTION uint GLINT_WIRE_TileEntryX(uint entry) { return entry & 0xFFFFu; }
GLINT_WIRE_FUNCTION uint GLINT_WIRE_TileEntryY(uint entry) { return entry >> 16; }

// Shadow mask: the bit of pixel (x, y) within its word.
GLINT_WIRE_FUNCTION uint GLINT_WIRE_ShadowMaskBit(uint x, uint y) { return (y & 3u) * 8u + (x & 7u); }

// Ray scratch layout (above): word indices for T tiles.
#define GLINT_WIRE_RAY_BLOCK_TILES 64u
#define GLINT_WIRE_RAY_SUPERBLOCK_BLOCKS 64u
GLINT_WIRE_FUNCTION uint GLINT_WIRE_RayBlocks(uint tiles) { return (tiles + 63u) / 64u; }
GLINT_WIRE_FUNCTION uint GLINT_WIRE_RaySuperblocks(uint tiles) { return (GLINT_WIRE_RayBlocks(tiles) + 63u) / 64u; }
GLINT_WIRE_FUNCTION uint GLINT_WIRE_RayScratchSlot(uint tile, uint slot) { return tile * 64u + slot; }
GLINT_WIRE_FUNCTION uint GLINT_WIRE_RayScratchTileCount(uint tiles, uint tile) { return tiles * 64u + tile; }
GLINT_WIRE_FUNCTION uint GLINT_WIRE_RayScratchBlockCount(uint tiles, uint block) { return tiles * 65u + block; }
GLINT_WIRE_FUNCTION uint GLINT_WIRE_RayScratchSuperblockCount(uint tiles, uint superblock)
{
    return tiles * 65u + GLINT_WIRE_RayBlocks(tiles) + superblock;
}
GLINT_WIRE_FUNCTION uint GLINT_WIRE_RayScratchCompletion(uint tiles)
{
    return GLINT_WIRE_RayScratchSuperblockCount(tiles, GLINT_WIRE_RaySuperblocks(tiles));
}
GLINT_WIRE_FUNCTION uint GLINT_WIRE_RayScratchWords(uint tiles) { return GLINT_WIRE_RayScratchCompletion(tiles) + 1u; }

#define GLINT_WIRE_SHADOW_TILE_CLEAR 1u
#define GLINT_WIRE_SHADOW_TILE_LIGHT 2u

#ifdef __cplusplus
} // namespace glint::shared
#endif
#undef GLINT_WIRE_FUNCTION

#endif // GLINT_WIRE_FORMATS_H
