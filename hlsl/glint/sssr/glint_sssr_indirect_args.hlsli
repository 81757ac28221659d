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
// Dispatch: [numthreads(1, 1, 1)], 1 group.
#ifndef GLINT_SSSR_INDIRECT_ARGS_HLSLI
#define GLINT_SSSR_INDIRECT_ARGS_HLSLI

#include "glint/sssr/glint_sssr_constants.h"

uint GLINT_SSSR_LoadCounter(uint index);
void GLINT_SSSR_StoreCounter(uint index, uint value);
void GLINT_SSSR_StoreArgument(uint index, uint value);

void GLINT_SSSR_WriteIndirectArguments()
{
    uint rays = GLINT_SSSR_LoadCounter(0);
    uint tiles = GLINT_SSSR_LoadCounter(2);
    // Rows of at most 1024 groups keep every dimension under the guaranteed 65535 at any size.
    uint groups = (rays + GLINT_SSSR_RAYS_PER_GROUP - 1) / GLINT_SSSR_RAYS_PER_GROUP;
    GLINT_SSSR_StoreArgument(0, min(groups, GLINT_SSSR_GROUPS_PER_ROW));
    GLINT_SSSR_StoreArgument(1, (groups + GLINT_SSSR_GROUPS_PER_ROW - 1) / GLINT_SSSR_GROUPS_PER_ROW);
    GLINT_SSSR_StoreArgument(2, 1);
    GLINT_SSSR_StoreArgument(3, tiles);
    GLINT_SSSR_StoreArgument(4, 1);
    GLINT_SSSR_StoreArgument(5, 1);
    GLINT_SSSR_StoreCounter(1, rays);
    GLINT_SSSR_StoreCounter(3, tiles);
    GLINT_SSSR_StoreCounter(0, 0);
    GLINT_SSSR_StoreCounter(2, 0);
}

#endif // GLINT_SSSR_INDIRECT_ARGS_HLSLI
