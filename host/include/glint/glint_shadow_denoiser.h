// glint public API: the ray-traced shadow denoiser (docs/shadow_denoiser.md).
//
// Input: one binary visibility sample per pixel (R32F, 1 = lit), device depth and world-space
// normals. The plan packs the visibility into a bitmask (one word per 8 x 4 pixels) and runs
// three edge-avoiding a-trous passes (steps 1, 2, 4) over (mean, variance); the last applies the
// contrast remap only when asked. Tile classification in between accumulates over time.
#pragma once

#include "glint/glint_pass.h"
#include "glint/glint_types.h"

#include <array>
#include <string>

namespace glint {

enum class ShadowDenoiserDepth : std::uint8_t {
    Standard, // near 0, far 1: z = n f / (f - d (f - n))
    Reversed, // near 1, far 0: z = n f / (n + d (f - n)); farPlane <= 0 means infinite (z = n / d)
};

struct ShadowDenoiserDesc {
    Extent2D size; // 1..16384 each
    ShadowDenoiserDepth depth = ShadowDenoiserDepth::Standard;
    float nearPlane = 0.1f;
    float farPlane = 1000.0f;
    float normalUnpackMul = 1.0f; // n = normalize(raw.xyz * mul + add); (2, -1) for UNORM normals
    float normalUnpackAdd = 0.0f;
    float depthSigma = 0.02f; // relative depth edge stop, see docs/shadow_denoiser.md
    float normalPower = 32.0f;
    bool filter = true;           // false: no filter passes
    bool classify = true;         // false: no classification; the filter reads "shadow_filter_input"
    bool skipClearedTiles = true; // with classify: the filter skips tiles classification cleared
    // The iterations with steps 1 and 2 in one dispatch ("filter01", the first over the 8x8
    // tile +- 2 pixels in groupshared memory), then "filter2"; same taps and results as
    // "filter0..2". Step 1 then runs over 144 pixels a group instead of 64, in exchange for one
    // dispatch and one scratch round trip fewer, which cost more (docs/performance.md).
    bool pairedFilter = true;
    // With the filter's tile list (skipClearedTiles): classification in two dispatches,
    // "classify" (every tile, 2x2 tiles a group: metadata, list, clear tiles' output) and
    // "temporal" (the listed tiles, indirectly). A dispatch of one tile a group over mostly
    // clear tiles is bound by the rate at which groups start, not by their work; one dispatch
    // more costs less than that (docs/performance.md). Same results.
    bool splitClassify = true;
    // FidelityFX's "contrast recovery" mean^max(1.2 - variance, 1) in the last pass. Off by
    // default: it darkens penumbrae (docs/shadow_denoiser.md, "Convergence").
    bool contrastRemap = false;
    // Classification's anti-lag test: a history its 5x5 neighbourhood contradicts is shortened,
    // so moving shadows are followed within a few frames (docs/shadow_denoiser.md, "Motion").
    // It loads up to 25 window positions a pixel in the tiles that are not clear (its cost:
    // docs/performance.md); content known to be static can turn it off.
    bool antiLag = true;
    // Clear tiles store no moments; next frame rebuilds their history from this frame's tile
    // metadata and depth (both frames' "shadow_previous_depth" must be the frame before's
    // "shadow_depth"). Same results, 16 bytes a pixel fewer writes on clear tiles.
    bool rebuildClearHistory = true;
    // Classification stores this times the variance of the accumulated mean as the variance of
    // its (shadow, variance) output, which the filter's edge stop reads: larger values keep
    // filtering settled penumbrae (less noise, more bias where they are narrow in pixels).
    // 0 (default): 1/16 up to 360 rows, growing with (rows / 360)^2 above (0.5625 at 1080p),
    // since a fixed-size kernel biases a penumbra less the more pixels it spans
    // (docs/shadow_denoiser.md, "The filter strength and the resolution").
    float storedVarianceScale = 0.0f;
    // The format of "shadow_output": R8Unorm (default), R16Float (the shadow only) or RG32Float
    // (shadow and the filter's variance, for debugging). A shadow mask needs one channel (NRD
    // recommends R8), and classification stores every clear tile's output, most of a frame: the
    // narrower the format, the fewer bytes it writes (docs/performance.md). Each format is its
    // own permutation of the passes that write the output (docs/shadow_denoiser.md, "Output
    // format").
    Format outputFormat = Format::R8Unorm;
    // The penumbra estimate (docs/shadow_denoiser.md, "Penumbra-aware filtering" and "Hard
    // shadows pass through"): a receiver's penumbra is about
    // W = blocker distance x 2 lightTanHalfAngle / (view depth x pixelAngularSize) pixels wide.
    // Classification passes a receiver whose 9 x 9 neighbourhood has no W above 1 pixel straight
    // through (its one sample is the answer: the output equals the input there), and each filter
    // pass's footprint follows W. Needs "shadow_blocker_distance" when lightTanHalfAngle > 0;
    // lightTanHalfAngle 0 (a light of angular radius 0) makes every shadow hard, so the output
    // equals the input everywhere. With lightTanHalfAngle < 0 or pixelAngularSize 0 (unknown), or
    // penumbraAware false, there is no estimate: the full temporal stage and filter everywhere.
    bool penumbraAware = true;
    // tan of the light's angular radius (half-angle): 0 a light of size 0, < 0 unknown.
    float lightTanHalfAngle = -1.0f;
    // Radians per pixel at the image centre, 2 tan(fovY / 2) / H; 0: unknown.
    float pixelAngularSize = 0.0f;

    // Classification (temporal) inputs. Matrices are row-major 4x4 with column vectors (q = M p).
    std::array<double, 16> reprojection{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; // VP_prev VP^-1
    std::array<double, 16> inverseViewProjection{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; // VP^-1
    std::array<float, 3> eyePosition{0.0f, 0.0f, 0.0f};
    bool vulkanNdc = true;        // y_n = 2v - 1 (true) or 1 - 2v (D3D-style)
    bool resetHistory = false;    // first frame, camera cut or resize: every history is ignored
    std::uint32_t frameIndex = 0; // moments and metadata ping-pong on its parity
};

// The stored variance scale a description resolves to (storedVarianceScale, or its automatic
// value for the size): the factor classification applies to the variance it stores.
float shadowStoredVarianceScale(const ShadowDenoiserDesc& desc);

// Whether the passes use the penumbra estimate: penumbraAware with a known light angle (>= 0)
// and pixel angular size (> 0).
bool shadowPenumbraKnown(const ShadowDenoiserDesc& desc);

// Whether the plan reads "shadow_blocker_distance": the estimate is known and the light has a
// size (lightTanHalfAngle > 0).
bool shadowPenumbraActive(const ShadowDenoiserDesc& desc);

// Words of the visibility mask: ceil(W / 8) x ceil(H / 4).
Extent2D shadowMaskTiles(Extent2D size);

// The tile metadata buffer frame `frameIndex` writes ("shadow_tile_metadata0" or "...1").
std::string shadowTileMetadataName(std::uint32_t frameIndex);

// Resources of the plan (application's inputs first):
//   "shadow_visibility"     R32F W x H, sampled; 1 = lit, >= 0.5 counts as lit, NaN as shadowed
//   "shadow_depth"          R32F W x H device depth
//   "shadow_previous_depth" R32F W x H last frame's device depth (the application copies it)
//   "shadow_normals"        RGBA W x H, any float format, world-space normals
//   "shadow_motion"         RG W x H, convention A: uv_prev = uv + mv
//   "shadow_filter_input"   RG32F W x H (mean, variance), only when classify is false
//   "shadow_blocker_distance" R32F (or R16F) W x H, sampled, only when shadowPenumbraActive:
//                           distance along the visibility sample's ray to its closest blocker
//                           (view-depth units), 0 when lit, < 0 when unknown (full filter there);
//                           read by classification and the filter
//   "shadow_mask"           buffer, 4 bytes per mask word, written by "prepare"
//   "shadow_tile_metadata0/1" buffer, 4 bytes per 8x8 tile: bit 0 CLEAR, bit 1 LIGHT; written on
//                           frame parity, the other read back as last frame's (rebuildClearHistory)
//   "shadow_moments0/1"     RGBA32F (mean, M2, n, accumulated shadow): written on frame parity, read
//                           on the other; .w is the next frame's shadow history. With
//                           rebuildClearHistory, texels of clear tiles are not written.
//   "shadow_scratch0/1"     RG32F (shadow, variance): classification writes 0 (with the tile
//                           list, not in clear tiles); "filter0" writes 1, "filter1" writes 0
//                           ("filter01" writes 1); scratch 1 only with the filter
//   "shadow_filter_work"    buffer, one uint: 8x8 tiles filtered, counted once per iteration (skipping)
//   "shadow_filter_tiles"   buffer, 4 bytes per 8x8 tile: the tiles classification listed for the
//                           filter dispatches (x | y << 16), with skipping
//   "shadow_filter_args"    buffer, 12 bytes: their indirect arguments (prepare resets, classify counts);
//                           classification then writes the CLEAR tiles' output itself
//   "shadow_output"         outputFormat (R8 UNORM by default): .x the denoised shadow (1 = lit, 1 for
//                           non-receivers); .y its variance with RG32Float only
// Every owned image must hold finite values or be ignored through resetHistory on the first frame.
Result planShadowDenoiser(const ShadowDenoiserDesc& desc, EffectPlan& plan, std::string* error);

} // namespace glint
