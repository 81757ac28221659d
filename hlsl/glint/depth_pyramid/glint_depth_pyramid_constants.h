// Constants of the depth pyramid pass, compiled by both C++ and HLSL. The host fills them
// from glint::planDepthPyramid, which is the single source of truth for the level count.
#ifndef GLINT_DEPTH_PYRAMID_CONSTANTS_H
#define GLINT_DEPTH_PYRAMID_CONSTANTS_H

#include "glint/common/glint_shared_types.h"

// Storage-image slots the entry file declares; 1 + log2(16384) levels cover the largest input.
#define GLINT_DEPTH_PYRAMID_MAX_LEVELS 15
// Levels 0..6 come from one 64x64 tile per group; coarser ones need every group's level 6.
#define GLINT_DEPTH_PYRAMID_TILE_LEVELS 7

#ifdef __cplusplus
namespace glint::shaders {
GLINT_SHARED_USING;
#endif

GLINT_CONSTANTS_BEGIN(GLINT_DepthPyramidConstants)
    uint2 inputSize;   // W x H of the depth input; texels outside it are far
    uint2 level0Size;  // W0 x H0 = (W, H) rounded up to multiples of 64
    uint levelCount;   // levels written, 1..1 + floor(log2(max(W0, H0)))
    uint groupCount;   // groups in the dispatch, for the last-group count
    float farDepth;    // device depth of the far plane: 1 standard, 0 reversed
    uint writeLevel0;  // 1: level 0 holds the sanitized, padded input; 0: left unwritten
GLINT_CONSTANTS_END(GLINT_DepthPyramidConstants);

#ifdef __cplusplus
static_assert(sizeof(GLINT_DepthPyramidConstants) == 32);
static_assert(offsetof(GLINT_DepthPyramidConstants, levelCount) == 16);
static_assert(offsetof(GLINT_DepthPyramidConstants, farDepth) == 24);
} // namespace glint::shaders
#endif

#endif // GLINT_DEPTH_PYRAMID_CONSTANTS_H
