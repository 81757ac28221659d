// Constants of the reflections denoiser passes (reproject, prefilter, resolve), compiled by
// both C++ and HLSL. The host fills them in host/src/core/reflections_denoiser_passes.cpp.
#ifndef GLINT_REFLECTIONS_DENOISER_CONSTANTS_H
#define GLINT_REFLECTIONS_DENOISER_CONSTANTS_H

#include "glint/common/glint_shared_types.h"

// Every pass works on the 8x8 tiles SSSR's classification listed, one group per tile, with a
// 4-pixel apron in groupshared memory (16 x 16 pixels).
#define GLINT_RD_TILE 8
#define GLINT_RD_APRON 4
#define GLINT_RD_SPAN 16
// Tile masks hold one word per tile, zeroed by the host before reproject marks it: bit
// dy * 2 + dx of tile t's word is set when tile t + (dx, dy), dx, dy in {0, 1}, was listed. Bit 0
// is the tile's own; one word answers for the 2x2 tiles a bilinear history footprint touches.
#define GLINT_RD_MASK_SELF 1u
// The hit distance SSSR writes for misses ("infinite": rotation-only parallax).
#define GLINT_RD_MISS_DISTANCE 65504.0
// The alpha reproject stores in the clamped sample, and the prefilter (or the reconstruction)
// in the prefiltered radiance, for pixels that are not glossy. Glossy pixels store their
// variance there, which is never negative; so the next pass learns a span pixel's glossiness
// from a fetch it makes anyway instead of 3 surface fetches (depth, normal, roughness). It holds
// only in tiles listed this frame: the others keep stale values, so the reader also tests this
// frame's tile mask.
#define GLINT_RD_NOT_GLOSSY (-1.0)

#define GLINT_RD_FLAG_REVERSED_DEPTH 1u
#define GLINT_RD_FLAG_RESET 2u // camera cut, resize or first frame: every history is ignored
#define GLINT_RD_FLAG_ANTI_LAG 4u // the resolve shortens histories this frame's samples contradict

// The resolve's anti-lag (docs/reflections_denoiser.md, "Resolve"): over the 9x9 Gaussian
// neighbourhood, the mean luminance difference between the reprojected histories and this
// frame's prefiltered samples is compared with what noise explains,
//   tolerance = NOISE * luma(sigma) + RELATIVE * luma(mean) + FLOOR,
// sigma and mean the neighbourhood's statistics of the prefiltered radiance. NOISE stands for
// k / sqrt(N): k = 3 standard deviations of a mean of about N = 9 independent samples, which is
// what the correlated neighbourhood holds (one ray per 2x2 quad, spread further by the
// prefilter's 3-pixel reach); sigma also counts the reflection's own detail, so the test is
// conservative at edges. RELATIVE and FLOOR keep tiny differences of bright and of black
// neighbourhoods below it. Beyond the tolerance, by the factor e, the history length n
// becomes max(1, n / e^2).
#define GLINT_RD_ANTI_LAG_NOISE 1.0
#define GLINT_RD_ANTI_LAG_RELATIVE 0.1
#define GLINT_RD_ANTI_LAG_FLOOR 0.001

#ifdef __cplusplus
namespace glint::shaders {
GLINT_SHARED_USING;
#endif

// Matrices are column-vector (q = M p) and passed as four rows.
// viewDepth = (A, B, C, 0) = GLINT_ViewDepthCoefficients(reversed, n, f) of
// glint/common/glint_view_depth.h, n and f the near and far planes: standard
// (n f / (f - n), f / (f - n), -1); reversed (n f / (f - n), n / (f - n), 1); reversed with an
// infinite far plane (n, 0, 1).
// Every field's formula: docs/integration.md.
GLINT_CONSTANTS_BEGIN(GLINT_ReflectionsDenoiserConstants)
    uint2 inputSize;              // W x H
    float2 inverseInputSize;
    float4 viewFromClip[4];       // P^-1 of this frame
    float4 previousClipFromView[4]; // VP_prev V^-1: this frame's view space -> last frame's clip
    float4 viewDepth;             // (A, B, C, 0): view depth z = A / (B + C d), both frames
    float2 normalUnpack;          // (mul, add)
    float ndcYSign;               // y_n = ndcYSign (2 v - 1)
    uint flags;                   // GLINT_RD_FLAG_*
    float2 motionScale;           // uv_prev = uv + motionScale * mv
    uint2 tiles;                  // ceil(W / 8) x ceil(H / 8)
    float roughnessThreshold;     // alpha: glossy below (the value SSSR classified with)
    float mirrorThreshold;        // alpha: no spatial filter below
    float historyClipScale;       // scale of the resolve's clip box (FidelityFX "temporal stability", 0.7)
    uint maxHistoryLength;        // cap of the per-pixel history length for rough pixels (32)
GLINT_CONSTANTS_END(GLINT_ReflectionsDenoiserConstants);

#ifdef __cplusplus
static_assert(sizeof(GLINT_ReflectionsDenoiserConstants) == 208);
static_assert(offsetof(GLINT_ReflectionsDenoiserConstants, viewFromClip) == 16);
static_assert(offsetof(GLINT_ReflectionsDenoiserConstants, viewDepth) == 144);
static_assert(offsetof(GLINT_ReflectionsDenoiserConstants, motionScale) == 176);
static_assert(offsetof(GLINT_ReflectionsDenoiserConstants, roughnessThreshold) == 192);
} // namespace glint::shaders
#endif

#endif // GLINT_REFLECTIONS_DENOISER_CONSTANTS_H
