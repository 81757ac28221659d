// glint hybrid reflections, pass 5: the ray tracer's indirect arguments (docs/hybrid.md), after
// the screen-space intersection has appended its misses. Counter 4 (classification's and the
// intersection's ray-traced rays) becomes the dispatch arguments at words 6..8, (min(g, 1024),
// ceil(g / 1024), 1) for g = ceil(rays / 64) as the SSSR intersection's; counter 5 keeps the
// count and counter 4 is zero again.
//
// Integration: the callbacks of glint_sssr_indirect_args.hlsli (counter indices 4 and 5,
// argument indices 6..8). Entry: GLINT_HYBRID_WriteRayTracedArguments() from one thread.
// Dispatch: [numthreads(1, 1, 1)], 1 group.
#ifndef GLINT_HYBRID_INDIRECT_ARGS_HLSLI
#define GLINT_HYBRID_INDIRECT_ARGS_HLSLI

#include "glint/hybrid/glint_hybrid_constants.h"
#include "glint/sssr/glint_sssr_indirect_args.hlsli"

void GLINT_HYBRID_WriteRayTracedArguments()
{
    uint rays = GLINT_SSSR_LoadCounter(GLINT_HYBRID_COUNTER_HW_RAYS);
    uint groups = (rays + GLINT_SSSR_RAYS_PER_GROUP - 1) / GLINT_SSSR_RAYS_PER_GROUP;
    GLINT_SSSR_StoreArgument(6, min(groups, GLINT_SSSR_GROUPS_PER_ROW));
    GLINT_SSSR_StoreArgument(7, (groups + GLINT_SSSR_GROUPS_PER_ROW - 1) / GLINT_SSSR_GROUPS_PER_ROW);
    GLINT_SSSR_StoreArgument(8, 1);
    GLINT_SSSR_StoreCounter(GLINT_HYBRID_COUNTER_HW_RAYS_COPY, rays);
    GLINT_SSSR_StoreCounter(GLINT_HYBRID_COUNTER_HW_RAYS, 0);
}

#endif // GLINT_HYBRID_INDIRECT_ARGS_HLSLI
