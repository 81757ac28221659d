// Constants of the hybrid reflection passes (docs/hybrid.md), compiled by both C++ and HLSL.
// Every hybrid pass takes the SSSR constants and these, in one cbuffer in that order:
//   cbuffer g_glint_constants { GLINT_SssrConstants g_glint_sssr; GLINT_HybridConstants g_glint_hybrid; };
// (the SSSR struct is 384 bytes, so these start at byte 384).
#ifndef GLINT_HYBRID_CONSTANTS_H
#define GLINT_HYBRID_CONSTANTS_H

#include "glint/common/glint_shared_types.h"

// Feedback counter: one uint per 8x8 tile, four 8-bit fields. Classification writes the "last
// frame" fields (from the history it chose for the tile); the screen-space intersection adds
// into the "this frame" fields. A traced ray counts 1 + its quad copies, so no field exceeds 64.
#define GLINT_HYBRID_FEEDBACK_HITS_SHIFT 0u
#define GLINT_HYBRID_FEEDBACK_HITS_LAST_SHIFT 8u
#define GLINT_HYBRID_FEEDBACK_MISSES_SHIFT 16u
#define GLINT_HYBRID_FEEDBACK_MISSES_LAST_SHIFT 24u

// Tile classes.
#define GLINT_HYBRID_TILE_FULL_SW 0u // every ray tries screen space first
#define GLINT_HYBRID_TILE_HALF_SW 1u // checkerboard: half the rays screen space, half ray traced
#define GLINT_HYBRID_TILE_FULL_HW 2u // every ray goes to the ray tracer

// The screen-space ray list is allocated per tile in blocks of 32 entries (32 or 64 per tile),
// so every aligned block of 32 entries belongs to one tile; unused entries hold this value.
#define GLINT_HYBRID_RAY_BLOCK 32u
#define GLINT_HYBRID_PADDING_ENTRY 0xFFFFFFFFu

// Counters buffer words: [0] SW rays, [1] SW rays (copy), [2] denoiser tiles, [3] tiles (copy),
// [4] HW rays, [5] HW rays (copy), [6] screen-space hits to re-shade, [7] their copy, [8] rays
// answered in screen space (statistics: with [5], the share of rays ray traced), [9] its copy.
// The first four are the SSSR layout, so the SSSR passes and the denoiser read them unchanged.
#define GLINT_HYBRID_COUNTER_HW_RAYS 4u
#define GLINT_HYBRID_COUNTER_HW_RAYS_COPY 5u
#define GLINT_HYBRID_COUNTER_RESHADED 6u
#define GLINT_HYBRID_COUNTER_RESHADED_COPY 7u
#define GLINT_HYBRID_COUNTER_SCREEN_SPACE_ANSWERS 8u
#define GLINT_HYBRID_COUNTER_SCREEN_SPACE_ANSWERS_COPY 9u
#define GLINT_HYBRID_COUNTER_WORDS 10
// Indirect arguments words: [0..2] SW intersection, [3..5] denoiser, [6..8] HW trace, [9..11]
// deferred shading (the ray-traced rays and the re-shaded screen-space hits).
#define GLINT_HYBRID_ARGUMENT_WORDS 12
#define GLINT_HYBRID_HW_ARGUMENTS_OFFSET 24    // bytes
#define GLINT_HYBRID_SHADE_ARGUMENTS_OFFSET 36 // bytes

// Flags.
#define GLINT_HYBRID_FLAG_SCREEN_SPACE 1u   // screen-space tracing on (off: every ray is ray traced)
#define GLINT_HYBRID_FLAG_RAY_TRACING 2u    // ray tracing on (off: every ray stays in screen space)
#define GLINT_HYBRID_FLAG_FEEDBACK 4u       // tile classes from the feedback (off: every tile FULL_SW)
#define GLINT_HYBRID_FLAG_ALTERNATE_CHECKER 8u // HALF_SW's checkerboard flips every frame
// Read by glint's entry files' GLINT_HYBRID_MaterialRoute, an example of a per-material
// override: mirrors (alpha below the SSSR mirror threshold) always ray traced.
#define GLINT_HYBRID_FLAG_MIRRORS_RAY_TRACED 16u
// Screen-space hits are shaded by the application's shading pass (GLINT_HYBRID_ShadeScreenHit),
// like ray-traced ones, instead of taking the colour buffer's radiance.
#define GLINT_HYBRID_FLAG_RESHADE 32u

#ifdef __cplusplus
namespace glint::shaders {
GLINT_SHARED_USING;
#endif

GLINT_CONSTANTS_BEGIN(GLINT_HybridConstants)
    uint2 tiles;                  // ceil(W / 8) x ceil(H / 8)
    uint flags;                   // GLINT_HYBRID_FLAG_*
    uint frameIndex;              // drives the per-tile lottery (an integer hash of tile and frame)
    float spawnRate;              // s: chance that a tile without statistics tries screen space
    float missWeight;             // w: cost of a miss against a hit in the decision u <= s + h - w m
    float rayTracingThreshold;    // alpha: at or above, rays stay in screen space (no ray tracing)
    float confidenceThreshold;    // a screen-space hit below this confidence is ray traced instead
    float maxRayDistance;         // world units: the ray tracer's t_max (environment beyond it)
    float rayOffset;              // world units: origin offset along the normal for ray tracing
    float thicknessRoughnessGrowth; // screen-space thickness scales by (1 + this * alpha)
    float thicknessDistanceGrowth;  // plus this times the ray's view-space length to the hit
GLINT_CONSTANTS_END(GLINT_HybridConstants);

#ifdef __cplusplus
static_assert(sizeof(GLINT_HybridConstants) == 48);
} // namespace glint::shaders
#endif

#endif // GLINT_HYBRID_CONSTANTS_H
