// Constants of the shadow denoiser passes, compiled by both C++ and HLSL. The host fills them
// from glint::planShadowDenoiser (host/src/core/shadow_denoiser_passes.cpp).
#ifndef GLINT_SHADOW_DENOISER_CONSTANTS_H
#define GLINT_SHADOW_DENOISER_CONSTANTS_H

#include "glint/common/glint_shared_types.h"
#include "glint/common/glint_wire_formats.h"

// The visibility mask: one 32-bit word per 8x4 pixel tile (docs/shadow_denoiser.md).
#define GLINT_SHADOW_DENOISER_MASK_TILE_WIDTH 8
#define GLINT_SHADOW_DENOISER_MASK_TILE_HEIGHT 4
// A prepare group of 32x8 threads packs 8x8 mask tiles (64x32 pixels), four threads per mask
// tile (one pixel row each).
#define GLINT_SHADOW_DENOISER_PREPARE_GROUP_WIDTH 32
#define GLINT_SHADOW_DENOISER_PREPARE_GROUP_HEIGHT 8
#define GLINT_SHADOW_DENOISER_PREPARE_GROUP_TILES_X 8
// A group of classification's tiles part works on 2x2 tiles of 8x8 pixels, one per
// groupThreadId.z (the other parts on one): a quarter of the groups, so that starting them no
// longer bounds the pass over mostly clear tiles (larger blocks do not pay: docs/performance.md).
#define GLINT_SHADOW_DENOISER_CLASSIFY_TILE_BLOCKS_X 2
#define GLINT_SHADOW_DENOISER_CLASSIFY_TILE_BLOCKS_Y 2
#define GLINT_SHADOW_DENOISER_CLASSIFY_TILE_BLOCKS (GLINT_SHADOW_DENOISER_CLASSIFY_TILE_BLOCKS_X * GLINT_SHADOW_DENOISER_CLASSIFY_TILE_BLOCKS_Y)
// The filter works on 8x8 pixel tiles with a 4-pixel apron (step 4 x radius 1).
#define GLINT_SHADOW_DENOISER_FILTER_TILE 8
#define GLINT_SHADOW_DENOISER_FILTER_APRON 4
// The penumbra width (pixels) an unknown blocker stands for: beyond the largest step + 1, so
// the filter's full footprint.
#define GLINT_SHADOW_DENOISER_FULL_PENUMBRA 64.0
// Classification's hard-shadow test (docs/shadow_denoiser.md, "Hard shadows pass through"): a
// receiver whose (2 HARD_RADIUS + 1)^2 neighbourhood implies no penumbra wider than HARD_WIDTH
// pixels outputs its own sample. Wider than the filter's 5 x 5, so that the lit pixels at the edge of a
// wide penumbra are rarely taken for hard (every pixel within the radius must be lit), and so
// that a pixel classification passes through takes no filter tap either.
#define GLINT_SHADOW_DENOISER_HARD_RADIUS 4
// The widest penumbra (pixels) a hard pixel's neighbourhood may imply: one pixel. Under it the
// one sample is right but where a pixel centre falls inside the penumbra, and a history there
// trails a moving shadow (docs/shadow_denoiser.md, "Hard shadows pass through").
#define GLINT_SHADOW_DENOISER_HARD_WIDTH 1.0

#ifdef __cplusplus
namespace glint::shaders {
GLINT_SHARED_USING;
#endif

GLINT_CONSTANTS_BEGIN(GLINT_ShadowDenoiserPrepareConstants)
    uint2 inputSize;  // W x H of the visibility input
    uint maskTilesX;  // ceil(W / 8): words per mask row
    uint maskTilesY;  // ceil(H / 4): mask rows
GLINT_CONSTANTS_END(GLINT_ShadowDenoiserPrepareConstants);

// viewDepth = (A, B, C, 0) = GLINT_ViewDepthCoefficients(reversed, n, f) of
// glint/common/glint_view_depth.h, n and f the near and far planes: standard
// (n f / (f - n), f / (f - n), -1); reversed (n f / (f - n), n / (f - n), 1); reversed with an
// infinite far plane (n, 0, 1).
GLINT_CONSTANTS_BEGIN(GLINT_ShadowDenoiserFilterConstants)
    uint2 inputSize;         // W x H
    uint step;               // a-trous tap spacing in pixels: 1, 2 or 4
    uint finalPass;          // 1: apply FidelityFX's contrast remap to the mean (opt-in, biased)
    float4 viewDepth;        // (A, B, C, 0): view depth z = A / (B + C d) of device depth d
    float2 normalUnpack;     // (mul, add): n = normalize(raw.xyz * mul + add)
    float depthSigma;        // relative depth edge stop: exp(-|z_c - z_q| / (depthSigma z_c))
    float normalPower;       // normal edge stop: max(0, N_c . N_q)^normalPower
    // Penumbra width in pixels per unit of blocker distance / receiver view depth:
    // 2 tan(light angular radius) / (pixel angular size); negative: no estimate (every pixel
    // takes the full filter); 0: a light of size 0 (no pixel takes a tap). See
    // glint_shadow_denoiser_penumbra.hlsli.
    float penumbraScale;
    uint padding0;           // the struct is whole 16-byte registers
    uint padding1;
    uint padding2;
GLINT_CONSTANTS_END(GLINT_ShadowDenoiserFilterConstants);

// Temporal accumulation (docs/shadow_denoiser.md, "Convergence"): the history is clamped to
// mu +- CLAMP_SIGMAS sigma_s of the 17x17 statistics, blended with alpha = max(1/n, 1/HISTORY_CAP),
// and the variance stored for the filter's edge stop is storedVarianceScale
// (ShadowDenoiserDesc::storedVarianceScale) times the variance of the accumulated mean.
#define GLINT_SHADOW_DENOISER_CLAMP_SIGMAS 2.0
#define GLINT_SHADOW_DENOISER_HISTORY_CAP 64.0
// A history younger than 16 frames lends the filter at least the binomial variance of this
// frame's 5x5 samples (not the 17x17 window's); a first sample takes FIRST_SAMPLE_VARIANCE times
// it, at most 1 (docs/shadow_denoiser.md, "The first samples beside a narrow penumbra").
#define GLINT_SHADOW_DENOISER_FIRST_SAMPLE_VARIANCE 4.0
// Anti-lag (docs/shadow_denoiser.md, "Convergence"): this frame's mask bits in a
// (2 RADIUS + 1)^2 window against last frame's accumulated shadow of the same window; when the
// larger of two binomial scores (with SLACK samples of slack; neighbours within DEPTH relative
// view depth) exceeds THRESHOLD sigmas, the history length is capped at
// LENGTH / (z - THRESHOLD)^2.
#define GLINT_SHADOW_DENOISER_ANTILAG_RADIUS 2
#define GLINT_SHADOW_DENOISER_ANTILAG_THRESHOLD 1.5
#define GLINT_SHADOW_DENOISER_ANTILAG_SLACK 1.0
#define GLINT_SHADOW_DENOISER_ANTILAG_DEPTH 0.1
#define GLINT_SHADOW_DENOISER_ANTILAG_LENGTH 4.0

// Tile metadata bits (one word per 8x8 tile): the wire format of glint/common/glint_wire_formats.h.
#define GLINT_SHADOW_DENOISER_TILE_CLEAR GLINT_WIRE_SHADOW_TILE_CLEAR
#define GLINT_SHADOW_DENOISER_TILE_LIGHT GLINT_WIRE_SHADOW_TILE_LIGHT

// Classification flags. RESET: camera cut or first frame, every history is ignored.
#define GLINT_SHADOW_DENOISER_CLASSIFY_FLAG_RESET 1u
// ANTI_LAG: the 5x5 anti-lag test shortens contradicted histories (docs/shadow_denoiser.md).
#define GLINT_SHADOW_DENOISER_CLASSIFY_FLAG_ANTI_LAG 4u
// REBUILD_CLEAR: clear tiles store no moments. Their history is rebuilt from last frame's tile
// metadata and previous depth instead: (v, 0, receiver, v) with v = LIGHT && receiver, exactly
// what they would have stored. Saves 16 bytes a pixel of writes in every clear tile. Set it on
// every frame of a sequence or on none (a frame that stores nothing for a clear tile cannot be
// followed by one that reads the stored value).
#define GLINT_SHADOW_DENOISER_CLASSIFY_FLAG_REBUILD_CLEAR 8u

// Matrices are column-vector (q = M p) and passed as four rows: q.i = dot(row_i, p).
// Every field's formula (all three structs): docs/integration.md.
GLINT_CONSTANTS_BEGIN(GLINT_ShadowDenoiserClassifyConstants)
    uint2 inputSize;
    uint2 maskTiles;            // ceil(W / 8) x ceil(H / 4)
    float4 reproject[4];        // R_reproj = VP_prev VP^-1: current NDC (x_n, y_n, d, 1) -> previous clip
    float4 inverseViewProj[4];  // VP^-1: current NDC -> world (homogeneous)
    float4 eyePosition;         // xyz: world-space eye; w: unused (0)
    float4 viewDepth;           // (A, B, C, 0): view depth z = A / (B + C d), both frames
    float2 normalUnpack;        // (mul, add)
    float ndcYSign;             // y_n = ndcYSign (2 v - 1): +1 Vulkan-style, -1 D3D-style
    uint flags;                 // GLINT_SHADOW_DENOISER_CLASSIFY_FLAG_*
    float storedVarianceScale;  // times the variance of the accumulated mean, stored for the filter
    float penumbraScale;        // as the filter's: < 0 no estimate; hard pixels pass through
    uint padding1;              // the struct is whole 16-byte registers
    uint padding2;
GLINT_CONSTANTS_END(GLINT_ShadowDenoiserClassifyConstants);

#ifdef __cplusplus
static_assert(sizeof(GLINT_ShadowDenoiserClassifyConstants) == 208);
static_assert(offsetof(GLINT_ShadowDenoiserClassifyConstants, reproject) == 16);
static_assert(offsetof(GLINT_ShadowDenoiserClassifyConstants, eyePosition) == 144);
static_assert(offsetof(GLINT_ShadowDenoiserClassifyConstants, normalUnpack) == 176);
static_assert(offsetof(GLINT_ShadowDenoiserClassifyConstants, flags) == 188);
static_assert(offsetof(GLINT_ShadowDenoiserClassifyConstants, storedVarianceScale) == 192);
static_assert(offsetof(GLINT_ShadowDenoiserClassifyConstants, penumbraScale) == 196);
static_assert(sizeof(GLINT_ShadowDenoiserPrepareConstants) == 16);
static_assert(sizeof(GLINT_ShadowDenoiserFilterConstants) == 64);
static_assert(offsetof(GLINT_ShadowDenoiserFilterConstants, penumbraScale) == 48);
static_assert(offsetof(GLINT_ShadowDenoiserFilterConstants, viewDepth) == 16);
static_assert(offsetof(GLINT_ShadowDenoiserFilterConstants, normalUnpack) == 32);
} // namespace glint::shaders
#endif

#endif // GLINT_SHADOW_DENOISER_CONSTANTS_H
