// Constants of the stochastic screen-space reflection passes (classify, blue noise, indirect
// arguments, intersect, composite), compiled by both C++ and HLSL. One struct serves every
// pass so that the host fills it once per frame (host/src/core/sssr_passes.cpp).
#ifndef GLINT_SSSR_CONSTANTS_H
#define GLINT_SSSR_CONSTANTS_H

#include "glint/common/glint_shared_types.h"

// Classification and the denoiser work on 8x8 tiles; the intersection traces one ray per
// thread in groups of 64.
#define GLINT_SSSR_TILE 8
#define GLINT_SSSR_RAYS_PER_GROUP 64
// The intersection's indirect grid is (min(groups, 1024), ceil(groups / 1024), 1): ray index =
// (group.y * 1024 + group.x) * 64 + thread.
#define GLINT_SSSR_GROUPS_PER_ROW 1024u
#define GLINT_SSSR_BLUE_NOISE_SIZE 128
// Ray-list entry: x in bits 0-14, y in bits 15-28, copy flags in 29 (x^1), 30 (y^1), 31 (both).
#define GLINT_SSSR_RAY_COPY_H 0x20000000u
#define GLINT_SSSR_RAY_COPY_V 0x40000000u
#define GLINT_SSSR_RAY_COPY_D 0x80000000u
// Counters buffer: [0] rays (accumulating), [1] rays (copy), [2] tiles (accumulating), [3] tiles (copy).
#define GLINT_SSSR_COUNTER_WORDS 4
// Indirect arguments buffer: [0..2] intersection, [3..5] denoiser (byte offset 12).
#define GLINT_SSSR_ARGUMENT_WORDS 6
// The documented "infinite" hit distance of misses and environment samples: parallax at
// infinity is rotation-only reprojection. Representable in fp16 (its largest finite value).
#define GLINT_SSSR_MISS_DISTANCE 65504.0
// Depth-pyramid levels the traversal uses (level 0 is the input depth itself).
#define GLINT_SSSR_PYRAMID_LEVELS 7

// Flags.
#define GLINT_SSSR_FLAG_REVERSED_DEPTH 1u
#define GLINT_SSSR_FLAG_ROUGHNESS_PERCEPTUAL 2u  // the material channel holds r (squared once here)
#define GLINT_SSSR_FLAG_VARIANCE_GUIDED 4u       // TVGT: extra rays where the reprojected variance is high
#define GLINT_SSSR_FLAG_PREVIOUS_FRAME_COLOR 8u  // hit radiance from last frame's colour through motion
#define GLINT_SSSR_FLAG_HALF_RESOLUTION 16u      // one ray per 2x2 quad, position rotating per frame
#define GLINT_SSSR_FLAG_THICKNESS_AWARE 32u      // rays may pass behind thin objects (RG32F pyramid)

// Debug classes written by the intersection's debug permutation (docs/sssr.md).
#define GLINT_SSSR_RAY_HIT 0u
#define GLINT_SSSR_RAY_ESCAPED 1u    // left the screen or passed the segment's end
#define GLINT_SSSR_RAY_BUDGET 2u     // iteration budget exhausted
#define GLINT_SSSR_RAY_OCCUPANCY 3u  // stopped by the low-occupancy exit
#define GLINT_SSSR_RAY_BEHIND 4u     // hit a surface from behind (back-facing)
#define GLINT_SSSR_RAY_REJECTED 5u   // hit off screen, on the background or without advancing
#define GLINT_SSSR_RAY_DEGENERATE 6u // no screen-space progress: not marched

#ifdef __cplusplus
namespace glint::shaders {
GLINT_SHARED_USING;
#endif

// Matrices are column-vector (q = M p) and passed as four rows: q.i = dot(row_i, p).
// viewDepth = (A, B, C, 0) = GLINT_ViewDepthCoefficients(reversed, n, f) of
// glint/common/glint_view_depth.h, n and f the near and far planes: standard
// (n f / (f - n), f / (f - n), -1); reversed (n f / (f - n), n / (f - n), 1); reversed with an
// infinite far plane (n, 0, 1).
// Every field's formula: docs/integration.md.
GLINT_CONSTANTS_BEGIN(GLINT_SssrConstants)
    uint2 inputSize;              // W x H
    float2 inverseInputSize;      // 1 / (W, H)
    float4 clipFromView[4];       // P, unjittered
    float4 viewFromClip[4];       // P^-1
    float4 viewFromWorld[4];      // V (rigid)
    float4 worldFromView[4];      // V^-1
    float4 viewDepth;             // (A, B, C, 0): view depth z = A / (B + C d) of device depth d
    float2 normalUnpack;          // (mul, add): n = normalize(raw.xyz * mul + add)
    float ndcYSign;               // y_n = ndcYSign (2 v - 1): +1 Vulkan-style, -1 D3D-style
    uint flags;                   // GLINT_SSSR_FLAG_*
    uint materialChannel;         // 0..3: the material channel holding roughness
    uint samplesPerQuad;          // 1, 2 or 4
    uint frameIndex;              // drives the blue noise and the half-resolution rotation
    uint maxIterations;           // traversal budget
    float roughnessThreshold;     // alpha: no ray at or above
    float mirrorThreshold;        // alpha: below it a pixel is a mirror (always traced, level 0)
    float roughnessFadeBand;      // alpha: traced results fade to the environment over [threshold - band, threshold)
    float varianceThreshold;      // TVGT: extra ray above this reprojected variance
    float thickness;              // relative to the surface's view depth
    float thicknessFloor;         // absolute floor of the thickness, view-depth units
    float importanceSampleBias;   // 0..1: shrinks the VNDF cap-height variable (Frostbite)
    float iblFactor;              // scales every environment sample
    uint mostDetailedMip;         // finest pyramid level for non-mirror rays
    uint minActiveRays;           // low-occupancy exit: non-mirror rays stop when at most this many of the group's 64 remain; 0 = off
    float environmentTexelSolidAngle; // steradians of one texel of the environment's level 0
    float environmentMaxLod;      // the environment's last level
    float nearPlane;              // view depth (clip w) of the near plane
    float farPlane;               // view depth of the far plane; 0: infinite
    float2 motionScale;           // convention A after scaling: uv_prev = uv + motionScale * mv
GLINT_CONSTANTS_END(GLINT_SssrConstants);

#ifdef __cplusplus
static_assert(sizeof(GLINT_SssrConstants) == 384);
static_assert(offsetof(GLINT_SssrConstants, clipFromView) == 16);
static_assert(offsetof(GLINT_SssrConstants, viewDepth) == 272);
static_assert(offsetof(GLINT_SssrConstants, normalUnpack) == 288);
static_assert(offsetof(GLINT_SssrConstants, motionScale) == 376);
} // namespace glint::shaders
#endif

#endif // GLINT_SSSR_CONSTANTS_H
