// glint reflections denoiser, pass 1: reproject (docs/reflections_denoiser.md). For every
// pixel of a listed tile: neighbourhood statistics of the noisy sample, a firefly clamp, the
// history fetched along the surface motion or the reflection's parallax (whichever fits;
// mirrors only the parallax, tested against their noise-free sample),
// the history length and temporal variance, this frame's guides for next frame, and the
// tile's luminance-weighted average radiance.
//
// Integration: the callbacks of glint_reflections_denoiser_common.hlsli, and
//
//   float4 GLINT_RD_LoadNoisy(int2 pixel);              SSSR radiance: rgb, a = hit distance (65504 = miss)
//   float2 GLINT_RD_LoadMotion(int2 pixel);             motion vector (scaled by motionScale: convention A)
//   uint   GLINT_RD_LoadHistoryTileMask(uint2 tile);    last frame's tile mask word (see
//                                                       glint_reflections_denoiser_constants.h)
//   float4 GLINT_RD_LoadHistoryGuides(int2 pixel);      last frame's (octahedral normal, view depth, alpha); depth 0: not glossy
//   float4 GLINT_RD_LoadHistoryRadianceAndVariance(int2 pixel);
//                                                       last frame's resolved radiance, a = its final
//                                                       variance (both from the resolve's radiance history)
//   float  GLINT_RD_LoadHistoryLength(int2 pixel);
//   void   GLINT_RD_StoreClamped(int2 pixel, float4 radianceAndVariance);
//                                                       rgb, a = the variance also given to StoreVariance
//                                                       (GLINT_RD_NOT_GLOSSY: not glossy), so that a
//                                                       prefilter span pixel is one fetch, flag included
//   void   GLINT_RD_StoreReprojected(int2 pixel, float4 historyAndValidity);
//   void   GLINT_RD_StoreVariance(int2 pixel, float variance);
//   void   GLINT_RD_StoreHistoryLength(int2 pixel, float length);
//   void   GLINT_RD_StoreGuides(int2 pixel, float4 guides);
//   void   GLINT_RD_StoreAverage(uint2 tile, float4 average);   rgb, a = weight sum
//   void   GLINT_RD_MarkTile(uint2 tile, uint bits);             this frame's tile mask: atomic OR
//
// Entry: from main, GLINT_RD_Reproject(c, SV_GroupID.x, SV_GroupThreadID.xy), c the
// GLINT_ReflectionsDenoiserConstants in a cbuffer (glint_reflections_denoiser_common.hlsli).
// Dispatch: [numthreads(8, 8, 1)] (also in the 16-bit permutation), indirect (tiles, 1, 1) from
// SSSR's arguments at byte 12.
#ifndef GLINT_REFLECTIONS_DENOISER_REPROJECT_HLSLI
#define GLINT_REFLECTIONS_DENOISER_REPROJECT_HLSLI

#define GLINT_RD_USES_ROW_STATISTICS 1
#include "glint/reflections_denoiser/glint_reflections_denoiser_common.hlsli"

float4 GLINT_RD_LoadNoisy(int2 pixel);
float2 GLINT_RD_LoadMotion(int2 pixel);
uint GLINT_RD_LoadHistoryTileMask(uint2 tile);
float4 GLINT_RD_LoadHistoryGuides(int2 pixel);
float4 GLINT_RD_LoadHistoryRadianceAndVariance(int2 pixel);
float GLINT_RD_LoadHistoryLength(int2 pixel);
void GLINT_RD_StoreClamped(int2 pixel, float4 radianceAndVariance);
void GLINT_RD_StoreReprojected(int2 pixel, float4 historyAndValidity);
void GLINT_RD_StoreVariance(int2 pixel, float variance);
void GLINT_RD_StoreHistoryLength(int2 pixel, float length);
void GLINT_RD_StoreGuides(int2 pixel, float4 guides);
void GLINT_RD_StoreAverage(uint2 tile, float4 average);
void GLINT_RD_MarkTile(uint2 tile, uint bits);

// The span's noisy rgb (0 for pixels that are not glossy) and hit distance (-1: not glossy)
// (GLINT_RD_SpanTexel): the neighbourhood statistics, the nearest hit and, in 32-bit spans, the
// pixel's own sample (in half spans the pixel's thread loads its own sample, which stays 32-bit).
groupshared GLINT_RD_SpanTexel g_glint_rd_noisy[GLINT_RD_SPAN * GLINT_RD_SPAN];
groupshared float4 g_glint_rd_average[GLINT_RD_TILE * GLINT_RD_TILE];

struct GLINT_RD_History
{
    float3 radiance;
    float variance;
    float length;
    float3 normal;
    float alpha;
    bool valid;
};

// One candidate's 2x2 history taps as fetched, none of them tested yet. Fetching and testing
// are separate so that a candidate's loads can be issued long before its values are needed
// (the on-surface candidate's before the span barrier, the parallax candidate's before the 9x9
// statistics), and the latencies hide behind that work.
struct GLINT_RD_HistoryTaps
{
    float2 f;           // bilinear fraction
    bool usable;        // uv inside the image, no reset
    bool listed[4];
    float4 guides[4];
    float4 radiance[4]; // rgb, a = variance
    float length[4];
};

// The 2x2 taps around uv. The taps are clamped to the image whatever uv is (a non-finite one
// included), so that no branch stands between the loads; whether uv was usable is tested in
// GLINT_RD_EvaluateHistory. All loads of the four taps are issued before any of them is tested
// (testing a tap's guides before fetching its radiance serialised memory round trips per tap).
GLINT_RD_HistoryTaps GLINT_RD_FetchHistory(GLINT_ReflectionsDenoiserConstants c, float2 uv)
{
    GLINT_RD_HistoryTaps taps;
    taps.usable = all(uv > 0.0) && all(uv < 1.0) && (c.flags & GLINT_RD_FLAG_RESET) == 0;
    float2 p = clamp(uv, -1.0, 2.0) * float2(c.inputSize) - 0.5;
    float2 base = floor(p);
    taps.f = p - base;
    // The taps lie in the first tap's tile or the next one right or down (the clamp keeps them
    // in order), so that tile's mask word answers for all four: one load instead of four.
    uint2 firstTile = uint2(clamp(int2(base), int2(0, 0), int2(c.inputSize) - 1)) / GLINT_RD_TILE;
    uint maskWord = GLINT_RD_LoadHistoryTileMask(firstTile);
    [unroll] for (uint tap = 0; tap < 4; ++tap)
    {
        int2 offset = int2(tap & 1u, tap >> 1);
        int2 pixel = clamp(int2(base) + offset, int2(0, 0), int2(c.inputSize) - 1);
        uint2 step = uint2(pixel) / GLINT_RD_TILE - firstTile; // 0 or 1 each
        taps.listed[tap] = (maskWord & (GLINT_RD_MASK_SELF << (step.y * 2u + step.x))) != 0;
        taps.guides[tap] = GLINT_RD_LoadHistoryGuides(pixel);
        taps.radiance[tap] = GLINT_RD_LoadHistoryRadianceAndVariance(pixel);
        taps.length[tap] = GLINT_RD_LoadHistoryLength(pixel);
    }
    return taps;
}

// Bilinear history from the 2x2 taps that were glossy last frame, in a tile listed last frame,
// and whose normal and depth match this pixel's (disocclusion weight >= 0.9 per tap). Accepted
// when the accepted taps carry at least half of the bilinear weight and every value they carry
// is finite.
//
// Lean per tap (it runs 8 times a pixel): no tap value is sanitised, because the one
// finiteness test of the sums below covers every accepted tap; the smaller code is what the
// separable statistics need to pay off (docs/performance.md, "Reflections denoiser reproject:
// history taps without per-tap sanitising"). A tap enters the sums through a select, so a
// rejected tap adds exactly nothing whatever it holds (stale, uninitialised or non-finite: a
// product with a zero weight would not do, NaN * 0 is NaN). A non-finite guide rejects its tap
// by itself: every comparison with NaN is false and an infinite misfit is not <= 0.105. A
// non-finite value in an accepted tap makes its sum non-finite, and the history is discarded.
// expected: the view depth last frame's camera sees this pixel's surface at, and its reciprocal.
GLINT_RD_History GLINT_RD_EvaluateHistory(GLINT_RD_HistoryTaps taps, GLINT_RD_Surface surface, float2 expected)
{
    GLINT_RD_History h = (GLINT_RD_History)0;
    float total = 0.0;
    float3 normalSum = float3(0.0, 0.0, 0.0);
    [unroll] for (uint t = 0; t < 4; ++t)
    {
        int2 offset = int2(t & 1u, t >> 1);
        float weight = (offset.x == 1 ? taps.f.x : 1.0 - taps.f.x) * (offset.y == 1 ? taps.f.y : 1.0 - taps.f.y);
        float4 guides = taps.guides[t];
        float3 n = GLINT_RD_DecodeNormal(guides.xy);
        // exp(-1.4 |1 - max(0, N.n)|) exp(-|z - z'| / z') >= 0.9, compared as exponents (no
        // exp: the same test, monotonic): 1.4 |1 - max(0, N.n)| + |z - z'| / z' <= -ln 0.9.
        float misfit = abs(1.0 - max(0.0, dot(n, surface.normal))) * 1.4 +
                       abs(guides.z - expected.x) * expected.y;
        bool accepted = weight > 0.0 && taps.listed[t] && guides.z > 0.0 && misfit <= 0.10536052;
        float4 radiance = taps.radiance[t];
        h.radiance = accepted ? h.radiance + weight * radiance.rgb : h.radiance;
        h.variance = accepted ? h.variance + weight * radiance.a : h.variance;
        h.length = accepted ? h.length + weight * taps.length[t] : h.length;
        h.alpha = accepted ? h.alpha + weight * guides.w : h.alpha;
        normalSum = accepted ? normalSum + weight * n : normalSum;
        total = accepted ? total + weight : total;
    }
    float inverse = 1.0 / max(total, 0.5);
    h.radiance *= inverse;
    h.variance *= inverse;
    h.length *= inverse;
    h.alpha *= inverse;
    h.normal = normalize(normalSum);
    float check = dot(h.radiance, float3(1.0, 1.0, 1.0)) + h.variance + h.length + h.alpha;
    h.valid = taps.usable && total >= 0.5 && GLINT_IsFinite(check);
    // Stored values are within these ranges; a history written by anything else is brought
    // into them (finite already: the sums are).
    h.radiance = clamp(h.radiance, 0.0, 65504.0);
    h.variance = clamp(h.variance, 0.0, 65504.0);
    h.length = clamp(h.length, 0.0, 65504.0);
    h.alpha = GLINT_Saturate(h.alpha);
    return h;
}

void GLINT_RD_Reproject(GLINT_ReflectionsDenoiserConstants c, uint groupId, uint2 local)
{
    uint entry = GLINT_RD_LoadTile(groupId);
    uint2 tileOrigin = uint2(GLINT_WIRE_TileEntryX(entry), GLINT_WIRE_TileEntryY(entry));
    uint localIndex = local.y * GLINT_RD_TILE + local.x;
    uint2 pixel = tileOrigin + local;
    bool inImage = all(pixel < c.inputSize);
    int2 ipixel = int2(min(pixel, c.inputSize - 1));
    // The pixel's own surface and motion need nothing from the group: loaded with the span, so
    // that they are in flight together instead of a round trip of their own after the barrier.
    GLINT_RD_Surface surface = GLINT_RD_LoadSurface(c, ipixel);
    float2 motion = GLINT_RD_LoadMotion(ipixel) * c.motionScale;
#if GLINT_RD_HALF_GROUPSHARED
    // The span holds halves: the pixel's own sample is loaded 32-bit.
    float3 ownNoisy = GLINT_RD_LoadNoisy(ipixel).rgb;
#endif
    // Unrolled (exactly 4 span slots a thread) so that the loads of all four are in flight
    // together instead of one slot's round trip after the other.
    [unroll] for (uint k = 0; k < GLINT_RD_SPAN * GLINT_RD_SPAN / (GLINT_RD_TILE * GLINT_RD_TILE); ++k)
    {
        uint i = localIndex + k * GLINT_RD_TILE * GLINT_RD_TILE;
        int2 spanPixel = GLINT_RD_SpanPixel(c, tileOrigin, i);
        GLINT_RD_Surface s = GLINT_RD_LoadSurface(c, spanPixel);
        float4 noisy = GLINT_RD_LoadNoisy(spanPixel);
        g_glint_rd_noisy[i] = GLINT_RD_PackSpanTexel(s.glossy ? float4(GLINT_RD_SanitizeRadiance(noisy.rgb),
                                                                   clamp(GLINT_FiniteOr(noisy.a, GLINT_RD_MISS_DISTANCE),
                                                                         0.0, GLINT_RD_MISS_DISTANCE))
                                                          : float4(0.0, 0.0, 0.0, -1.0));
    }

    float2 uv = (float2(ipixel) + 0.5) * c.inverseInputSize;
    float3 viewPosition = GLINT_RD_ViewPosition(c, uv, surface.depth);
    float expectedViewDepth;
    GLINT_RD_PreviousUv(c, viewPosition, expectedViewDepth);
    expectedViewDepth = max(expectedViewDepth, 1e-6);
    float2 expected = float2(expectedViewDepth, 1.0 / expectedViewDepth);
    // The on-surface candidate needs no neighbour either: its taps are fetched before the
    // barrier and arrive while the group synchronises.
    GLINT_RD_HistoryTaps surfaceTaps = (GLINT_RD_HistoryTaps)0;
    if (surface.glossy)
    {
        float2 surfaceUv = uv + float2(GLINT_FiniteOr(motion.x, 1e9), GLINT_FiniteOr(motion.y, 1e9));
        surfaceTaps = GLINT_RD_FetchHistory(c, surfaceUv);
    }
    GroupMemoryBarrierWithGroupSync();

    uint centre = (local.y + GLINT_RD_APRON) * GLINT_RD_SPAN + local.x + GLINT_RD_APRON;
#if GLINT_RD_HALF_GROUPSHARED
    float3 current = surface.glossy ? GLINT_RD_SanitizeRadiance(ownNoisy) : float3(0.0, 0.0, 0.0);
#else
    float3 current = GLINT_RD_UnpackSpanTexel(g_glint_rd_noisy[centre]).rgb; // the same value, one load fewer
#endif

    // The nearest hit of the 3x3 (one noisy hit distance is a poor parallax estimate:
    // docs/conventions.md, defect RD11). First, so that the parallax candidate's taps are
    // fetched before the 9x9 statistics, which then hide their latency.
    //
    // A mirror's own hit distance is exact (its ray is the mirror direction, not a sample), and
    // the nearest of its neighbours' may belong to another object at a reflection's edge: a
    // mirror follows its own reflected point (docs/reflections_denoiser.md, "Mirrors").
    bool mirror = surface.alpha < c.mirrorThreshold;
    float hitDistance = GLINT_RD_MISS_DISTANCE;
    [unroll] for (int hy = -1; hy <= 1; ++hy)
        [unroll] for (int hx = -1; hx <= 1; ++hx)
        {
            float a = GLINT_RD_UnpackSpanTexel(g_glint_rd_noisy[centre + hy * GLINT_RD_SPAN + hx]).a;
            bool counts = a >= 0.0 && (!mirror || (hx == 0 && hy == 0));
            hitDistance = min(hitDistance, counts ? a : GLINT_RD_MISS_DISTANCE);
        }
    GLINT_RD_HistoryTaps virtualTaps = (GLINT_RD_HistoryTaps)0;
    if (surface.glossy)
    {
        // Parallax: the reflected point continued behind the mirror, reprojected. A miss's
        // "infinite" distance makes it rotation-only.
        float viewLength = length(viewPosition);
        float3 virtualPoint = viewPosition / max(viewLength, 1e-12) * (viewLength + hitDistance);
        float unused;
        virtualTaps = GLINT_RD_FetchHistory(c, GLINT_RD_PreviousUv(c, virtualPoint, unused));
    }
    // The on-surface taps were issued before the barrier and have had it to arrive: tested now,
    // under the parallax taps' latency, so that only the tested history (not the raw taps)
    // stays live through the statistics.
    GLINT_RD_History onSurface = (GLINT_RD_History)0;
    if (surface.glossy)
        onSurface = GLINT_RD_EvaluateHistory(surfaceTaps, surface, expected);

    // 9x9 Gaussian statistics over glossy neighbours, separably (GLINT_RD_AccumulateRowPair).
    // Only glossy pixels use them (a pixel that is not glossy has current = 0, which the clamp
    // below keeps); every thread takes part in the row sums. A neighbour that is not glossy
    // holds rgb 0 and a negative distance: its mask is 0.
    {
        GLINT_RD_RowPair pair = (GLINT_RD_RowPair)0;
        uint first = GLINT_RD_RowPairRow(localIndex) * GLINT_RD_SPAN + GLINT_RD_RowPairColumn(localIndex);
        [unroll] for (int i = 0; i < 2 * GLINT_RD_APRON + 2; ++i)
        {
            float4 q = GLINT_RD_UnpackSpanTexel(g_glint_rd_noisy[first + uint(i)]);
            GLINT_RD_AccumulateRowPair(pair, i, q.rgb, q.a < 0.0 ? 0.0 : 1.0, 0.0);
        }
        GLINT_RD_StoreRowPair(localIndex, pair);
    }
    GroupMemoryBarrierWithGroupSync();
    float3 sum = float3(0.0, 0.0, 0.0);
    float3 sumSquares = float3(0.0, 0.0, 0.0);
    float weightSum = 0.0;
    float unusedExtra = 0.0;
    if (surface.glossy)
        GLINT_RD_ColumnStatistics(local, sum, sumSquares, weightSum, unusedExtra);
    float3 mean = weightSum > 0.0 ? sum / weightSum : current;
    float3 variance3 = weightSum > 0.0 ? abs(sumSquares / weightSum - mean * mean) : float3(0.0, 0.0, 0.0);
    float3 sigma = sqrt(variance3);
    // Firefly clamp before any spatial reuse (docs/conventions.md, defect RD14). Its bound
    // widens as the spatial footprint shrinks and is gone for mirrors, whose samples are
    // noise-free: a bright reflected highlight is not a firefly (GLINT_RD_SpatialFootprint).
    float footprint = GLINT_RD_SpatialFootprint(c, surface.alpha);
    current = footprint > 0.0 ? min(current, mean + 3.0 * sigma / footprint) : current;

    GLINT_RD_History history = (GLINT_RD_History)0;
    history.valid = false;
    if (surface.glossy)
    {
        GLINT_RD_History virtualHistory = GLINT_RD_EvaluateHistory(virtualTaps, surface, expected);
        float virtualFit = dot(virtualHistory.normal, surface.normal);
        float surfaceFit = onSurface.valid ? dot(onSurface.normal, surface.normal) : -1.0;
        // A mirror reuses only the parallax candidate: what it shows moves with the reflected
        // point, not with its surface.
        bool useVirtual = virtualHistory.valid && virtualFit > 0.9999 &&
                          (mirror || (virtualFit + 1e-3 > surfaceFit &&
                                      (!onSurface.valid || abs(virtualHistory.alpha - surface.alpha) <
                                                               abs(onSurface.alpha - surface.alpha) + 1e-3)));
        float3 surfaceOffset = onSurface.radiance - mean;
        if (useVirtual)
            history = virtualHistory;
        else if (!mirror && onSurface.valid && dot(surfaceOffset, surfaceOffset) < 1.5 * length(variance3) + 1e-6)
            history = onSurface;
        // A mirror's sample is noise-free: a history outside the band around it shows another
        // point (an object that moved, a wrong hit distance) and is rejected, not blended.
        if (mirror && any(abs(history.radiance - current) > GLINT_RD_MirrorBand(current)))
            history.valid = false;
    }

    float3 reprojected = float3(0.0, 0.0, 0.0);
    float temporalVariance = 0.0;
    float historyLength = 0.0;
    float3 contribution = current;
    if (surface.glossy && history.valid)
    {
        historyLength = min(GLINT_RD_MaxHistoryLength(c, surface.alpha), history.length + 1.0);
        float lumaCurrent = max(GLINT_RD_Luma(current), 0.001);
        float lumaHistory = max(GLINT_RD_Luma(history.radiance), 0.001);
        float difference = abs(lumaCurrent - lumaHistory) / max(max(lumaCurrent, lumaHistory), 0.5);
        // The variance is the running mean of the squared relative difference over the history
        // (docs/conventions.md, defect RD10: the reference weights the history by 1/n instead).
        temporalVariance = lerp(history.variance, difference * difference, 1.0 / historyLength);
        reprojected = history.radiance;
        contribution = lerp(current, history.radiance, 0.3);
    }
    else if (surface.glossy)
    {
        temporalVariance = 1.0;
        historyLength = 1.0;
    }

    // The pixel's own outputs do not depend on the tile average: stored before the reduction,
    // so that they leave while the group reduces.
    if (inImage)
    {
        float storedVariance = clamp(GLINT_FiniteOr(temporalVariance, 1.0), 0.0, 65504.0);
        GLINT_RD_StoreClamped(ipixel, float4(GLINT_RD_SanitizeRadiance(current),
                                             surface.glossy ? storedVariance : GLINT_RD_NOT_GLOSSY));
        GLINT_RD_StoreReprojected(ipixel, float4(GLINT_RD_SanitizeRadiance(reprojected), history.valid ? 1.0 : 0.0));
        GLINT_RD_StoreVariance(ipixel, storedVariance);
        GLINT_RD_StoreHistoryLength(ipixel, historyLength);
        GLINT_RD_StoreGuides(ipixel, float4(GLINT_RD_EncodeNormal(surface.normal),
                                            surface.glossy ? surface.viewDepth : 0.0, surface.alpha));
    }

    // The tile's luminance-weighted average (bright outliers weigh less).
    float weight = surface.glossy && inImage ? max(exp(-0.3 * GLINT_RD_Luma(contribution)), 0.01) : 0.0;
    // In two rounds, eight threads summing eight values each and then one thread the eight sums:
    // one barrier instead of the six of a pairwise tree. The serial adds cost less than the
    // barriers they replace (docs/performance.md, "Reflections denoiser reproject: tile average
    // in two rounds").
    g_glint_rd_average[localIndex] = float4(contribution * weight, weight);
    GroupMemoryBarrierWithGroupSync();
    if (localIndex < GLINT_RD_TILE)
    {
        float4 rowSum = g_glint_rd_average[localIndex];
        [unroll] for (uint k = 1; k < GLINT_RD_TILE; ++k)
            rowSum += g_glint_rd_average[localIndex + k * GLINT_RD_TILE];
        g_glint_rd_average[localIndex] = rowSum;
    }
    GroupMemoryBarrierWithGroupSync();
    uint2 tile = tileOrigin / GLINT_RD_TILE;
    if (localIndex == 0)
    {
        float4 total = g_glint_rd_average[0];
        [unroll] for (uint k = 1; k < GLINT_RD_TILE; ++k)
            total += g_glint_rd_average[k];
        GLINT_RD_StoreAverage(tile, float4(GLINT_RD_SanitizeRadiance(total.rgb / max(total.a, 1e-3)), total.a));
    }
    // The tile's bit in its own mask word and in those of the tiles left of, above and
    // diagonally before it (one thread each): bit dy * 2 + dx of tile t means t + (dx, dy).
    if (localIndex < 4)
    {
        int2 step = int2(localIndex & 1u, localIndex >> 1);
        int2 owner = int2(tile) - step;
        if (all(owner >= 0))
            GLINT_RD_MarkTile(uint2(owner), GLINT_RD_MASK_SELF << localIndex);
    }
}

#endif // GLINT_REFLECTIONS_DENOISER_REPROJECT_HLSLI
