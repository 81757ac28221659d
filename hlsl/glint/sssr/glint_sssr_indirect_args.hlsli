// glint SSSR, pass 4: indirect arguments (docs/sssr.md). Turns the classification's
// accumulating counters into dispatch arguments, keeps a copy for the passes that read the
// counts, and resets the accumulators for the next frame: the host never resets them
// mid-frame. A frame with no glossy pixel dispatches zero groups.
//
// Integration: define these callbacks before or after including this header.
//
//   uint GLINT_SSSR_LoadCounter(uint index);               index 0..3
//   void GLINT_SSSR_StoreCounter(uint index, uint value);
//   void GLINT_SSSR_StoreArgument(uint index, uint value);  index 0..5
//
// Arguments: [0..2] the intersection's (min(g, 1024), ceil(g / 1024), 1), g = ceil(rays / 64);
// [3..5] the reflections denoiser's (tiles, 1, 1), byte offset 12. Counters: [1] and [3] keep
// this frame's ray and tile counts; [0] and [2] are zero again afterwards.
//
// Entry: GLINT_SSSR_WriteIndirectArguments() from one thread, after classification; no
// constants. Dispatch: [numthreads(1, 1, 1)], 1 group, or (as glint's sssr_blue_noise entry
// does) from thread (0, 0) of the blue-noise dispatch. Integration guide: docs/integration.md.
#ifndef GLINT_SSSR_INDIRECT_ARGS_HLSLI
#define GLINT_SSSR_INDIRECT_ARGS_HLSLI

#include "glint/sssr/glint_sssr_constants.h"

uint GLINT_SSSR_LoadCounter(uint index);
void GLINT_SSSR_StoreCounter(uint index, uint value);
void GLINT_SSSR_StoreArgument(uint index, uint value);

// The dispatch of one thread per ray, 64 per group, at arguments firstArgument..+2. Rows of at
// most 1024 groups keep every dimension under the guaranteed 65535 at any size.
void GLINT_SSSR_StoreRayArguments(uint firstArgument, uint rays)
{
    uint groups = (rays + GLINT_SSSR_RAYS_PER_GROUP - 1) / GLINT_SSSR_RAYS_PER_GROUP;
    GLINT_SSSR_StoreArgument(firstArgument, min(groups, GLINT_SSSR_GROUPS_PER_ROW));
    GLINT_SSSR_StoreArgument(firstArgument + 1, (groups + GLINT_SSSR_GROUPS_PER_ROW - 1) / GLINT_SSSR_GROUPS_PER_ROW);
    GLINT_SSSR_StoreArgument(firstArgument + 2, 1);
}

void GLINT_SSSR_WriteIndirectArguments()
{
    uint rays = GLINT_SSSR_LoadCounter(0);
    uint tiles = GLINT_SSSR_LoadCounter(2);
    GLINT_SSSR_StoreRayArguments(0, rays);
    GLINT_SSSR_StoreArgument(3, tiles);
    GLINT_SSSR_StoreArgument(4, 1);
    GLINT_SSSR_StoreArgument(5, 1);
    GLINT_SSSR_StoreCounter(1, rays);
    GLINT_SSSR_StoreCounter(3, tiles);
    GLINT_SSSR_StoreCounter(0, 0);
    GLINT_SSSR_StoreCounter(2, 0);
}

#endif // GLINT_SSSR_INDIRECT_ARGS_HLSLI
