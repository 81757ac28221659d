// glint hybrid reflections, pass 2: tile classification (docs/hybrid.md). The SSSR per-pixel
// decision (glint_sssr_classify.hlsli: which pixels own a ray, which copy a quad neighbour's)
// plus, per 8x8 tile, a class chosen from last frame's feedback counters: FULL_SW (every ray
// tries screen space first), HALF_SW (a checkerboard of the two) or FULL_HW (every ray is ray
// traced). Screen-space rays go to a list padded per tile to 32 or 64 entries, so that every
// aligned block of 32 entries belongs to one tile; ray-traced rays to a plain list. Tiles with
// a glossy pixel go to the denoiser's tile list, mirrors included.
//
// Integration: the callbacks of glint_sssr_classify.hlsli except GLINT_SSSR_AddRays,
// GLINT_SSSR_StoreRayScratch and GLINT_SSSR_AddRayScratch (the SSSR ray list is not used), and
// these:
//
//   uint GLINT_HYBRID_LoadFeedbackHistory(int2 tile);  last frame's counter image, R32_UINT
//       ceil(W/8) x ceil(H/8); only in-range tiles are asked
//   void GLINT_HYBRID_StoreFeedback(int2 tile, uint counter);  this frame's counter image
//   void GLINT_HYBRID_StoreTileClass(int2 tile, uint tileClass);  GLINT_HYBRID_TILE_*, for views
//   uint GLINT_HYBRID_MaterialRoute(int2 pixel, float alpha);  per-material override:
//       GLINT_HYBRID_ROUTE_AUTO, _RAY_TRACED (e.g. mirrors always ray traced) or _SCREEN_SPACE
//   uint GLINT_HYBRID_AddScreenSpaceRays(uint count);  atomic add to counter 0, returns the old value
//   void GLINT_HYBRID_StoreScreenSpaceRay(uint index, uint entry);
//   uint GLINT_HYBRID_AddRayTracedRays(uint count);    atomic add to counter 4, returns the old value
//   void GLINT_HYBRID_StoreRayTracedRay(uint index, uint entry);
//
// Entry: from main, GLINT_HYBRID_Classify(c, h, SV_GroupID.xy, SV_GroupThreadID.xy), with c the
// GLINT_SssrConstants and h the GLINT_HybridConstants of one cbuffer (glint_hybrid_constants.h).
// Dispatch: [numthreads(8, 8, 1)], ceil(W / 8) x ceil(H / 8) groups, one tile per group. The
// screen-space list needs ceil(W/8) ceil(H/8) 64 entries, the ray-traced list W H.
#ifndef GLINT_HYBRID_CLASSIFY_HLSLI
#define GLINT_HYBRID_CLASSIFY_HLSLI

#include "glint/hybrid/glint_hybrid_common.hlsli"
#include "glint/sssr/glint_sssr_classify.hlsli"

uint GLINT_HYBRID_LoadFeedbackHistory(int2 tile);
void GLINT_HYBRID_StoreFeedback(int2 tile, uint counter);
void GLINT_HYBRID_StoreTileClass(int2 tile, uint tileClass);
uint GLINT_HYBRID_MaterialRoute(int2 pixel, float alpha);
uint GLINT_HYBRID_AddScreenSpaceRays(uint count);
void GLINT_HYBRID_StoreScreenSpaceRay(uint index, uint entry);
uint GLINT_HYBRID_AddRayTracedRays(uint count);
void GLINT_HYBRID_StoreRayTracedRay(uint index, uint entry);

groupshared uint g_glint_hybrid_tile_class;
groupshared uint g_glint_hybrid_sw_count;
groupshared uint g_glint_hybrid_hw_count;
groupshared uint g_glint_hybrid_sw_base;
groupshared uint g_glint_hybrid_hw_base;

// The history counter this tile's statistics come from: the tile its random pixel came from
// (through that pixel's motion), unless one of the 3x3 tiles around this tile's own position
// had more screen-space hits (the safe band). Off-screen or non-finite motion reprojects to
// no statistics (0).
uint GLINT_HYBRID_ChooseHistory(GLINT_SssrConstants c, GLINT_HybridConstants h, uint2 tile)
{
    uint random = GLINT_HYBRID_TileHash(h, tile, h.frameIndex);
    uint2 pixel = min(tile * GLINT_SSSR_TILE + GLINT_HYBRID_TilePixelOffset(random), c.inputSize - 1u);
    float2 uv = (float2(pixel) + 0.5) * c.inverseInputSize;
    float2 previousUv = uv + GLINT_SSSR_LoadMotion(int2(pixel)) * c.motionScale;
    uint reprojected = 0;
    if (all(previousUv >= 0.0) && all(previousUv < 1.0)) // false for NaN
    {
        uint2 previousPixel = min(uint2(previousUv * float2(c.inputSize)), c.inputSize - 1u);
        reprojected = GLINT_HYBRID_LoadFeedbackHistory(int2(previousPixel / GLINT_SSSR_TILE));
    }
    uint best = reprojected;
    for (int dy = -1; dy <= 1; ++dy)
    {
        for (int dx = -1; dx <= 1; ++dx)
        {
            int2 neighbour = int2(tile) + int2(dx, dy);
            if (any(neighbour < 0) || any(neighbour >= int2(h.tiles)))
                continue;
            uint counter = GLINT_HYBRID_LoadFeedbackHistory(neighbour);
            if (GLINT_HYBRID_Hits(counter) > GLINT_HYBRID_Hits(best))
                best = counter;
        }
    }
    return best;
}

// The tile's class from the chosen history: screen space now if u <= s + h - w m on this
// frame's fields and last frame's, each with its own frame's lottery number.
uint GLINT_HYBRID_TileClass(GLINT_HybridConstants h, uint2 tile, uint history)
{
    if ((h.flags & GLINT_HYBRID_FLAG_RAY_TRACING) == 0)
        return GLINT_HYBRID_TILE_FULL_SW;
    if ((h.flags & GLINT_HYBRID_FLAG_SCREEN_SPACE) == 0)
        return GLINT_HYBRID_TILE_FULL_HW;
    if ((h.flags & GLINT_HYBRID_FLAG_FEEDBACK) == 0)
        return GLINT_HYBRID_TILE_FULL_SW;
    bool now = GLINT_HYBRID_PrefersScreenSpace(h, GLINT_HYBRID_Hits(history), GLINT_HYBRID_Misses(history),
                                               GLINT_HYBRID_TileUniform(GLINT_HYBRID_TileHash(h, tile, h.frameIndex)));
    bool before = GLINT_HYBRID_PrefersScreenSpace(h, GLINT_HYBRID_LastHits(history), GLINT_HYBRID_LastMisses(history),
                                                  GLINT_HYBRID_TileUniform(GLINT_HYBRID_TileHash(h, tile, h.frameIndex - 1u)));
    if (now && before)
        return GLINT_HYBRID_TILE_FULL_SW;
    if (!now && !before)
        return GLINT_HYBRID_TILE_FULL_HW;
    return GLINT_HYBRID_TILE_HALF_SW;
}

// Whether a pixel's own ray goes to screen space (else to the ray tracer).
bool GLINT_HYBRID_RouteToScreenSpace(GLINT_HybridConstants h, uint tileClass, int2 pixel, float alpha)
{
    if ((h.flags & GLINT_HYBRID_FLAG_RAY_TRACING) == 0)
        return true;
    if ((h.flags & GLINT_HYBRID_FLAG_SCREEN_SPACE) == 0)
        return false;
    uint route = GLINT_HYBRID_MaterialRoute(pixel, alpha);
    if (route != GLINT_HYBRID_ROUTE_AUTO)
        return route == GLINT_HYBRID_ROUTE_SCREEN_SPACE;
    if (!(alpha < h.rayTracingThreshold))
        return true;
    if (tileClass == GLINT_HYBRID_TILE_HALF_SW)
        return GLINT_HYBRID_CheckerboardScreenSpace(h, uint2(pixel));
    return tileClass == GLINT_HYBRID_TILE_FULL_SW;
}

void GLINT_HYBRID_Classify(GLINT_SssrConstants c, GLINT_HybridConstants h, uint2 groupId, uint2 local)
{
    uint localIndex = local.y * GLINT_SSSR_TILE + local.x;
    if (localIndex == 0)
    {
        uint history = GLINT_HYBRID_ChooseHistory(c, h, groupId);
        g_glint_hybrid_tile_class = GLINT_HYBRID_TileClass(h, groupId, history);
        GLINT_HYBRID_StoreTileClass(int2(groupId), g_glint_hybrid_tile_class);
        // This frame's counter starts with the chosen history's fresh fields as its "last
        // frame" fields; the screen-space intersection adds this frame's.
        GLINT_HYBRID_StoreFeedback(int2(groupId), GLINT_HYBRID_Age(history));
        g_glint_hybrid_sw_count = 0;
        g_glint_hybrid_hw_count = 0;
        g_glint_sssr_any_glossy = 0;
    }
    // Its barrier also publishes the tile class and orders the initialization above.
    GLINT_SSSR_PixelDecision d = GLINT_SSSR_ClassifyPixel(c, groupId, local);
    bool screenSpace = d.traces && GLINT_HYBRID_RouteToScreenSpace(h, g_glint_hybrid_tile_class, d.pixel, d.alpha);
    bool rayTraced = d.traces && !screenSpace;

    // Per-wave prefix counts and one groupshared atomic per wave, as SSSR's compaction.
    uint waveSw = WaveActiveCountBits(screenSpace);
    uint waveHw = WaveActiveCountBits(rayTraced);
    uint swWaveBase = 0;
    uint hwWaveBase = 0;
    if (WaveIsFirstLane() && waveSw > 0)
        InterlockedAdd(g_glint_hybrid_sw_count, waveSw, swWaveBase);
    if (WaveIsFirstLane() && waveHw > 0)
        InterlockedAdd(g_glint_hybrid_hw_count, waveHw, hwWaveBase);
    uint swSlot = WaveReadLaneFirst(swWaveBase) + WavePrefixCountBits(screenSpace);
    uint hwSlot = WaveReadLaneFirst(hwWaveBase) + WavePrefixCountBits(rayTraced);
    bool waveGlossy = WaveActiveAnyTrue(d.glossy);
    if (WaveIsFirstLane() && waveGlossy)
        InterlockedOr(g_glint_sssr_any_glossy, 1u);
    GroupMemoryBarrierWithGroupSync();
    uint swAllocation = GLINT_HYBRID_ScreenSpaceAllocation(g_glint_hybrid_sw_count);
    if (localIndex == 0)
    {
        if (swAllocation > 0)
            g_glint_hybrid_sw_base = GLINT_HYBRID_AddScreenSpaceRays(swAllocation);
        if (g_glint_hybrid_hw_count > 0)
            g_glint_hybrid_hw_base = GLINT_HYBRID_AddRayTracedRays(g_glint_hybrid_hw_count);
        if (g_glint_sssr_any_glossy != 0)
            GLINT_SSSR_StoreTile(GLINT_SSSR_AddTile(), GLINT_SSSR_PackTile(groupId * GLINT_SSSR_TILE));
    }
    GroupMemoryBarrierWithGroupSync();
    uint entry = GLINT_SSSR_PackRay(uint2(d.pixel), d.copyFlags);
    if (screenSpace)
        GLINT_HYBRID_StoreScreenSpaceRay(g_glint_hybrid_sw_base + swSlot, entry);
    if (localIndex >= g_glint_hybrid_sw_count && localIndex < swAllocation)
        GLINT_HYBRID_StoreScreenSpaceRay(g_glint_hybrid_sw_base + localIndex, GLINT_HYBRID_PADDING_ENTRY);
    if (rayTraced)
        GLINT_HYBRID_StoreRayTracedRay(g_glint_hybrid_hw_base + hwSlot, entry);

    GLINT_SSSR_StoreInitialRadiance(c, d);
}

#endif // GLINT_HYBRID_CLASSIFY_HLSLI
