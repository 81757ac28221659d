// glint shadow denoiser, pass 2 (tile classification + temporal accumulation): tile metadata,
// local statistics from the visibility mask, disocclusion, Welford moments, history
// reprojection with neighbourhood clamping and an anti-lag test (docs/shadow_denoiser.md).
//
// Integration: define these callbacks before or after including this header. Pixel and tile
// arguments are always inside the image / mask.
//
//   uint   GLINT_SHADOW_DENOISER_LoadMask(int2 tile);          mask word of 8x4 tile
//   float  GLINT_SHADOW_DENOISER_LoadDepth(int2 pixel);         device depth, current frame
//   float  GLINT_SHADOW_DENOISER_LoadPreviousDepth(int2 pixel); device depth, previous frame
//   float3 GLINT_SHADOW_DENOISER_LoadNormal(int2 pixel);        unpacked world normal
//   float2 GLINT_SHADOW_DENOISER_LoadMotion(int2 pixel);        convention A: uv_prev = uv + mv
//   float3 GLINT_SHADOW_DENOISER_LoadMomentsHistory(int2 pixel);(mean, M2, n) of last frame
//   float  GLINT_SHADOW_DENOISER_LoadShadowHistory(int2 pixel); last frame's accumulated shadow
//                                                               (the .w of StoreMoments)
//   uint   GLINT_SHADOW_DENOISER_LoadPreviousMetadata(uint tileIndex); last frame's tile metadata
//          (read only with GLINT_SHADOW_DENOISER_CLASSIFY_FLAG_REBUILD_CLEAR: its clear tiles
//          stored no moments, and LoadPreviousDepth must then return last frame's LoadDepth)
//   void   GLINT_SHADOW_DENOISER_StoreMetadata(uint tileIndex, uint metadata);
//   void   GLINT_SHADOW_DENOISER_StoreShadowVariance(int2 pixel, float2 value);
//   void   GLINT_SHADOW_DENOISER_StoreMoments(int2 pixel, float4 moments);  (mean, M2, n, shadow)
//   float  GLINT_SHADOW_DENOISER_LoadBlockerDistance(int2 pixel);
//          distance along this frame's shadow ray to its closest blocker, as the filter's
//          (glint_shadow_denoiser_filter.hlsli); read only with penumbraScale > 0
// With GLINT_SHADOW_DENOISER_TILE_LIST=1 (for the filter's tile list):
//   void   GLINT_SHADOW_DENOISER_AppendFilterTile(uint2 tile);   once per tile that is not clear
//   void   GLINT_SHADOW_DENOISER_StoreClearOutput(int2 pixel, float2 value);
//          the filter's final (shadow, variance) of a clear tile's pixel (a one-channel output
//          may keep .x only); its StoreShadowVariance is then skipped (the filter rebuilds clear
//          tiles from the metadata).
// Every loaded value may be non-finite: such histories count as missing, such depths as sky.
// Hard shadows (penumbraScale >= 0, glint_shadow_denoiser_penumbra.hlsli): only shadowed
// samples' blocker distances are read (a lit one implies no penumbra); a receiver whose
// (2 HARD_RADIUS + 1)^2 neighbourhood implies no penumbra wider than HARD_WIDTH (one pixel)
// stores its own sample, (x, 0), and the moments of a one-sample history, (x, 0, 1, x); with
// the filter's footprint (which takes no tap there) the output is the input
// (docs/shadow_denoiser.md, "Hard shadows pass through").
// The (shadow, variance) stored for a non-receiver is (1, 0): lit, as the visibility input marks
// it (docs/shadow_denoiser.md, "Non-receivers"); its moments are zeros (no history).
//
// Entry: from main, GLINT_SHADOW_DENOISER_Classify(SV_GroupID.xy, SV_GroupThreadID, p), p a
// GLINT_ShadowDenoiserClassifyParams (below) copied field by field from a
// GLINT_ShadowDenoiserClassifyConstants c (glint_shadow_denoiser_constants.h; filled by
// host/src/core/shadow_denoiser_passes.cpp), the matrices as float4x4(c.reproject[0], ...,
// c.reproject[3]): glslang cannot pass a ConstantBuffer to a function. c.normalUnpack is for
// LoadNormal. Integration guide: docs/integration.md.
//
// Dispatch: [numthreads(8, 8, GLINT_SHADOW_DENOISER_CLASSIFY_BLOCKS)], that is (8, 8, 1): 1
// block (8x8 tile) a group, ceil(W / 8) x ceil(H / 8) x 1 groups, unless
// GLINT_SHADOW_DENOISER_CLASSIFY_PART says:
// - GLINT_SHADOW_DENOISER_CLASSIFY_PART_TILES (with the tile list): (8, 8, 4), only the tile
//   classification (metadata, list, clear tiles' output) of 2 x 2 blocks a group,
//   ceil(W / 16) x ceil(H / 16) x 1 groups. With one block per group a pass over mostly clear
//   tiles is bound by the rate at which the GPU starts groups, not by their work
//   (docs/performance.md, "Shadow denoiser: figures the headers cited");
// - GLINT_SHADOW_DENOISER_CLASSIFY_PART_LISTED (with the tile list): (8, 8, 1), the temporal part
//   of the blocks the tiles part listed, one a group, dispatched indirectly from the list's
//   arguments (listed tiles, 1, 1) at byte 0; it takes
//   uint2 GLINT_SHADOW_DENOISER_LoadFilterTile(uint listIndex)  as the filter does.
// Both parts together write what the whole pass writes. The whole pass keeps one block a group:
// with four, its few busy groups would fill the SMs the clear ones share (docs/performance.md).
#ifndef GLINT_SHADOW_DENOISER_CLASSIFY_HLSLI
#define GLINT_SHADOW_DENOISER_CLASSIFY_HLSLI

#include "glint/common/glint_math.hlsli"
#include "glint/common/glint_wire_formats.h"
#include "glint/shadow_denoiser/glint_shadow_denoiser_constants.h"
#include "glint/shadow_denoiser/glint_shadow_denoiser_penumbra.hlsli"

uint GLINT_SHADOW_DENOISER_LoadMask(int2 tile);
float GLINT_SHADOW_DENOISER_LoadDepth(int2 pixel);
float GLINT_SHADOW_DENOISER_LoadPreviousDepth(int2 pixel);
float3 GLINT_SHADOW_DENOISER_LoadNormal(int2 pixel);
float2 GLINT_SHADOW_DENOISER_LoadMotion(int2 pixel);
float3 GLINT_SHADOW_DENOISER_LoadMomentsHistory(int2 pixel);
float GLINT_SHADOW_DENOISER_LoadShadowHistory(int2 pixel);
uint GLINT_SHADOW_DENOISER_LoadPreviousMetadata(uint tileIndex);
void GLINT_SHADOW_DENOISER_StoreMetadata(uint tileIndex, uint metadata);
void GLINT_SHADOW_DENOISER_StoreShadowVariance(int2 pixel, float2 value);
void GLINT_SHADOW_DENOISER_StoreMoments(int2 pixel, float4 moments);
float GLINT_SHADOW_DENOISER_LoadBlockerDistance(int2 pixel);
#if GLINT_SHADOW_DENOISER_TILE_LIST
void GLINT_SHADOW_DENOISER_AppendFilterTile(uint2 tile);
void GLINT_SHADOW_DENOISER_StoreClearOutput(int2 pixel, float2 value);
#endif

#define GLINT_SHADOW_DENOISER_CLASSIFY_PART_WHOLE 0
#define GLINT_SHADOW_DENOISER_CLASSIFY_PART_TILES 1
#define GLINT_SHADOW_DENOISER_CLASSIFY_PART_LISTED 2
#ifndef GLINT_SHADOW_DENOISER_CLASSIFY_PART
#define GLINT_SHADOW_DENOISER_CLASSIFY_PART GLINT_SHADOW_DENOISER_CLASSIFY_PART_WHOLE
#endif
#if GLINT_SHADOW_DENOISER_CLASSIFY_PART != GLINT_SHADOW_DENOISER_CLASSIFY_PART_WHOLE && !GLINT_SHADOW_DENOISER_TILE_LIST
#error "the classification parts need GLINT_SHADOW_DENOISER_TILE_LIST"
#endif
#if GLINT_SHADOW_DENOISER_CLASSIFY_PART == GLINT_SHADOW_DENOISER_CLASSIFY_PART_TILES
#define GLINT_SHADOW_DENOISER_CLASSIFY_BLOCKS GLINT_SHADOW_DENOISER_CLASSIFY_TILE_BLOCKS
#else
#define GLINT_SHADOW_DENOISER_CLASSIFY_BLOCKS 1
#endif
#if GLINT_SHADOW_DENOISER_CLASSIFY_PART == GLINT_SHADOW_DENOISER_CLASSIFY_PART_LISTED
uint2 GLINT_SHADOW_DENOISER_LoadFilterTile(uint listIndex);
#endif

// Per block (8 x 8 tile) q = groupThreadId.z of the group: each array holds the values of the
// group's GLINT_SHADOW_DENOISER_CLASSIFY_BLOCKS blocks.
groupshared uint g_glint_shadow_denoiser_classify_receivers[GLINT_SHADOW_DENOISER_CLASSIFY_BLOCKS];
// OR and AND of the 3x6 mask words around the block, one word loaded per thread.
groupshared uint g_glint_shadow_denoiser_classify_or[GLINT_SHADOW_DENOISER_CLASSIFY_BLOCKS];
groupshared uint g_glint_shadow_denoiser_classify_and[GLINT_SHADOW_DENOISER_CLASSIFY_BLOCKS];
// Those 18 words (mask tiles tile.x - 1 .. + 1, 2 tile.y - 2 .. + 3, clamped to the mask):
// every mask bit the 17x17 statistics and the pixel's own sample read.
groupshared uint g_glint_shadow_denoiser_classify_words[GLINT_SHADOW_DENOISER_CLASSIFY_BLOCKS * 18];
// Horizontal lit sums of rows blockOrigin.y - 8 .. blockOrigin.y + 15 (24 x 8 columns); see
// GLINT_SHADOW_DENOISER_RowSum (the shadowed sum is 1 - this, exactly).
groupshared float g_glint_shadow_denoiser_classify_rows[GLINT_SHADOW_DENOISER_CLASSIFY_BLOCKS * 24 * 8];
// The lit samples among the 5 of each of those rows centred on the column (the 5x5 window's rows).
groupshared uint g_glint_shadow_denoiser_classify_rows5[GLINT_SHADOW_DENOISER_CLASSIFY_BLOCKS * 24 * 8];
// Smallest and largest packed offset (previous pixel - pixel) of the block's candidate pixels
// for the anti-lag test (GLINT_SHADOW_DENOISER_AntiLagWindow): equal when the block moved by one
// whole-pixel offset (always, for a still camera), and the test's windows then overlap exactly.
groupshared uint g_glint_shadow_denoiser_classify_offset_min[GLINT_SHADOW_DENOISER_CLASSIFY_BLOCKS];
groupshared uint g_glint_shadow_denoiser_classify_offset_max[GLINT_SHADOW_DENOISER_CLASSIFY_BLOCKS];
// Anti-lag terms (GLINT_SHADOW_DENOISER_AntiLagTexel) of the block plus a 2-pixel apron.
#define GLINT_SHADOW_DENOISER_ANTILAG_SPAN (8 + 2 * GLINT_SHADOW_DENOISER_ANTILAG_RADIUS)
#define GLINT_SHADOW_DENOISER_ANTILAG_SLOTS (GLINT_SHADOW_DENOISER_ANTILAG_SPAN * GLINT_SHADOW_DENOISER_ANTILAG_SPAN)
groupshared float4 g_glint_shadow_denoiser_classify_window[GLINT_SHADOW_DENOISER_CLASSIFY_BLOCKS *
                                                          GLINT_SHADOW_DENOISER_ANTILAG_SLOTS];
// The hard-shadow test of a block that is not clear (one block a group in the parts that run it):
// per row of the block plus a HARD_RADIUS apron (coordinates clamped to the image), bit i set
// when span column i implies a penumbra wider than HARD_WIDTH. OR-ed in by the threads that
// load the span, read after the row sums' barrier: no barrier of its own.
#define GLINT_SHADOW_DENOISER_HARD_SPAN (8 + 2 * GLINT_SHADOW_DENOISER_HARD_RADIUS)
groupshared uint g_glint_shadow_denoiser_classify_soft_rows[GLINT_SHADOW_DENOISER_HARD_SPAN];

// Span slot k = 0..3 of thread `localIndex` (an 8 x 8 block's 16 x 16 span): slot 0 is the
// thread's own pixel (span (4, 4) + local), slots 1..3 the 192 apron pixels: the 4 rows above,
// the 4 below, then 4 columns left and right of the block's rows.
int2 GLINT_SHADOW_DENOISER_HardSpanPixel(uint localIndex, uint k)
{
    if (k == 0u)
        return int2(localIndex % 8u, localIndex / 8u) + GLINT_SHADOW_DENOISER_HARD_RADIUS;
    uint a = localIndex + (k - 1u) * 64u;
    if (a < 64u)
        return int2(a % 16u, a / 16u);
    if (a < 128u)
        return int2((a - 64u) % 16u, 12u + (a - 64u) / 16u);
    if (a < 160u)
        return int2((a - 128u) % 4u, 4u + (a - 128u) / 4u);
    return int2(12u + (a - 160u) % 4u, 4u + (a - 160u) / 4u);
}

// View depth of a receiver (finite depth strictly inside (1e-6, 1 - 1e-6)), or -1.
float GLINT_SHADOW_DENOISER_ClassifyViewDepth(float depth, float4 viewDepth)
{
    if (!GLINT_IsFinite(depth) || !(depth > 1e-6 && depth < 1.0 - 1e-6))
        return -1.0;
    float z = viewDepth.x / (viewDepth.y + viewDepth.z * depth);
    return GLINT_IsFinite(z) && z > 0.0 ? z : -1.0;
}

// 1D weights w(i) = exp(-3 i^2 / 81) / sum_{j=-8..8} exp(-3 j^2 / 81), i = 0..8, rounded to
// multiples of 2^-20 (w(0) adjusted by 3 units) so that the 17 of a row sum to exactly 1: every
// partial row sum of them is then exact in float, whatever the order or FMA contraction, and so
// is 1 - a row sum (GLINT_SHADOW_DENOISER_RowSum).
static const float GLINT_SHADOW_DENOISER_GAUSSIAN_17[9] = {0.11083221435546875,
                                                           0.10679912567138671875,
                                                           0.09556865692138671875,
                                                           0.0794124603271484375,
                                                           0.06127643585205078125,
                                                           0.04390621185302734375,
                                                           0.02921390533447265625,
                                                           0.01805019378662109375,
                                                           0.010356903076171875};

float GLINT_SHADOW_DENOISER_GaussianWeight(int i)
{
    return GLINT_SHADOW_DENOISER_GAUSSIAN_17[i];
}

// The mask word of mask tile (tile.x + dx, tileY), dx in {-1, 0, 1}, from block q's 18 words.
// tileY must lie within 2 tile.y - 2 .. + 3 after clamping to the mask, as every tile row of
// the rows the block reads does (the block's first row is inside the image).
uint GLINT_SHADOW_DENOISER_BlockWord(uint q, uint2 tile, int dx, int tileY)
{
    return g_glint_shadow_denoiser_classify_words[q * 18u + uint((tileY - int(tile.y * 2u) + 2) * 3 + dx + 1)];
}

// The mask bits of pixel row y (clamped to the image) from column x - 8 (bit 0) to x + 8 (bit
// 16) and beyond, x a column of block q (8x8 tile `tile`): the row's bytes of the mask tiles left
// of, at and right of the block (clamped to the mask, as the 18 words are).
uint GLINT_SHADOW_DENOISER_RowWindow(uint q, uint2 tile, int x, int y, uint2 inputSize)
{
    int row = clamp(y, 0, int(inputSize.y) - 1);
    int tileY = row >> 2;
    uint shift = GLINT_WIRE_ShadowMaskBit(0u, uint(row)); // the row's byte: its leftmost pixel's bit
    uint left = (GLINT_SHADOW_DENOISER_BlockWord(q, tile, -1, tileY) >> shift) & 0xFFu;
    uint centre = (GLINT_SHADOW_DENOISER_BlockWord(q, tile, 0, tileY) >> shift) & 0xFFu;
    uint right = (GLINT_SHADOW_DENOISER_BlockWord(q, tile, 1, tileY) >> shift) & 0xFFu;
    return (left | (centre << 8) | (right << 16)) >> uint(x & 7);
}

// Horizontal 17-tap sum of a row window (GLINT_SHADOW_DENOISER_RowWindow) centred on its
// column: the Gaussian weight of the lit samples, exact, and so is the
// shadowed samples' weight, 1 minus it (the weights are multiples of 2^-20 summing to 1). The
// spatial variance is mean (1 - mean), and in a window that is lit but for a few samples at its
// edge 1 - mean is ~1e-5: taken as the difference of the 17x17 sum from 1, its rounding would
// depend on how a compiler contracts the sums into FMAs, and with it the variance, the clamp
// radius and the history length; summed from the exact row complements it is accurate in itself
// on every device.
float GLINT_SHADOW_DENOISER_RowSum(uint window)
{
    float lit = 0.0;
    [unroll] for (int k = 0; k <= 16; ++k)
        lit += ((window >> uint(k)) & 1u) != 0u ? GLINT_SHADOW_DENOISER_GaussianWeight(abs(k - 8)) : 0.0;
    return lit;
}

// Last frame's (mean, M2, n, accumulated shadow) of an in-image pixel. With REBUILD_CLEAR a
// pixel of a tile that was clear stored nothing: its history is what the clear branch of
// GLINT_SHADOW_DENOISER_Classify would have stored, from the tile's LIGHT bit and whether the
// pixel was a receiver (its depth then is this frame's previous depth).
float4 GLINT_SHADOW_DENOISER_LoadHistory(int2 pixel, uint2 inputSize, float4 viewDepth, uint flags)
{
    float4 stored = float4(GLINT_SHADOW_DENOISER_LoadMomentsHistory(pixel), GLINT_SHADOW_DENOISER_LoadShadowHistory(pixel));
    if ((flags & GLINT_SHADOW_DENOISER_CLASSIFY_FLAG_REBUILD_CLEAR) == 0u)
        return stored;
    // All three loads before any test, so their latencies overlap; the stored texel of a clear
    // tile (stale, possibly NaN) is selected away, never used.
    uint tilesX = (inputSize.x + 7u) / 8u;
    uint metadata = GLINT_SHADOW_DENOISER_LoadPreviousMetadata(uint(pixel.y >> 3) * tilesX + uint(pixel.x >> 3));
    bool receiver =
        GLINT_SHADOW_DENOISER_ClassifyViewDepth(GLINT_SHADOW_DENOISER_LoadPreviousDepth(pixel), viewDepth) > 0.0;
    float value = receiver && (metadata & GLINT_SHADOW_DENOISER_TILE_LIGHT) != 0u ? 1.0 : 0.0;
    float4 rebuilt = float4(value, 0.0, receiver ? 1.0 : 0.0, value);
    return (metadata & GLINT_SHADOW_DENOISER_TILE_CLEAR) != 0u ? rebuilt : stored;
}

float GLINT_SHADOW_DENOISER_BilinearHistory(float2 uv, uint2 inputSize, float4 viewDepth, uint flags, out bool valid)
{
    float2 p = uv * float2(inputSize) - 0.5;
    float2 base = floor(p);
    float2 f = p - base;
    int2 b = int2(base);
    int2 last = int2(inputSize) - 1;
    float h00 = GLINT_SHADOW_DENOISER_LoadHistory(clamp(b, int2(0, 0), last), inputSize, viewDepth, flags).w;
    float h10 = GLINT_SHADOW_DENOISER_LoadHistory(clamp(b + int2(1, 0), int2(0, 0), last), inputSize, viewDepth, flags).w;
    float h01 = GLINT_SHADOW_DENOISER_LoadHistory(clamp(b + int2(0, 1), int2(0, 0), last), inputSize, viewDepth, flags).w;
    float h11 = GLINT_SHADOW_DENOISER_LoadHistory(clamp(b + int2(1, 1), int2(0, 0), last), inputSize, viewDepth, flags).w;
    float h = lerp(lerp(h00, h10, f.x), lerp(h01, h11, f.x), f.y);
    valid = GLINT_IsFinite(h);
    return valid ? clamp(h, 0.0, 1.0) : 0.0;
}

// The anti-lag terms of one window position: this frame's view depth at `current` (-1 when
// either position is outside the image or the history there is missing), last frame's view
// depth at `previous`, the accumulated shadow there, and its sample count, negated when this
// frame's mask bit at `current` is 0 (a valid history has n > 0, so the sign is the bit).
float4 GLINT_SHADOW_DENOISER_AntiLagTexel(int2 current, int2 previous, uint2 inputSize, float4 viewDepth, uint flags)
{
    bool inImage = all(current >= 0) && all(previous >= 0) && all(current < int2(inputSize)) &&
                   all(previous < int2(inputSize));
    current = clamp(current, int2(0, 0), int2(inputSize) - 1);
    previous = clamp(previous, int2(0, 0), int2(inputSize) - 1);
    float currentZ = GLINT_SHADOW_DENOISER_ClassifyViewDepth(GLINT_SHADOW_DENOISER_LoadDepth(current), viewDepth);
    float pastZ = GLINT_SHADOW_DENOISER_ClassifyViewDepth(GLINT_SHADOW_DENOISER_LoadPreviousDepth(previous), viewDepth);
    float4 loaded = GLINT_SHADOW_DENOISER_LoadHistory(previous, inputSize, viewDepth, flags);
    uint word = GLINT_SHADOW_DENOISER_LoadMask(int2(current.x >> 3, current.y >> 2));
    bool bit = ((word >> GLINT_WIRE_ShadowMaskBit(uint(current.x), uint(current.y))) & 1u) != 0u;
    bool valid = inImage && GLINT_IsFinite(loaded.z) && GLINT_IsFinite(loaded.w) && loaded.z > 0.0;
    float samples = min(loaded.z, 1023.0);
    return float4(valid ? currentZ : -1.0, pastZ, clamp(loaded.w, 0.0, 1.0), bit ? samples : -samples);
}

// Sums of the anti-lag scores (see GLINT_SHADOW_DENOISER_AntiLagLength).
struct GLINT_ShadowDenoiserAntiLagSums
{
    float observed;
    float expected;
    float variance;
    float surprise;
    float surpriseVariance;
};

GLINT_ShadowDenoiserAntiLagSums GLINT_SHADOW_DENOISER_AntiLagBegin()
{
    GLINT_ShadowDenoiserAntiLagSums sums;
    sums.observed = 0.0;
    sums.expected = 0.0;
    sums.variance = 0.0;
    sums.surprise = 0.0;
    sums.surpriseVariance = 0.0;
    return sums;
}

// Adds one window position; it counts when its history is present and it is a receiver
// within ANTILAG_DEPTH relative view depth of the centre in both frames.
void GLINT_SHADOW_DENOISER_AntiLagAdd(inout GLINT_ShadowDenoiserAntiLagSums sums, float4 texel, float z, float previousZ)
{
    bool valid = texel.x > 0.0 && texel.y > 0.0 && abs(texel.x - z) <= GLINT_SHADOW_DENOISER_ANTILAG_DEPTH * z &&
                 abs(texel.y - previousZ) <= GLINT_SHADOW_DENOISER_ANTILAG_DEPTH * previousZ;
    if (!valid)
        return;
    float h = texel.z;
    float samples = abs(texel.w);
    float bit = texel.w > 0.0 ? 1.0 : 0.0;
    float p = (h * samples + 0.25) / (samples + 0.5);
    sums.observed += bit;
    sums.expected += h;
    sums.variance += p * (1.0 - p) * (1.0 + 1.0 / (samples + 1.0));
    float q = (h * samples + 1.0) / (samples + 2.0);
    sums.surprise += abs(bit - h) - (q * (1.0 - h) + (1.0 - q) * h);
    sums.surpriseVariance += q * (1.0 - q) * (1.0 - 2.0 * h) * (1.0 - 2.0 * h);
}

// Anti-lag (docs/shadow_denoiser.md, "Convergence"): the longest history that the 5x5 window
// around the pixel still supports. This frame's mask bits b_j in the window are compared with
// last frame's accumulated shadow h_j (n_j samples) of the same window around the previous
// position, pixel by pixel, so the shape of a static penumbra cancels out. Two scores, each in
// binomial sigmas with ANTILAG_SLACK samples of slack for the histories' own error:
// - signed: |sum b_j - sum h_j| / sqrt(sum p_j (1 - p_j) (1 + 1/(n_j + 1)) + slack), with
//   p_j = (h_j n_j + 1/4) / (n_j + 1/2); it sees a shadow that arrived or left as a whole;
// - absolute: sum (|b_j - h_j| - E_j) / sqrt(sum q_j (1 - q_j) (1 - 2 h_j)^2 + slack), with
//   q_j = (h_j n_j + 1) / (n_j + 2) and E_j = q_j (1 - h_j) + (1 - q_j) h_j the expected
//   |b_j - h_j|; it sees bits that contradict confident histories in both directions (a thin
//   shadow that moved sideways gains on one edge what it loses on the other).
// Neighbours count when they are inside the image and receivers within ANTILAG_DEPTH relative
// view depth of the centre in both frames (moments of non-receivers store n = 0). With z the
// larger score: above ANTILAG_THRESHOLD the history length is capped at
// ANTILAG_LENGTH / (z - ANTILAG_THRESHOLD)^2 (at least 1; continuous at the threshold).
float GLINT_SHADOW_DENOISER_AntiLagLength(GLINT_ShadowDenoiserAntiLagSums sums)
{
    float score = max(abs(sums.observed - sums.expected) * rsqrt(sums.variance + GLINT_SHADOW_DENOISER_ANTILAG_SLACK),
                      sums.surprise * rsqrt(sums.surpriseVariance + GLINT_SHADOW_DENOISER_ANTILAG_SLACK));
    float excess = score - GLINT_SHADOW_DENOISER_ANTILAG_THRESHOLD;
    return excess > 0.0 ? max(GLINT_SHADOW_DENOISER_ANTILAG_LENGTH / (excess * excess), 1.0) : 1024.0;
}

// The anti-lag test of a block that is not clear (one block a group in the parts that run it),
// in two calls that every thread of the block makes, each synchronising the group once, so
// that the window's loads overlap the pixels' own history loads:
// - AntiLagWindow, as soon as the pixels' reprojected positions are known: when every
//   candidate (a pixel that reprojects into the image) moved by the same whole-pixel offset,
//   their windows are one 12x12 region, and each thread fetches about 2 of its positions into
//   groupshared memory instead of all 25 of its own window. Returns whether it did.
// - AntiLagWindowLength, after the history test: the length for the pixels that found a history
//   (`wanted`, a subset of the candidates, so the window holds their positions too), 1024 for
//   the others. Same terms, same order of summation, same result as the per-pixel loop that
//   runs when the candidates moved by different offsets.
bool GLINT_SHADOW_DENOISER_AntiLagWindow(bool candidate, int2 offset, uint q, uint2 tile, uint localIndex,
                                         uint2 inputSize, float4 viewDepth, uint flags)
{
    const int radius = GLINT_SHADOW_DENOISER_ANTILAG_RADIUS;
    const int span = GLINT_SHADOW_DENOISER_ANTILAG_SPAN;
    // Offsets lie within +-16383 (image sizes), so the biased halves never carry.
    uint packed = uint(offset.x + 32768) | (uint(offset.y + 32768) << 16);
    if (candidate)
    {
        InterlockedMin(g_glint_shadow_denoiser_classify_offset_min[q], packed);
        InterlockedMax(g_glint_shadow_denoiser_classify_offset_max[q], packed);
    }
    GroupMemoryBarrierWithGroupSync();
    uint low = g_glint_shadow_denoiser_classify_offset_min[q];
    uint high = g_glint_shadow_denoiser_classify_offset_max[q];
    // A block without candidates has low > high: it fills no window.
    bool uniformWindow = low == high;
    if (uniformWindow)
    {
        uint windowBase = q * GLINT_SHADOW_DENOISER_ANTILAG_SLOTS;
        int2 uniformOffset = int2(int(low & 0xFFFFu) - 32768, int(low >> 16) - 32768);
        int2 origin = int2(tile * 8u) - radius;
        // A loop: unrolling it, so that a thread's up to 3 positions load together, does not pay
        // (docs/performance.md).
        for (uint i = localIndex; i < uint(span * span); i += 64u)
        {
            int2 current = origin + int2(int(i % uint(span)), int(i / uint(span)));
            g_glint_shadow_denoiser_classify_window[windowBase + i] =
                GLINT_SHADOW_DENOISER_AntiLagTexel(current, current + uniformOffset, inputSize, viewDepth, flags);
        }
    }
    return uniformWindow;
}

float GLINT_SHADOW_DENOISER_AntiLagWindowLength(bool wanted, bool uniformWindow, int2 pixel, int2 previousPixel, float z,
                                                float previousZ, uint q, uint2 local, uint2 inputSize, float4 viewDepth,
                                                uint flags)
{
    const int radius = GLINT_SHADOW_DENOISER_ANTILAG_RADIUS;
    const int span = GLINT_SHADOW_DENOISER_ANTILAG_SPAN;
    GroupMemoryBarrierWithGroupSync();
    if (!wanted)
        return 1024.0;
    GLINT_ShadowDenoiserAntiLagSums sums = GLINT_SHADOW_DENOISER_AntiLagBegin();
    if (uniformWindow)
    {
        uint centre =
            q * GLINT_SHADOW_DENOISER_ANTILAG_SLOTS + (local.y + uint(radius)) * uint(span) + local.x + uint(radius);
        // Rows in a loop, columns unrolled (as the reflections denoiser's 9x9 statistics).
        [loop] for (int dy = -radius; dy <= radius; ++dy)
            [unroll] for (int dx = -radius; dx <= radius; ++dx)
                GLINT_SHADOW_DENOISER_AntiLagAdd(sums, g_glint_shadow_denoiser_classify_window[int(centre) + dy * span + dx],
                                                 z, previousZ);
        return GLINT_SHADOW_DENOISER_AntiLagLength(sums);
    }
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx)
            GLINT_SHADOW_DENOISER_AntiLagAdd(sums,
                                             GLINT_SHADOW_DENOISER_AntiLagTexel(pixel + int2(dx, dy), previousPixel + int2(dx, dy),
                                                                                inputSize, viewDepth, flags),
                                             z, previousZ);
    return GLINT_SHADOW_DENOISER_AntiLagLength(sums);
}

// Constants as in GLINT_ShadowDenoiserClassifyConstants; the matrices are built from its rows
// with float4x4(row0, row1, row2, row3), so mul(matrix, p) = (dot(row_i, p)).
struct GLINT_ShadowDenoiserClassifyParams
{
    uint2 inputSize;
    uint2 maskTiles;
    float4x4 reproject;
    float4x4 inverseViewProj;
    float4 eyePosition;
    float4 viewDepth;
    float ndcYSign;
    uint flags; // GLINT_SHADOW_DENOISER_CLASSIFY_FLAG_*
    // Times the variance of the accumulated mean, stored for the filter's edge stop: larger
    // values filter settled penumbrae more (docs/shadow_denoiser.md).
    float storedVarianceScale;
    // Penumbra width per blocker distance / view depth (glint_shadow_denoiser_penumbra.hlsli);
    // negative: no estimate, no pixel passes through.
    float penumbraScale;
};

// Motion of the closest receiver of the pixel's 2x2 quad (z: the pixel's own view depth).
float2 GLINT_SHADOW_DENOISER_QuadMotion(int2 pixel, int2 loadPixel, float z, uint2 inputSize, float4 viewDepth)
{
    int2 quad = pixel & ~1;
    int2 motionPixel = loadPixel;
    float closest = z;
    [unroll] for (int k = 0; k < 4; ++k)
    {
        int2 other = min(quad + int2(k & 1, k >> 1), int2(inputSize) - 1);
        float otherZ = GLINT_SHADOW_DENOISER_ClassifyViewDepth(GLINT_SHADOW_DENOISER_LoadDepth(other), viewDepth);
        if (otherZ > 0.0 && otherZ < closest)
        {
            closest = otherZ;
            motionPixel = other;
        }
    }
    return GLINT_SHADOW_DENOISER_LoadMotion(motionPixel);
}

// groupThreadId.z picks the group's block (8x8 tile) q: with 4 blocks a group, tile =
// 2 groupId + (q & 1, q >> 1); with one, tile = groupId (or, for the listed part, list entry
// groupId.x).
void GLINT_SHADOW_DENOISER_Classify(uint2 groupId, uint3 groupThreadId, GLINT_ShadowDenoiserClassifyParams c)
{
    uint q = groupThreadId.z;
#if GLINT_SHADOW_DENOISER_CLASSIFY_PART == GLINT_SHADOW_DENOISER_CLASSIFY_PART_LISTED
    uint2 tile = GLINT_SHADOW_DENOISER_LoadFilterTile(groupId.x);
#elif GLINT_SHADOW_DENOISER_CLASSIFY_PART == GLINT_SHADOW_DENOISER_CLASSIFY_PART_TILES
    uint2 tile = groupId * uint2(GLINT_SHADOW_DENOISER_CLASSIFY_TILE_BLOCKS_X, GLINT_SHADOW_DENOISER_CLASSIFY_TILE_BLOCKS_Y) +
                 uint2(q % GLINT_SHADOW_DENOISER_CLASSIFY_TILE_BLOCKS_X, q / GLINT_SHADOW_DENOISER_CLASSIFY_TILE_BLOCKS_X);
#else
    uint2 tile = groupId;
#endif
    uint2 local = groupThreadId.xy;
    uint localIndex = local.y * 8u + local.x;
    int2 pixel = int2(tile * 8u + local);
    bool inside = all(uint2(pixel) < c.inputSize);
    int2 loadPixel = min(pixel, int2(c.inputSize) - 1);
    float depth = GLINT_SHADOW_DENOISER_LoadDepth(loadPixel);
    // Uniform region: the 3x6 mask tiles around the block (24x24 pixels), clamped; threads
    // 0..17 of the block load one word each (with the depth, before the first barrier) instead
    // of every thread loading all 18.
    uint word = 0u;
    if (localIndex < 18u)
    {
        int2 firstTile = int2(tile.x, tile.y * 2u);
        int2 maskTile = clamp(firstTile + int2(int(localIndex % 3u) - 1, int(localIndex / 3u) - 2), int2(0, 0),
                              int2(c.maskTiles) - 1);
        word = GLINT_SHADOW_DENOISER_LoadMask(maskTile);
    }
    float z = GLINT_SHADOW_DENOISER_ClassifyViewDepth(depth, c.viewDepth);
    bool receiver = inside && z > 0.0;

#if GLINT_SHADOW_DENOISER_CLASSIFY_PART != GLINT_SHADOW_DENOISER_CLASSIFY_PART_TILES
    if (localIndex < GLINT_SHADOW_DENOISER_HARD_SPAN)
        g_glint_shadow_denoiser_classify_soft_rows[localIndex] = 0u;
#endif
#if GLINT_SHADOW_DENOISER_CLASSIFY_PART == GLINT_SHADOW_DENOISER_CLASSIFY_PART_LISTED
    // A listed block is not clear (the tiles part tested it and stored its metadata).
    if (localIndex == 0)
    {
        g_glint_shadow_denoiser_classify_offset_min[q] = 0xFFFFFFFFu;
        g_glint_shadow_denoiser_classify_offset_max[q] = 0u;
    }
    if (localIndex < 18u)
        g_glint_shadow_denoiser_classify_words[q * 18u + localIndex] = word;
    GroupMemoryBarrierWithGroupSync();
    const bool clear = false;
#else
    if (localIndex == 0)
    {
        g_glint_shadow_denoiser_classify_receivers[q] = 0u;
        g_glint_shadow_denoiser_classify_or[q] = 0u;
        g_glint_shadow_denoiser_classify_and[q] = 0xFFFFFFFFu;
        g_glint_shadow_denoiser_classify_offset_min[q] = 0xFFFFFFFFu;
        g_glint_shadow_denoiser_classify_offset_max[q] = 0u;
    }
    GroupMemoryBarrierWithGroupSync();
    if (receiver)
        InterlockedOr(g_glint_shadow_denoiser_classify_receivers[q], 1u);
    if (localIndex < 18u)
    {
        g_glint_shadow_denoiser_classify_words[q * 18u + localIndex] = word;
        InterlockedOr(g_glint_shadow_denoiser_classify_or[q], word);
        InterlockedAnd(g_glint_shadow_denoiser_classify_and[q], word);
    }
    GroupMemoryBarrierWithGroupSync();
    bool anyReceiver = g_glint_shadow_denoiser_classify_receivers[q] != 0u;
    bool allLit = g_glint_shadow_denoiser_classify_and[q] == 0xFFFFFFFFu;
    // Blocks beyond the image have no receiver: clear.
    bool clear = !anyReceiver || allLit || g_glint_shadow_denoiser_classify_or[q] == 0u;

    uint tilesX = (c.inputSize.x + 7u) / 8u;
    if (localIndex == 0 && all(tile * 8u < c.inputSize))
    {
        uint metadata = clear ? GLINT_SHADOW_DENOISER_TILE_CLEAR : 0u;
        if (clear && anyReceiver && allLit)
            metadata |= GLINT_SHADOW_DENOISER_TILE_LIGHT;
        GLINT_SHADOW_DENOISER_StoreMetadata(tile.y * tilesX + tile.x, metadata);
#if GLINT_SHADOW_DENOISER_TILE_LIST
        if (!clear)
            GLINT_SHADOW_DENOISER_AppendFilterTile(tile);
#endif
    }
#endif
    bool readsBlockers = GLINT_SHADOW_DENOISER_PenumbraReadsBlockers(c.penumbraScale);
#if GLINT_SHADOW_DENOISER_CLASSIFY_PART != GLINT_SHADOW_DENOISER_CLASSIFY_PART_TILES
    if (!clear)
    {
        // The span's soft pixels, 4 slots a thread (the first its own pixel, whose depth it has),
        // their loads in flight with the row sums'; the row sums' barrier publishes them. A lit
        // sample implies no penumbra (its blocker distance is 0): only shadowed samples load. The
        // width is the filter's own (GLINT_SHADOW_DENOISER_PenumbraWidth), so a pixel passed
        // through here is one the filter takes no tap at.
        if (readsBlockers)
        {
            int2 spanOrigin = int2(tile * 8u) - GLINT_SHADOW_DENOISER_HARD_RADIUS;
            [unroll] for (uint k = 0; k < 4u; ++k)
            {
                int2 spanLocal = GLINT_SHADOW_DENOISER_HardSpanPixel(localIndex, k);
                int2 spanPixel = clamp(spanOrigin + spanLocal, int2(0, 0), int2(c.inputSize) - 1);
                uint spanWord = GLINT_SHADOW_DENOISER_BlockWord(q, tile, (spanPixel.x >> 3) - int(tile.x), spanPixel.y >> 2);
                if (((spanWord >> GLINT_WIRE_ShadowMaskBit(uint(spanPixel.x), uint(spanPixel.y))) & 1u) != 0u)
                    continue;
                float spanZ = k == 0u ? z
                                      : GLINT_SHADOW_DENOISER_ClassifyViewDepth(GLINT_SHADOW_DENOISER_LoadDepth(spanPixel), c.viewDepth);
                float width = GLINT_SHADOW_DENOISER_PenumbraWidth(GLINT_SHADOW_DENOISER_LoadBlockerDistance(spanPixel), spanZ,
                                                                  c.penumbraScale);
                if (width > GLINT_SHADOW_DENOISER_HARD_WIDTH)
                    InterlockedOr(g_glint_shadow_denoiser_classify_soft_rows[spanLocal.y], 1u << uint(spanLocal.x));
            }
        }
        // Horizontal 17-tap sums of the 24 rows the block's vertical taps reach, once per
        // (row, column) instead of once per tap: 3 per thread, from the 18 words in groupshared
        // memory. One block a group here, so `clear` is uniform and the barrier too. Columns
        // beyond the image use the last one (their sums go unused).
        int column = min(int(tile.x * 8u + local.x), int(c.inputSize.x) - 1);
        [unroll] for (uint part = 0; part < 3u; ++part)
        {
            uint row = local.y + part * 8u;
            uint window = GLINT_SHADOW_DENOISER_RowWindow(q, tile, column, int(tile.y * 8u + row) - 8, c.inputSize);
            g_glint_shadow_denoiser_classify_rows[(q * 24u + row) * 8u + local.x] = GLINT_SHADOW_DENOISER_RowSum(window);
            g_glint_shadow_denoiser_classify_rows5[(q * 24u + row) * 8u + local.x] = countbits((window >> 6u) & 0x1Fu);
        }
        GroupMemoryBarrierWithGroupSync();
    }
#endif
#if GLINT_SHADOW_DENOISER_CLASSIFY_PART != GLINT_SHADOW_DENOISER_CLASSIFY_PART_LISTED
    if (clear && inside)
    {
        float value = anyReceiver && allLit && receiver ? 1.0 : 0.0;
        float shadow = receiver ? value : 1.0;
#if GLINT_SHADOW_DENOISER_TILE_LIST
        GLINT_SHADOW_DENOISER_StoreClearOutput(pixel, float2(shadow, 0.0));
#else
        GLINT_SHADOW_DENOISER_StoreShadowVariance(pixel, float2(shadow, 0.0));
#endif
        if ((c.flags & GLINT_SHADOW_DENOISER_CLASSIFY_FLAG_REBUILD_CLEAR) == 0u)
            GLINT_SHADOW_DENOISER_StoreMoments(pixel, float4(value, 0.0, receiver ? 1.0 : 0.0, value));
    }
#endif
    // The tiles part stops here (the listed part does the rest).
    if (clear || GLINT_SHADOW_DENOISER_CLASSIFY_PART == GLINT_SHADOW_DENOISER_CLASSIFY_PART_TILES)
        return;
    // A block that is not clear: no thread returns before the anti-lag test's barriers.
    // Pixels outside the image or not receiving run along (as disoccluded, loading in-image
    // pixels only) and store their defined zeros after it.
    bool active = inside && receiver;

    // Local mean and variance: 17x17 Gaussian, rows first; the variance from the lit and the
    // shadowed weight, each summed (GLINT_SHADOW_DENOISER_RowSum).
    // `precise` (no contraction or reassociation): every operation rounds as on the CPU
    // reference, whatever the compiler; the variance is sensitive here by construction, and a
    // contracted sum changes history lengths (docs/shadow_denoiser.md, "Validation").
    precise float2 litShadowed = float2(0.0, 0.0);
    [unroll] for (int r = -8; r <= 8; ++r)
    {
        float rowLit = g_glint_shadow_denoiser_classify_rows[(q * 24u + uint(int(local.y) + r + 8)) * 8u + local.x];
        litShadowed += GLINT_SHADOW_DENOISER_GaussianWeight(abs(r)) * float2(rowLit, 1.0 - rowLit);
    }
    float mean = clamp(litShadowed.x, 0.0, 1.0);
    float spatialVariance = max(mean * clamp(litShadowed.y, 0.0, 1.0), 0.0);
    float spatialSigma = sqrt(spatialVariance);
    uint ownWord = GLINT_SHADOW_DENOISER_BlockWord(q, tile, 0, loadPixel.y >> 2);
    float x = ((ownWord >> GLINT_WIRE_ShadowMaskBit(uint(loadPixel.x), uint(loadPixel.y))) & 1u) != 0u ? 1.0 : 0.0;
    // A hard shadow: no penumbra wider than a pixel around the receiver, so its sample is the
    // answer (a light of size 0 makes every receiver hard without loading a blocker).
    uint softNeighbours = 0u;
    if (readsBlockers)
        [unroll] for (uint dy = 0; dy <= 2u * GLINT_SHADOW_DENOISER_HARD_RADIUS; ++dy)
            softNeighbours |= g_glint_shadow_denoiser_classify_soft_rows[local.y + dy] >> local.x;
    softNeighbours &= (1u << (2u * GLINT_SHADOW_DENOISER_HARD_RADIUS + 1u)) - 1u;
    bool hard = active && GLINT_SHADOW_DENOISER_PenumbraKnown(c.penumbraScale) && softNeighbours == 0u;

    // Loaded after the barriers: loading it before them in the listed part does not pay
    // (docs/performance.md).
    float2 motion = float2(0.0, 0.0);
    if (!hard)
        motion = GLINT_SHADOW_DENOISER_QuadMotion(pixel, loadPixel, z, c.inputSize, c.viewDepth);
    float2 uv = (float2(pixel) + 0.5) / float2(c.inputSize);
    float2 uvPrevious = uv + motion;
    // A hard pixel needs no history: it takes no part in the anti-lag window either.
    bool disoccluded = !active || hard || (c.flags & GLINT_SHADOW_DENOISER_CLASSIFY_FLAG_RESET) != 0u ||
                       !GLINT_IsFinite(uvPrevious.x) || !GLINT_IsFinite(uvPrevious.y) || any(uvPrevious < 0.0) ||
                       any(uvPrevious > 1.0);
    int2 previousPixel = disoccluded ? int2(0, 0) : min(int2(uvPrevious * float2(c.inputSize)), int2(c.inputSize) - 1);
    // Anti-lag: the 17x17 clamp cannot see a shadow edge that moved inside its window. The
    // flag is uniform, so every thread of the block reaches the test's barriers or none does.
    bool antiLag = (c.flags & GLINT_SHADOW_DENOISER_CLASSIFY_FLAG_ANTI_LAG) != 0u;
    bool uniformWindow = false;
    if (antiLag)
        uniformWindow = GLINT_SHADOW_DENOISER_AntiLagWindow(!disoccluded, previousPixel - pixel, q, tile, localIndex,
                                                            c.inputSize, c.viewDepth, c.flags);
    float previousZ = -1.0;
    if (!disoccluded)
    {
        float4 ndc = float4(2.0 * uv.x - 1.0, c.ndcYSign * (2.0 * uv.y - 1.0), depth, 1.0);
        float4 previousClip = mul(c.reproject, ndc);
        float reprojectedZ = GLINT_SHADOW_DENOISER_ClassifyViewDepth(previousClip.z / previousClip.w, c.viewDepth);
        previousZ =
            GLINT_SHADOW_DENOISER_ClassifyViewDepth(GLINT_SHADOW_DENOISER_LoadPreviousDepth(previousPixel), c.viewDepth);
        float4 world = mul(c.inverseViewProj, ndc);
        float3 toEye = c.eyePosition.xyz - world.xyz / world.w;
        float3 normal = GLINT_SHADOW_DENOISER_LoadNormal(pixel);
        float cosine = abs(dot(normalize(toEye), normalize(normal)));
        cosine = GLINT_IsFinite(cosine) ? min(cosine, 1.0) : 0.0;
        float threshold = lerp(0.01, 0.1, pow(1.0 - cosine, 8.0));
        // Finiteness is tested on the bits, never through a comparison with a NaN: drivers may
        // assume no NaNs (Vulkan does not require preserving them) and rewrite !(a < b) as
        // a >= b, which would turn sky pixels (infinite view depth) into accepted histories.
        bool depthsValid = GLINT_IsFinite(reprojectedZ) && GLINT_IsFinite(previousZ) && reprojectedZ > 0.0 &&
                           previousZ > 0.0;
        float relative = depthsValid ? abs(previousZ - reprojectedZ) / reprojectedZ : 1.0;
        disoccluded = !depthsValid || !GLINT_IsFinite(relative) || relative >= threshold;
    }

    float3 moments = float3(0.0, 0.0, 0.0);
    float history = mean;
    bool historyFound = false;
    if (!disoccluded)
    {
        float3 loaded = GLINT_SHADOW_DENOISER_LoadHistory(previousPixel, c.inputSize, c.viewDepth, c.flags).xyz;
        bool historyValid;
        float bilinear = GLINT_SHADOW_DENOISER_BilinearHistory(uvPrevious, c.inputSize, c.viewDepth, c.flags, historyValid);
        if (GLINT_IsFinite(loaded.x) && GLINT_IsFinite(loaded.y) && GLINT_IsFinite(loaded.z) && historyValid)
        {
            moments = float3(clamp(loaded.x, 0.0, 1.0), max(loaded.y, 0.0), clamp(loaded.z, 0.0, 1023.0));
            history = bilinear;
            historyFound = true;
        }
    }

    float antiLagLength = 1024.0;
    if (antiLag)
        antiLagLength = GLINT_SHADOW_DENOISER_AntiLagWindowLength(historyFound, uniformWindow, pixel, previousPixel, z,
                                                                  previousZ, q, local, c.inputSize, c.viewDepth, c.flags);
    if (!active)
    {
        if (inside)
        {
            GLINT_SHADOW_DENOISER_StoreShadowVariance(pixel, float2(1.0, 0.0));
            GLINT_SHADOW_DENOISER_StoreMoments(pixel, float4(0.0, 0.0, 0.0, 0.0));
        }
        return;
    }
    if (hard)
    {
        GLINT_SHADOW_DENOISER_StoreShadowVariance(pixel, float2(x, 0.0));
        GLINT_SHADOW_DENOISER_StoreMoments(pixel, float4(x, 0.0, 1.0, x));
        return;
    }

    // Welford update with this frame's sample.
    float n = moments.z + 1.0;
    float delta = x - moments.x;
    float newMean = moments.x + delta / n;
    float m2 = moments.y + delta * (x - newMean);
    // This frame's 5x5 samples: their binomial variance stands for a young history's spread.
    uint lit5 = 0u;
    [unroll] for (uint r5 = 6u; r5 <= 10u; ++r5)
        lit5 += g_glint_shadow_denoiser_classify_rows5[(q * 24u + local.y + r5) * 8u + local.x];
    float litShare = float(lit5) / 25.0;
    float windowVariance = litShare * (1.0 - litShare);
    float temporalVariance =
        n > 1.0 ? m2 / (n - 1.0) : min(GLINT_SHADOW_DENOISER_FIRST_SAMPLE_VARIANCE * windowVariance, 1.0);

    // The history is the unfiltered accumulation (never a filter output: feeding the filtered
    // value back blurs the penumbra again every frame). The clamp is wide (2 sigma_s): the
    // 17x17 mean is biased across narrow penumbrae, and a tight clamp pins the history to it.
    // The range always holds this frame's sample: a history that agrees with it is kept (a thin
    // hard shadow in a mostly lit window would otherwise be pulled towards the window's mean on
    // every frame, though every sample says shadowed).
    float clampRadius = GLINT_SHADOW_DENOISER_CLAMP_SIGMAS * spatialSigma;
    float clamped = clamp(history, min(mean - clampRadius, x), max(mean + clampRadius, x));
    float deviation = (history - mean) / max(clampRadius, 0.001);
    n *= exp(-deviation * deviation / 20.0);
    // n <= 1024 already: the cap changes only the histories the anti-lag test contradicted.
    n = min(n, antiLagLength);
    float count = max(n, 1.0);
    // Variance of the accumulated mean (boosted while young): the filter's edge stop tightens as
    // samples accumulate, so the spatial filter fades out instead of biasing the penumbra.
    float variance = (n < 16.0 ? max(temporalVariance, windowVariance) * max(16.0 - n, 1.0) : temporalVariance) /
                     count * c.storedVarianceScale;
    float alpha = max(1.0 / count, 1.0 / GLINT_SHADOW_DENOISER_HISTORY_CAP);
    float result = clamp(lerp(clamped, x, alpha), 0.0, 1.0);
    result = GLINT_FiniteOr(result, 0.0);

    GLINT_SHADOW_DENOISER_StoreShadowVariance(pixel, float2(result, max(GLINT_FiniteOr(variance, 0.0), 0.0)));
    GLINT_SHADOW_DENOISER_StoreMoments(pixel, float4(clamp(GLINT_FiniteOr(newMean, 0.0), 0.0, 1.0),
                                                     max(GLINT_FiniteOr(m2, 0.0), 0.0), GLINT_FiniteOr(n, 0.0), result));
}

#endif // GLINT_SHADOW_DENOISER_CLASSIFY_HLSLI
