// Constants of the G-buffer preparation passes, compiled by both C++ and HLSL.
#ifndef GLINT_GBUFFER_CONSTANTS_H
#define GLINT_GBUFFER_CONSTANTS_H

#include "glint/common/glint_shared_types.h"

#ifdef __cplusplus
namespace glint::shaders {
GLINT_SHARED_USING;
#endif

GLINT_CONSTANTS_BEGIN(GLINT_GBufferRoughnessConstants)
    uint2 size;            // render size in pixels; threads outside it do nothing
    uint materialChannel;  // 0..3, the channel of the material texture that holds roughness
    uint inputIsPerceptual; // 1: the channel holds perceptual roughness r, output r*r; 0: alpha
GLINT_CONSTANTS_END(GLINT_GBufferRoughnessConstants);

#ifdef __cplusplus
static_assert(sizeof(GLINT_GBufferRoughnessConstants) == 16);
static_assert(offsetof(GLINT_GBufferRoughnessConstants, materialChannel) == 8);
static_assert(offsetof(GLINT_GBufferRoughnessConstants, inputIsPerceptual) == 12);
} // namespace glint::shaders
#endif

#endif // GLINT_GBUFFER_CONSTANTS_H
