// glint hybrid reflections, pass 5: the ray tracer's and the shading pass's indirect arguments
// (docs/hybrid.md), after the screen-space intersection has appended its misses and its hits to
// re-shade. Counter 4 (classification's and the intersection's ray-traced rays) becomes the
// tracing arguments at words 6..8, counters 4 + 6 (the re-shaded hits) the shading arguments at
// words 9..11, each (min(g, 1024), ceil(g / 1024), 1) for g = ceil(rays / 64) as the SSSR
// intersection's; counters 5, 7 and 9 keep counters 4, 6 and 8, which are zero again.
//
// Integration: the callbacks of glint_sssr_indirect_args.hlsli (counter indices 4 to 9,
// argument indices 6..11). Entry: GLINT_HYBRID_WriteRayTracedArguments() from one thread.
// Dispatch: [numthreads(1, 1, 1)], 1 group.
#ifndef GLINT_HYBRID_INDIRECT_ARGS_HLSLI
#define GLINT_HYBRID_INDIRECT_ARGS_HLSLI

#include "glint/hybrid/glint_hybrid_constants.h"
#include "glint/sssr/glint_sssr_indirect_args.hlsli"

void GLINT_HYBRID_WriteRayTracedArguments()
{
    uint rays = GLINT_SSSR_LoadCounter(GLINT_HYBRID_COUNTER_HW_RAYS);
    uint reshaded = GLINT_SSSR_LoadCounter(GLINT_HYBRID_COUNTER_RESHADED);
    GLINT_SSSR_StoreRayArguments(GLINT_HYBRID_HW_ARGUMENTS_OFFSET / 4, rays);
    GLINT_SSSR_StoreRayArguments(GLINT_HYBRID_SHADE_ARGUMENTS_OFFSET / 4, rays + reshaded);
    GLINT_SSSR_StoreCounter(GLINT_HYBRID_COUNTER_HW_RAYS_COPY, rays);
    GLINT_SSSR_StoreCounter(GLINT_HYBRID_COUNTER_HW_RAYS, 0);
    GLINT_SSSR_StoreCounter(GLINT_HYBRID_COUNTER_RESHADED_COPY, reshaded);
    GLINT_SSSR_StoreCounter(GLINT_HYBRID_COUNTER_RESHADED, 0);
    uint answers = GLINT_SSSR_LoadCounter(GLINT_HYBRID_COUNTER_SCREEN_SPACE_ANSWERS);
    GLINT_SSSR_StoreCounter(GLINT_HYBRID_COUNTER_SCREEN_SPACE_ANSWERS_COPY, answers);
    GLINT_SSSR_StoreCounter(GLINT_HYBRID_COUNTER_SCREEN_SPACE_ANSWERS, 0);
}

#endif // GLINT_HYBRID_INDIRECT_ARGS_HLSLI
