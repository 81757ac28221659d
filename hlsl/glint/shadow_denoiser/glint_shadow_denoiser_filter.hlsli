// glint shadow denoiser, the filter passes ("filter0".."filter2", or "filter01" + "filter2"):
// one edge-avoiding a-trous iteration over (mean, variance) with depth and normal edge stops;
// run three times with step 1, 2 and 4 (docs/shadow_denoiser.md).
//
// Integration: define these callbacks before or after including this header.
//
//   float2 GLINT_SHADOW_DENOISER_LoadMeanVariance(int2 pixel);
//       (mean, variance) of the previous iteration at an in-image pixel. Any value is
//       allowed: non-finite ones become 0, the mean is clamped to [0, 1], the variance to >= 0.
//   float  GLINT_SHADOW_DENOISER_LoadDepth(int2 pixel);
//       Device depth of an in-image pixel. Receivers have finite depth strictly inside
//       (1e-6, 1 - 1e-6); anything else (sky, NaN) is a non-receiver.
//   float3 GLINT_SHADOW_DENOISER_LoadNormal(int2 pixel);
//       Unpacked world-space normal (need not be unit length). Non-finite or zero normals
//       make the pixel accept no neighbour (only its own sample).
//   void   GLINT_SHADOW_DENOISER_StoreFiltered(int2 pixel, float2 meanVariance);
//       Writes the result; the final pass writes (remapped mean, variance). The image's format
//       is the integration's choice: a one-channel output may keep .x only.
//   float  GLINT_SHADOW_DENOISER_LoadBlockerDistance(int2 pixel);
//       Distance along this frame's shadow ray of an in-image pixel to its closest blocker, in
//       the units of the view depth: > 0 for a shadowed sample, 0 when the ray reached the
//       light; negative or non-finite when unknown. A sample below the surface has no blocker:
//       on a curved surface its terminator's penumbra is about as wide as a blocker at the
//       curvature radius would cast; a flat face is below the horizon as a whole (0).
//       Read only when penumbraScale > 0; an integration without the data returns -1 (or
//       passes a negative penumbraScale): every pixel then takes the full filter.
//
// Tile skipping, GLINT_SHADOW_DENOISER_TILE_LIST=1 (tile metadata and the tile list from the
// classification pass): the dispatch is indirect, one group per tile classification listed
// (never a CLEAR one), with these callbacks too:
//   uint2  GLINT_SHADOW_DENOISER_LoadFilterTile(uint listIndex);     8x8 tile coordinates
//   uint   GLINT_SHADOW_DENOISER_LoadTileMetadata(uint tileIndex);   one word per 8x8 tile
//   void   GLINT_SHADOW_DENOISER_CountFilteredTile();                called once per filtered tile
// The passes write listed tiles only; CLEAR neighbours are rebuilt from the metadata (1 for
// receivers of a LIGHT tile, else 0; variance 0), and classification wrote the CLEAR tiles'
// output.
//
// Weights, for a receiver c and a receiver neighbour q at step * (i, j), i, j in {-1, 0, 1}:
//   w = k(i) k(j) exp(-|s_c - s_q| / sigma) exp(-|z_c - z_q| / (depthSigma z_c)) max(0, N_c . N_q)^normalPower
// with k(0) = 1, k(1) = 2/3, sigma = sqrt(var_f + 1e-9), var_f the 3x3 Gaussian (1/4 centre,
// 1/8 edges, 1/16 corners) of the variance around c, z the view depth A / (B + C d). The
// centre weighs 1. mean = sum w s / sum w, variance = sum w^2 var_q / (sum w)^2.
// Final pass: mean^max(1.2 - variance, 1). Non-receivers write (1, 0): lit, as the visibility
// input marks them (docs/shadow_denoiser.md, "Non-receivers").
//
// Penumbra footprint (penumbraScale >= 0; glint_shadow_denoiser_penumbra.hlsli: negative is no
// estimate, 0 a light of size 0 whose shadows are all hard): the penumbra width in pixels at a
// receiver is about
// W = penumbraScale * b / z, b the blocker distance, z the view depth; per pixel, W is the
// largest over its 5 x 5 neighbourhood (one shadow ray a pixel, and a lit one carries no
// distance). A pass of step s scales every neighbour's weight by saturate((W - 1) / s): no taps
// for a penumbra under a pixel, the full filter from s + 1 pixels. A hard shadow keeps its
// input, a wide penumbra gets the filter as without the estimate. The neighbourhood stays
// within the span in both the single and the paired passes (+-2 around pixels at most 2 beyond
// the tile), so both give the same result.
//
// Entry: from main, with c a GLINT_ShadowDenoiserFilterConstants (glint_shadow_denoiser_constants.h,
// filled by host/src/core/shadow_denoiser_passes.cpp; c.normalUnpack is for LoadNormal):
//   GLINT_SHADOW_DENOISER_Filter(SV_GroupID.xy, SV_GroupThreadID.xy, SV_GroupIndex, c.inputSize,
//                                c.step, c.finalPass != 0, c.viewDepth, c.depthSigma, c.normalPower,
//                                c.penumbraScale)
// or, with GLINT_SHADOW_DENOISER_FILTER_PAIR=1, steps 1 and 2 in one dispatch (the first over the
// tile +- 2 pixels, in groupshared memory; same taps, same results as two Filter dispatches):
//   GLINT_SHADOW_DENOISER_FilterPair(SV_GroupID.xy, SV_GroupThreadID.xy, SV_GroupIndex,
//                                    c.inputSize, c.viewDepth, c.depthSigma, c.normalPower,
//                                    c.penumbraScale)
// Integration guide: docs/integration.md.
//
// Dispatch: [numthreads(8, 8, 1)] in every variant (single, pair, tile list, pair + tile list;
// there is no fused three-iteration variant): ceil(W / 8) x ceil(H / 8) x 1 groups, or with the
// tile list indirect, (listed tiles, 1, 1) from byte 0 of the arguments. Groupshared span of
// 16 x 16 pixels (the 8 x 8 tile plus a 4-pixel apron), coordinates clamped to the image.
#ifndef GLINT_SHADOW_DENOISER_FILTER_HLSLI
#define GLINT_SHADOW_DENOISER_FILTER_HLSLI

#include "glint/common/glint_math.hlsli"
#include "glint/shadow_denoiser/glint_shadow_denoiser_constants.h"
#include "glint/shadow_denoiser/glint_shadow_denoiser_penumbra.hlsli"

float2 GLINT_SHADOW_DENOISER_LoadMeanVariance(int2 pixel);
float GLINT_SHADOW_DENOISER_LoadDepth(int2 pixel);
float3 GLINT_SHADOW_DENOISER_LoadNormal(int2 pixel);
void GLINT_SHADOW_DENOISER_StoreFiltered(int2 pixel, float2 meanVariance);
float GLINT_SHADOW_DENOISER_LoadBlockerDistance(int2 pixel);
#if GLINT_SHADOW_DENOISER_TILE_LIST
uint2 GLINT_SHADOW_DENOISER_LoadFilterTile(uint listIndex);
// The metadata marks the neighbours that were not stored (CLEAR tiles).
uint GLINT_SHADOW_DENOISER_LoadTileMetadata(uint tileIndex);
void GLINT_SHADOW_DENOISER_CountFilteredTile();
#endif

// The filter works on a 16 x 16 span (8 x 8 tile, 4-pixel apron); the paired one
// (GLINT_SHADOW_DENOISER_FILTER_PAIR=1) keeps its first iteration's results in a second value
// buffer.
#define GLINT_SHADOW_DENOISER_FILTER_SPAN 16
#if GLINT_SHADOW_DENOISER_FILTER_PAIR
#define GLINT_SHADOW_DENOISER_FILTER_BUFFERS 2
#else
#define GLINT_SHADOW_DENOISER_FILTER_BUFFERS 1
#endif
#define GLINT_SHADOW_DENOISER_FILTER_SLOTS (GLINT_SHADOW_DENOISER_FILTER_SPAN * GLINT_SHADOW_DENOISER_FILTER_SPAN)

// (mean, variance) and (view depth or -1 for non-receivers, normal) of the span.
groupshared float2 g_glint_shadow_denoiser_filter_values[GLINT_SHADOW_DENOISER_FILTER_BUFFERS * GLINT_SHADOW_DENOISER_FILTER_SLOTS];
groupshared float4 g_glint_shadow_denoiser_filter_geometry[GLINT_SHADOW_DENOISER_FILTER_SLOTS];
// Penumbra width in pixels each slot's shadow ray implies (0: lit or not a receiver); only with
// penumbraScale >= 0.
groupshared float g_glint_shadow_denoiser_filter_penumbra[GLINT_SHADOW_DENOISER_FILTER_SLOTS];

float2 GLINT_SHADOW_DENOISER_SanitizeMeanVariance(float2 value)
{
    float mean = GLINT_IsFinite(value.x) ? clamp(value.x, 0.0, 1.0) : 0.0;
    float variance = GLINT_IsFinite(value.y) ? max(value.y, 0.0) : 0.0;
    return float2(mean, variance);
}

// View depth of a receiver, or -1.
float GLINT_SHADOW_DENOISER_ReceiverViewDepth(float depth, float4 viewDepth)
{
    if (!GLINT_IsFinite(depth) || !(depth > 1e-6 && depth < 1.0 - 1e-6))
        return -1.0;
    float z = viewDepth.x / (viewDepth.y + viewDepth.z * depth);
    return GLINT_IsFinite(z) && z > 0.0 ? z : -1.0;
}

float3 GLINT_SHADOW_DENOISER_SanitizeNormal(float3 n)
{
    if (!GLINT_IsFinite(n.x) || !GLINT_IsFinite(n.y) || !GLINT_IsFinite(n.z))
        return float3(0.0, 0.0, 0.0);
    float lengthSquared = dot(n, n);
    if (!(lengthSquared > 1e-12) || !GLINT_IsFinite(lengthSquared))
        return float3(0.0, 0.0, 0.0);
    return n * rsqrt(lengthSquared);
}

float GLINT_SHADOW_DENOISER_KernelWeight(int offset)
{
    return offset == 0 ? 1.0 : 2.0 / 3.0;
}

// Span slot of an image pixel clamped to the image: every load is clamped, so a tap beyond the
// border reads the border pixel (the clamped pixel always lies in the span).
uint GLINT_SHADOW_DENOISER_FilterSlot(int2 pixel, int2 spanOrigin, uint2 inputSize)
{
    int2 local = clamp(pixel, int2(0, 0), int2(inputSize) - 1) - spanOrigin;
    return uint(local.y) * GLINT_SHADOW_DENOISER_FILTER_SPAN + uint(local.x);
}

// Loads the (clamped) pixel of every span slot: sanitized (mean, variance) into value buffer 0,
// (view depth or -1, unit normal) into the geometry. With tile skipping (the tile list), a slot
// whose value is fixed (GLINT_SHADOW_DENOISER_FixedValue: a
// non-receiver, or a receiver in a clear tile, which neither classification nor the earlier
// passes stored) takes that value here, from its tile's metadata word loaded alongside the
// value: no second pass over the span and its barrier.
void GLINT_SHADOW_DENOISER_LoadSpan(uint groupIndex, uint groupThreads, int2 spanOrigin, uint2 inputSize,
                                    float4 viewDepth, float penumbraScale)
{
#if GLINT_SHADOW_DENOISER_TILE_LIST
    uint tilesX = (inputSize.x + GLINT_SHADOW_DENOISER_FILTER_TILE - 1) / GLINT_SHADOW_DENOISER_FILTER_TILE;
#endif
    // At most 4 slots a thread (256 / 64), unrolled so that their loads are in flight together.
    [unroll] for (uint k = 0; k < 4u; ++k)
    {
        uint slot = groupIndex + k * groupThreads;
        if (slot >= GLINT_SHADOW_DENOISER_FILTER_SLOTS)
            break;
        int2 local = int2(slot % GLINT_SHADOW_DENOISER_FILTER_SPAN, slot / GLINT_SHADOW_DENOISER_FILTER_SPAN);
        int2 pixel = clamp(spanOrigin + local, int2(0, 0), int2(inputSize) - 1);
        float2 value = GLINT_SHADOW_DENOISER_SanitizeMeanVariance(GLINT_SHADOW_DENOISER_LoadMeanVariance(pixel));
        // The normal is loaded whatever the depth, so that both loads are in flight together
        // (a load under `z > 0` would wait for the depth).
        float3 loadedNormal = GLINT_SHADOW_DENOISER_LoadNormal(pixel);
        float z = GLINT_SHADOW_DENOISER_ReceiverViewDepth(GLINT_SHADOW_DENOISER_LoadDepth(pixel), viewDepth);
        float3 n = z > 0.0 ? GLINT_SHADOW_DENOISER_SanitizeNormal(loadedNormal) : float3(0.0, 0.0, 0.0);
#if GLINT_SHADOW_DENOISER_TILE_LIST
        uint2 tile = uint2(pixel) / GLINT_SHADOW_DENOISER_FILTER_TILE;
        uint metadata = GLINT_SHADOW_DENOISER_LoadTileMetadata(tile.y * tilesX + tile.x);
        if (!(z > 0.0))
            value = float2(1.0, 0.0);
        else if ((metadata & GLINT_SHADOW_DENOISER_TILE_CLEAR) != 0u)
            value = float2((metadata & GLINT_SHADOW_DENOISER_TILE_LIGHT) != 0u ? 1.0 : 0.0, 0.0);
#endif
        g_glint_shadow_denoiser_filter_values[slot] = value;
        g_glint_shadow_denoiser_filter_geometry[slot] = float4(z, n);
        if (GLINT_SHADOW_DENOISER_PenumbraKnown(penumbraScale))
        {
            float blocker = 0.0;
            if (GLINT_SHADOW_DENOISER_PenumbraReadsBlockers(penumbraScale))
                blocker = GLINT_SHADOW_DENOISER_LoadBlockerDistance(pixel);
            g_glint_shadow_denoiser_filter_penumbra[slot] = GLINT_SHADOW_DENOISER_PenumbraWidth(blocker, z, penumbraScale);
        }
    }
}

// The factor of a pass of step `step` on every neighbour's weight: saturate((W - 1) / step) with W
// the widest penumbra of the pixel's 5 x 5 neighbourhood; 1 when the estimate is off.
float GLINT_SHADOW_DENOISER_PenumbraFootprint(int2 pixel, int2 spanOrigin, uint2 inputSize, uint step,
                                              float penumbraScale)
{
    if (!GLINT_SHADOW_DENOISER_PenumbraKnown(penumbraScale))
        return 1.0;
    float width = 0.0;
    [unroll] for (int y = -2; y <= 2; ++y)
        [unroll] for (int x = -2; x <= 2; ++x)
            width = max(width, g_glint_shadow_denoiser_filter_penumbra[GLINT_SHADOW_DENOISER_FilterSlot(
                                   pixel + int2(x, y), spanOrigin, inputSize)]);
    return saturate((width - 1.0) / float(step));
}

// One a-trous iteration at an in-image receiver pixel, reading value buffer `source`.
float2 GLINT_SHADOW_DENOISER_FilterPixel(int2 pixel, int2 spanOrigin, uint2 inputSize, uint source, uint step,
                                         float depthSigma, float normalPower, float penumbraScale)
{
    uint base = source * GLINT_SHADOW_DENOISER_FILTER_SLOTS;
    uint centreSlot = GLINT_SHADOW_DENOISER_FilterSlot(pixel, spanOrigin, inputSize);
    float4 geometry = g_glint_shadow_denoiser_filter_geometry[centreSlot];
    float2 value = g_glint_shadow_denoiser_filter_values[base + centreSlot];
    // A penumbra under a pixel: no taps, the input as it is.
    float footprint = GLINT_SHADOW_DENOISER_PenumbraFootprint(pixel, spanOrigin, inputSize, step, penumbraScale);
    if (!(footprint > 0.0))
        return value;

    float filteredVariance = 0.0;
    [unroll] for (int y = -1; y <= 1; ++y)
        [unroll] for (int x = -1; x <= 1; ++x)
        {
            float weight = (x == 0 ? 0.5 : 0.25) * (y == 0 ? 0.5 : 0.25);
            uint slot = GLINT_SHADOW_DENOISER_FilterSlot(pixel + int2(x, y), spanOrigin, inputSize);
            filteredVariance += weight * g_glint_shadow_denoiser_filter_values[base + slot].y;
        }
    // The three edge stops as one exponential, 2^(log2(e) (-|ds| / sigma - |dz| / depthScale) +
    // normalPower log2(max(N_c . N_q, 0))): one log2 and one exp2 a tap instead of two exps and
    // a pow. A normal at 90 degrees or more gives log2(0) = -inf and a weight of 0, as pow does.
    float luminanceRate = 1.44269504 / sqrt(filteredVariance + 1e-9);
    float depthRate = 1.44269504 / max(depthSigma * geometry.x, 1e-20);

    // The mean accumulates offsets from the centre (mean = s_c + sum w (s_q - s_c) / sum w):
    // a uniform neighbourhood then returns s_c exactly on every GPU, whatever the precision of
    // its division, so a skipped tile's constant and a filtered tile's result agree bit for bit.
    float weightSum = 1.0;
    float meanOffsetSum = 0.0;
    float varianceSum = value.y;
    [unroll] for (int j = -1; j <= 1; ++j)
        [unroll] for (int i = -1; i <= 1; ++i)
        {
            if (i == 0 && j == 0)
                continue;
            uint slot = GLINT_SHADOW_DENOISER_FilterSlot(pixel + int(step) * int2(i, j), spanOrigin, inputSize);
            float4 other = g_glint_shadow_denoiser_filter_geometry[slot];
            if (other.x <= 0.0)
                continue;
            float2 tap = g_glint_shadow_denoiser_filter_values[base + slot];
            float exponent = normalPower * log2(max(dot(geometry.yzw, other.yzw), 0.0)) -
                             abs(value.x - tap.x) * luminanceRate - abs(geometry.x - other.x) * depthRate;
            float weight = footprint * GLINT_SHADOW_DENOISER_KernelWeight(i) *
                           GLINT_SHADOW_DENOISER_KernelWeight(j) * exp2(exponent);
            weightSum += weight;
            meanOffsetSum += weight * (tap.x - value.x);
            varianceSum += weight * weight * tap.y;
        }
    float mean = clamp(value.x + meanOffsetSum / weightSum, 0.0, 1.0);
    float variance = max(varianceSum / (weightSum * weightSum), 0.0);
    return float2(GLINT_FiniteOr(mean, 0.0), GLINT_FiniteOr(variance, 0.0));
}

float GLINT_SHADOW_DENOISER_ContrastRemap(float2 meanVariance)
{
    return GLINT_FiniteOr(pow(meanVariance.x, max(1.2 - meanVariance.y, 1.0)), 0.0);
}

#if GLINT_SHADOW_DENOISER_TILE_LIST
// Tile metadata of the 3 x 3 filter tiles under the span (8x8 tile + 4), starting at tile
// floor(spanOrigin / 8).
#define GLINT_SHADOW_DENOISER_FILTER_META_ACROSS 3
groupshared uint g_glint_shadow_denoiser_filter_metadata[GLINT_SHADOW_DENOISER_FILTER_META_ACROSS *
                                                         GLINT_SHADOW_DENOISER_FILTER_META_ACROSS];

int2 GLINT_SHADOW_DENOISER_FirstSpanTile(int2 spanOrigin)
{
    // floor(spanOrigin / 8) for spanOrigin >= -8 (integer division truncates towards 0).
    return (spanOrigin + GLINT_SHADOW_DENOISER_FILTER_TILE) / GLINT_SHADOW_DENOISER_FILTER_TILE - 1;
}

void GLINT_SHADOW_DENOISER_LoadSpanMetadata(uint groupIndex, int2 spanOrigin, uint2 inputSize)
{
    uint tilesX = (inputSize.x + GLINT_SHADOW_DENOISER_FILTER_TILE - 1) / GLINT_SHADOW_DENOISER_FILTER_TILE;
    uint tilesY = (inputSize.y + GLINT_SHADOW_DENOISER_FILTER_TILE - 1) / GLINT_SHADOW_DENOISER_FILTER_TILE;
    if (groupIndex < GLINT_SHADOW_DENOISER_FILTER_META_ACROSS * GLINT_SHADOW_DENOISER_FILTER_META_ACROSS)
    {
        // Tiles beyond the image hold only pixels no lookup reaches (lookups clamp to the image).
        int2 tile = GLINT_SHADOW_DENOISER_FirstSpanTile(spanOrigin) +
                    int2(groupIndex % GLINT_SHADOW_DENOISER_FILTER_META_ACROSS, groupIndex / GLINT_SHADOW_DENOISER_FILTER_META_ACROSS);
        tile = clamp(tile, int2(0, 0), int2(tilesX, tilesY) - 1);
        g_glint_shadow_denoiser_filter_metadata[groupIndex] =
            GLINT_SHADOW_DENOISER_LoadTileMetadata(uint(tile.y) * tilesX + uint(tile.x));
    }
}
#endif

// The value of an in-image pixel that is not filtered: a non-receiver's (1, 0) or, with tile
// skipping, a clear tile's constant; what every filter pass writes there.
// Returns false for pixels to filter. Needs the span (and its metadata) loaded.
bool GLINT_SHADOW_DENOISER_FixedValue(int2 pixel, int2 spanOrigin, uint2 inputSize, out float2 fixedValue)
{
    uint slot = GLINT_SHADOW_DENOISER_FilterSlot(pixel, spanOrigin, inputSize);
    fixedValue = float2(1.0, 0.0);
    bool receiver = g_glint_shadow_denoiser_filter_geometry[slot].x > 0.0;
    if (!receiver)
        return true;
#if GLINT_SHADOW_DENOISER_TILE_LIST
    int2 tile = pixel / GLINT_SHADOW_DENOISER_FILTER_TILE - GLINT_SHADOW_DENOISER_FirstSpanTile(spanOrigin);
    uint metadata = g_glint_shadow_denoiser_filter_metadata[tile.y * GLINT_SHADOW_DENOISER_FILTER_META_ACROSS + tile.x];
    if ((metadata & GLINT_SHADOW_DENOISER_TILE_CLEAR) != 0u)
    {
        fixedValue = float2((metadata & GLINT_SHADOW_DENOISER_TILE_LIGHT) != 0u ? 1.0 : 0.0, 0.0);
        return true;
    }
#endif
    return false;
}

// The 8 x 8 filters' start: the group's tile (from the list with GLINT_SHADOW_DENOISER_TILE_LIST,
// counted `iterations` times), its span loaded into value buffer 0 and the geometry, clear
// neighbours fixed. Returns the tile's first pixel; spanOrigin is the span's.
int2 GLINT_SHADOW_DENOISER_FilterBegin(uint2 groupId, uint groupIndex, uint2 inputSize, float4 viewDepth,
                                       float penumbraScale, uint iterations, out int2 spanOrigin)
{
#if GLINT_SHADOW_DENOISER_TILE_LIST
    // Only the tiles classification listed (never clear ones) are dispatched; the others hold
    // their constant in the output already (classification wrote it).
    groupId = GLINT_SHADOW_DENOISER_LoadFilterTile(groupId.x);
    if (groupIndex == 0)
        for (uint i = 0; i < iterations; ++i)
            GLINT_SHADOW_DENOISER_CountFilteredTile();
#endif
    int2 tileOrigin = int2(groupId * GLINT_SHADOW_DENOISER_FILTER_TILE);
    spanOrigin = tileOrigin - GLINT_SHADOW_DENOISER_FILTER_APRON;
    GLINT_SHADOW_DENOISER_LoadSpan(groupIndex, 64u, spanOrigin, inputSize, viewDepth, penumbraScale);
#if GLINT_SHADOW_DENOISER_TILE_LIST
    // Neighbouring clear tiles were not stored by classification or the earlier passes: their
    // span slots were fixed by LoadSpan; the words stay for GLINT_SHADOW_DENOISER_FixedValue.
    GLINT_SHADOW_DENOISER_LoadSpanMetadata(groupIndex, spanOrigin, inputSize);
#endif
    GroupMemoryBarrierWithGroupSync();
    return tileOrigin;
}

#if GLINT_SHADOW_DENOISER_FILTER_PAIR
// Iterations 1 and 2 (steps 1 and 2) of an 8 x 8 tile. The second reads the first's results
// at the tile +- 2 pixels (its taps; its 3x3 variance needs +- 1), which read the span at
// +- 3: within the 4-pixel apron. Clear and non-receiver pixels take their fixed value in
// both, as the separate dispatches give them.
void GLINT_SHADOW_DENOISER_FilterPair(uint2 groupId, uint2 groupThreadId, uint groupIndex, uint2 inputSize,
                                      float4 viewDepth, float depthSigma, float normalPower, float penumbraScale)
{
    int2 spanOrigin;
    int2 tileOrigin =
        GLINT_SHADOW_DENOISER_FilterBegin(groupId, groupIndex, inputSize, viewDepth, penumbraScale, 2u, spanOrigin);
    const uint width = GLINT_SHADOW_DENOISER_FILTER_TILE + 4u;
    // 144 pixels over 64 threads: 3 rounds for the first 16, 2 for the others.
    [loop] for (uint i = groupIndex; i < width * width; i += 64u)
    {
        int2 pixel = tileOrigin - 2 + int2(i % width, i / width);
        if (any(uint2(pixel) >= inputSize))
            continue;
        float2 value;
        if (!GLINT_SHADOW_DENOISER_FixedValue(pixel, spanOrigin, inputSize, value))
            value = GLINT_SHADOW_DENOISER_FilterPixel(pixel, spanOrigin, inputSize, 0u, 1u, depthSigma, normalPower,
                                                      penumbraScale);
        g_glint_shadow_denoiser_filter_values[GLINT_SHADOW_DENOISER_FILTER_SLOTS +
                                              GLINT_SHADOW_DENOISER_FilterSlot(pixel, spanOrigin, inputSize)] = value;
    }
    GroupMemoryBarrierWithGroupSync();

    int2 pixel = tileOrigin + int2(groupThreadId);
    if (any(uint2(pixel) >= inputSize))
        return;
    float2 result;
    if (!GLINT_SHADOW_DENOISER_FixedValue(pixel, spanOrigin, inputSize, result))
        result = GLINT_SHADOW_DENOISER_FilterPixel(pixel, spanOrigin, inputSize, 1u, 2u, depthSigma, normalPower,
                                                   penumbraScale);
    GLINT_SHADOW_DENOISER_StoreFiltered(pixel, result);
}
#endif

void GLINT_SHADOW_DENOISER_Filter(uint2 groupId, uint2 groupThreadId, uint groupIndex, uint2 inputSize, uint step,
                                  bool finalPass, float4 viewDepth, float depthSigma, float normalPower,
                                  float penumbraScale)
{
    int2 spanOrigin;
    int2 tileOrigin =
        GLINT_SHADOW_DENOISER_FilterBegin(groupId, groupIndex, inputSize, viewDepth, penumbraScale, 1u, spanOrigin);
    int2 pixel = tileOrigin + int2(groupThreadId);
    if (any(uint2(pixel) >= inputSize))
        return;
    if (g_glint_shadow_denoiser_filter_geometry[GLINT_SHADOW_DENOISER_FilterSlot(pixel, spanOrigin, inputSize)].x <= 0.0)
    {
        GLINT_SHADOW_DENOISER_StoreFiltered(pixel, float2(1.0, 0.0));
        return;
    }
    float2 result =
        GLINT_SHADOW_DENOISER_FilterPixel(pixel, spanOrigin, inputSize, 0u, step, depthSigma, normalPower, penumbraScale);
    if (finalPass)
        result.x = GLINT_SHADOW_DENOISER_ContrastRemap(result);
    GLINT_SHADOW_DENOISER_StoreFiltered(pixel, result);
}

#endif // GLINT_SHADOW_DENOISER_FILTER_HLSLI
