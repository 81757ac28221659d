// glint hybrid reflections: what every hybrid pass shares (docs/hybrid.md) — the feedback
// counter's fields, the per-tile lottery, the decision rule and the ray routes. Has no
// callbacks of its own.
#ifndef GLINT_HYBRID_COMMON_HLSLI
#define GLINT_HYBRID_COMMON_HLSLI

#include "glint/hybrid/glint_hybrid_constants.h"

// GLINT_HYBRID_MaterialRoute results.
#define GLINT_HYBRID_ROUTE_AUTO 0u
#define GLINT_HYBRID_ROUTE_RAY_TRACED 1u
#define GLINT_HYBRID_ROUTE_SCREEN_SPACE 2u

uint GLINT_HYBRID_Hits(uint counter) { return (counter >> GLINT_HYBRID_FEEDBACK_HITS_SHIFT) & 0xFFu; }
uint GLINT_HYBRID_LastHits(uint counter) { return (counter >> GLINT_HYBRID_FEEDBACK_HITS_LAST_SHIFT) & 0xFFu; }
uint GLINT_HYBRID_Misses(uint counter) { return (counter >> GLINT_HYBRID_FEEDBACK_MISSES_SHIFT) & 0xFFu; }
uint GLINT_HYBRID_LastMisses(uint counter) { return (counter >> GLINT_HYBRID_FEEDBACK_MISSES_LAST_SHIFT) & 0xFFu; }

// A counter's fresh fields moved to its "last frame" fields, the fresh ones cleared.
uint GLINT_HYBRID_Age(uint counter)
{
    return (GLINT_HYBRID_Hits(counter) << GLINT_HYBRID_FEEDBACK_HITS_LAST_SHIFT) |
           (GLINT_HYBRID_Misses(counter) << GLINT_HYBRID_FEEDBACK_MISSES_LAST_SHIFT);
}

// PCG's output permutation of an LCG step: an integer hash, so the per-tile pattern does not
// degrade as the frame index grows (docs/conventions.md, defect HR6).
uint GLINT_HYBRID_Hash(uint x)
{
    uint state = x * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// The per-tile, per-frame random word.
uint GLINT_HYBRID_TileHash(GLINT_HybridConstants h, uint2 tile, uint frame)
{
    return GLINT_HYBRID_Hash((tile.y * h.tiles.x + tile.x) ^ GLINT_HYBRID_Hash(frame));
}

// The lottery number u in [0, 1) of a tile hash (24 bits).
float GLINT_HYBRID_TileUniform(uint hash) { return float(hash >> 8) * (1.0 / 16777216.0); }

// The tile's random pixel, (0..7, 0..7) from the tile hash's low 6 bits.
uint2 GLINT_HYBRID_TilePixelOffset(uint hash) { return uint2(hash & 7u, (hash >> 3) & 7u); }

// The decision rule SW(h, m, u) := u <= s + h - w m.
bool GLINT_HYBRID_PrefersScreenSpace(GLINT_HybridConstants c, uint hits, uint misses, float u)
{
    return u <= c.spawnRate + float(hits) - c.missWeight * float(misses);
}

// HALF_SW tiles: pixels with (x ^ y) even (flipping every frame with ALTERNATE_CHECKER) go to
// screen space.
bool GLINT_HYBRID_CheckerboardScreenSpace(GLINT_HybridConstants c, uint2 pixel)
{
    uint phase = (c.flags & GLINT_HYBRID_FLAG_ALTERNATE_CHECKER) != 0 ? c.frameIndex : 0u;
    return ((pixel.x ^ pixel.y ^ phase) & 1u) == 0u;
}

// Entries a tile allocates in the screen-space list for `count` rays: 0, 32 or 64.
uint GLINT_HYBRID_ScreenSpaceAllocation(uint count)
{
    return count == 0u ? 0u : count <= GLINT_HYBRID_RAY_BLOCK ? GLINT_HYBRID_RAY_BLOCK : 2u * GLINT_HYBRID_RAY_BLOCK;
}

// The re-shaded screen-space hits fill the ray-traced list (W H entries) from its end down, so
// the ray-traced rays (from its start) and they never overlap: together they are at most one
// ray per pixel.
uint GLINT_HYBRID_ReshadedSlot(uint2 inputSize, uint index) { return inputSize.x * inputSize.y - 1u - index; }

// A screen-space hit to re-shade: the pixel it hit, the world distance along the ray to it and
// its confidence (roughness fade included).
struct GLINT_HYBRID_ScreenHit
{
    int2 pixel;
    float distance;
    float confidence;
};

// Its 16-byte record in the hit records buffer, at the same index as its list entry.
uint4 GLINT_HYBRID_PackScreenHit(GLINT_HYBRID_ScreenHit hit)
{
    return uint4(asuint(hit.distance), uint(hit.pixel.x) | (uint(hit.pixel.y) << 16), asuint(hit.confidence), 0u);
}

GLINT_HYBRID_ScreenHit GLINT_HYBRID_UnpackScreenHit(uint4 record)
{
    GLINT_HYBRID_ScreenHit hit;
    hit.distance = asfloat(record.x);
    hit.pixel = int2(record.y & 0xFFFFu, record.y >> 16);
    hit.confidence = asfloat(record.z);
    return hit;
}

#endif // GLINT_HYBRID_COMMON_HLSLI
