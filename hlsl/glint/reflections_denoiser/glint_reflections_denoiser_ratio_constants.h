// Constants of the reflections denoiser's optional ratio-estimator path (reconstruct and
// cleanup passes), compiled by both C++ and HLSL: the denoiser's common constants followed by
// what only this path needs. The host fills them in host/src/core/reflections_denoiser_passes.cpp.
#ifndef GLINT_REFLECTIONS_DENOISER_RATIO_CONSTANTS_H
#define GLINT_REFLECTIONS_DENOISER_RATIO_CONSTANTS_H

#include "glint/reflections_denoiser/glint_reflections_denoiser_constants.h"

// Farthest pixel offset of a reconstruction tap: reconstructionRadius is clamped to it.
#define GLINT_RD_RATIO_MAX_RADIUS 8.0

#ifdef __cplusplus
namespace glint::shaders {
GLINT_SHARED_USING;
#endif

GLINT_CONSTANTS_BEGIN(GLINT_ReflectionsDenoiserRatioConstants)
    GLINT_ReflectionsDenoiserConstants common;
    float4 worldFromView[3];    // rotation rows of V^-1 (w unused): view-space -> world directions
    uint frameIndex;            // rotates the reconstruction taps every frame
    float reconstructionRadius; // R_max in pixels (DiligentFX: 4, range 2..8)
    float cleanupSigma;         // spatial sigma of the bilateral cleanup in pixels (0.9)
    float reserved;
GLINT_CONSTANTS_END(GLINT_ReflectionsDenoiserRatioConstants);

#ifdef __cplusplus
static_assert(sizeof(GLINT_ReflectionsDenoiserRatioConstants) == 272);
static_assert(offsetof(GLINT_ReflectionsDenoiserRatioConstants, worldFromView) == 208);
static_assert(offsetof(GLINT_ReflectionsDenoiserRatioConstants, frameIndex) == 256);
} // namespace glint::shaders
#endif

#endif // GLINT_REFLECTIONS_DENOISER_RATIO_CONSTANTS_H
