// The tile averages and this frame's tile mask, for the prefilter and resolve entries.
#ifndef RD_ENTRY_AVERAGE_HLSLI
#define RD_ENTRY_AVERAGE_HLSLI

GLINT_BINDING(5, 0) Texture2D<float4> g_glint_average;
GLINT_BINDING(6, 0) StructuredBuffer<uint> g_glint_tile_mask;

float4 GLINT_RD_LoadAverage(uint2 tile) { return g_glint_average.Load(int3(tile, 0)); }
bool GLINT_RD_TileListed(uint2 tile)
{
    return (g_glint_tile_mask[tile.y * g_glint_rd.tiles.x + tile.x] & GLINT_RD_MASK_SELF) != 0;
}

#endif // RD_ENTRY_AVERAGE_HLSLI
