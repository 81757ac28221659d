// glint reflections denoiser, pass 3: temporal resolve (docs/reflections_denoiser.md).
// Neighbourhood statistics of the prefiltered radiance, an anti-lag test that shortens the
// history length where the neighbourhood's histories disagree with its samples by more than
// noise explains, history clipping toward the statistics, and a blend by history length
// (mirrors: their noise-free sample, no blend). The result is written
// over SSSR's radiance in place (so that the effect's output is defined in every tile: unlisted
// tiles keep classification's values) and into this frame's radiance history; the variance
// feeds next frame and SSSR's TVGT.
//
// Integration: of the callbacks of glint_reflections_denoiser_common.hlsli only GLINT_RD_LoadTile
// and GLINT_RD_LoadRoughness are called (and the average's), and
//
//   float4 GLINT_RD_LoadPrefiltered(int2 pixel);    rgb, a = variance (GLINT_RD_NOT_GLOSSY: not glossy;
//                                                   defined in tiles listed this frame)
//   float4 GLINT_RD_LoadReprojected(int2 pixel);    history rgb, a = 1 when valid
//   float  GLINT_RD_LoadLength(int2 pixel);         this frame's history length (reproject)
//   void   GLINT_RD_StoreLength(int2 pixel, float length);
//                                                   the same image, glossy pixels only: the length
//                                                   after the anti-lag (next frame's reproject reads it)
//   float4 GLINT_RD_LoadNoisy(int2 pixel);          SSSR radiance (its alpha, the hit distance, is kept)
//   void   GLINT_RD_StoreOutput(int2 pixel, float4 radianceAndHitDistance);
//   void   GLINT_RD_StoreRadianceHistory(int2 pixel, float4 radianceAndVariance);
//                                                   rgb, a = the variance also given to StoreVariance
//                                                   (next frame's reproject reads both in one fetch)
//   void   GLINT_RD_StoreVariance(int2 pixel, float variance);
//
// Entry: from main, GLINT_RD_Resolve(c, SV_GroupID.x, SV_GroupThreadID.xy), c the
// GLINT_ReflectionsDenoiserConstants in a cbuffer (glint_reflections_denoiser_common.hlsli).
// Dispatch: [numthreads(8, 8, 1)] (also in the 16-bit permutation), indirect (tiles, 1, 1) from
// SSSR's arguments at byte 12.
#ifndef GLINT_REFLECTIONS_DENOISER_RESOLVE_HLSLI
#define GLINT_REFLECTIONS_DENOISER_RESOLVE_HLSLI

#define GLINT_RD_USES_AVERAGE 1
#define GLINT_RD_USES_ROW_STATISTICS 1
#include "glint/reflections_denoiser/glint_reflections_denoiser_common.hlsli"

float4 GLINT_RD_LoadPrefiltered(int2 pixel);
float4 GLINT_RD_LoadReprojected(int2 pixel);
float GLINT_RD_LoadLength(int2 pixel);
void GLINT_RD_StoreLength(int2 pixel, float length);
float4 GLINT_RD_LoadNoisy(int2 pixel);
void GLINT_RD_StoreOutput(int2 pixel, float4 radianceAndHitDistance);
void GLINT_RD_StoreRadianceHistory(int2 pixel, float4 radianceAndVariance);
void GLINT_RD_StoreVariance(int2 pixel, float variance);

// Prefiltered rgb of the span; a = 1 for glossy pixels, 0 otherwise (GLINT_RD_SpanTexel). The
// pixel's own value is its thread's 32-bit load in either span format.
groupshared GLINT_RD_SpanTexel g_glint_rd_resolve_radiance[GLINT_RD_SPAN * GLINT_RD_SPAN];
// The anti-lag's difference of the span: luma(reprojected history) - luma(prefiltered sample) for
// glossy pixels with a valid history, 0 otherwise (and everywhere with the anti-lag off). 32-bit
// in both permutations.
groupshared float g_glint_rd_resolve_lag[GLINT_RD_SPAN * GLINT_RD_SPAN];

void GLINT_RD_Resolve(GLINT_ReflectionsDenoiserConstants c, uint groupId, uint2 local)
{
    uint entry = GLINT_RD_LoadTile(groupId);
    uint2 tileOrigin = uint2(GLINT_WIRE_TileEntryX(entry), GLINT_WIRE_TileEntryY(entry));
    uint localIndex = local.y * GLINT_RD_TILE + local.x;
    uint2 pixel = tileOrigin + local;
    bool inImage = all(pixel < c.inputSize);
    int2 ipixel = int2(min(pixel, c.inputSize - 1));
    // The pixel's own inputs need nothing from the group, and the tile averages are loaded by
    // nine threads: all with the span, so that they arrive while the group synchronises. The
    // output image is read before the group writes it: every pixel is read and written by its
    // own thread only.
    uint2 tile = tileOrigin / GLINT_RD_TILE;
    GLINT_RD_LoadTileAverages(c, tile, localIndex);
    float4 prefiltered = GLINT_RD_LoadPrefiltered(ipixel);
    float4 reprojected = GLINT_RD_LoadReprojected(ipixel);
    float storedLength = GLINT_RD_LoadLength(ipixel);
    float hitDistance = GLINT_RD_LoadNoisy(ipixel).a;
    float alpha = GLINT_FiniteOr(GLINT_RD_LoadRoughness(ipixel), 1.0);
    bool antiLag = (c.flags & GLINT_RD_FLAG_ANTI_LAG) != 0;
    // Unrolled (exactly 4 span slots a thread) so that the loads of all four are in flight
    // together instead of one slot's round trip after the other.
    //
    // A slot is one prefiltered fetch and its tile's mask word (the same few words across a
    // wave), instead of the surface's depth, normal and roughness as well: the prefilter (or the
    // reconstruction) marks pixels that are not glossy with GLINT_RD_NOT_GLOSSY in alpha, and
    // glossy pixels hold their variance there, never negative. Only listed tiles hold this
    // frame's values; in the others no pixel is glossy (GLINT_RD_PixelListed). With the anti-lag,
    // a slot also fetches its reprojected history (reproject wrote it in every listed tile).
    [unroll] for (uint k = 0; k < GLINT_RD_SPAN * GLINT_RD_SPAN / (GLINT_RD_TILE * GLINT_RD_TILE); ++k)
    {
        uint i = localIndex + k * GLINT_RD_TILE * GLINT_RD_TILE;
        int2 spanPixel = GLINT_RD_SpanPixel(c, tileOrigin, i);
        bool listed = GLINT_RD_PixelListed(spanPixel);
        float4 spanPrefiltered = GLINT_RD_LoadPrefiltered(spanPixel);
        float4 spanHistory = float4(0.0, 0.0, 0.0, 0.0);
        if (antiLag)
            spanHistory = GLINT_RD_LoadReprojected(spanPixel);
        bool glossy = listed && spanPrefiltered.a >= 0.0;
        float3 spanSample = GLINT_RD_SanitizeRadiance(spanPrefiltered.rgb);
        g_glint_rd_resolve_radiance[i] =
            GLINT_RD_PackSpanTexel(glossy ? float4(spanSample, 1.0) : float4(0.0, 0.0, 0.0, 0.0));
        float lag = GLINT_RD_Luma(GLINT_RD_SanitizeRadiance(spanHistory.rgb)) - GLINT_RD_Luma(spanSample);
        g_glint_rd_resolve_lag[i] = glossy && spanHistory.a > 0.5 ? lag : 0.0;
    }
    GroupMemoryBarrierWithGroupSync();

    // 9x9 Gaussian statistics, separably (GLINT_RD_AccumulateRowPair), the column sums after
    // the barrier. A neighbour that is not glossy holds (0, 0, 0, 0): its a is the mask. The
    // anti-lag's differences are summed with the same weights.
    {
        GLINT_RD_RowPair pair = (GLINT_RD_RowPair)0;
        uint first = GLINT_RD_RowPairRow(localIndex) * GLINT_RD_SPAN + GLINT_RD_RowPairColumn(localIndex);
        [unroll] for (int i = 0; i < 2 * GLINT_RD_APRON + 2; ++i)
        {
            float4 q = GLINT_RD_UnpackSpanTexel(g_glint_rd_resolve_radiance[first + uint(i)]);
            GLINT_RD_AccumulateRowPair(pair, i, q.rgb, q.a, g_glint_rd_resolve_lag[first + uint(i)]);
        }
        GLINT_RD_StoreRowPair(localIndex, pair);
    }
    GroupMemoryBarrierWithGroupSync();

    if (!inImage)
        return;
    uint centre = (local.y + GLINT_RD_APRON) * GLINT_RD_SPAN + local.x + GLINT_RD_APRON;
    if (GLINT_RD_UnpackSpanTexel(g_glint_rd_resolve_radiance[centre]).a == 0.0)
    {
        // Not glossy: the output keeps classification's value; histories get defined zeros.
        GLINT_RD_StoreRadianceHistory(ipixel, float4(0.0, 0.0, 0.0, 0.0));
        GLINT_RD_StoreVariance(ipixel, 0.0);
        return;
    }
    float3 average = GLINT_RD_AverageAt(uint2(ipixel), tile);
    float3 sum, sumSquares;
    float weightSum, lagSum;
    GLINT_RD_ColumnStatistics(local, sum, sumSquares, weightSum, lagSum);
    float3 mean = sum / weightSum;
    float3 sigma = sqrt(abs(sumSquares / weightSum - mean * mean));
    float3 current = GLINT_RD_SanitizeRadiance(prefiltered.rgb);
    float variance = clamp(GLINT_FiniteOr(prefiltered.a, 1.0), 0.0, 65504.0);
    bool valid = reprojected.a > 0.5;
    bool mirror = alpha < c.mirrorThreshold;
    float historyLength = max(GLINT_FiniteOr(storedLength, 1.0), 1.0);

    // Anti-lag: the neighbourhood's histories against its samples, both over the same glossy
    // pixels with the same weights (those without a history add 0), so that the reflection's
    // own detail cancels and only change and noise remain. A mean difference beyond what noise
    // explains (GLINT_RD_ANTI_LAG_*) by the factor e shortens the history to n / e^2 frames, at
    // least 1; it is stored for next frame. Mirrors keep theirs (their output is their sample).
    if (antiLag && valid && !mirror)
    {
        float tolerance = GLINT_RD_ANTI_LAG_NOISE * GLINT_RD_Luma(sigma) +
                          GLINT_RD_ANTI_LAG_RELATIVE * GLINT_RD_Luma(mean) + GLINT_RD_ANTI_LAG_FLOOR;
        float excess = abs(lagSum / weightSum) / tolerance;
        historyLength = max(historyLength / max(excess * excess, 1.0), 1.0);
    }

    // The clip box: the neighbourhood's spread plus its distance from the tile average, scaled.
    float3 extent = (sigma + abs(mean - average)) * c.historyClipScale * 1.4;
    float3 boxCentre = lerp(mean, average, 0.2);
    float3 history = valid ? GLINT_RD_ClipToBox(GLINT_RD_SanitizeRadiance(reprojected.rgb), boxCentre, extent) : current;
    // The pull and the clip around the tile average, scaled by the spatial footprint (0 for
    // mirrors: GLINT_RD_SpatialFootprint). The pull's target moves from the box centre (mostly
    // the neighbourhood's mean) for a sample without a history to the tile average for a long
    // one: the average is weighted toward dim samples, and pulling a first sample halfway to it
    // drops the energy of bright highlights (docs/reflections_denoiser.md, "Bright highlights").
    float3 pullTarget = lerp(boxCentre, average, 1.0 - 1.0 / historyLength);
    float3 regularised = GLINT_RD_ClipToBox(lerp(current, pullTarget, 1.0 / (historyLength + 1.0)), average, extent);
    current = lerp(current, regularised, GLINT_RD_SpatialFootprint(c, alpha));
    // Mirrors (docs/reflections_denoiser.md, "Mirrors"): the sample is noise-free, so averaging
    // it with a history removes no noise and can only lag a moving reflection; the output is
    // the sample. Reproject still follows the reflected point for the history's length and
    // temporal variance (a history that left the band around the sample restarts them).
    float historyWeight = valid && !mirror ? 1.0 - 1.0 / historyLength : 0.0;
    float3 result = GLINT_RD_SanitizeRadiance(lerp(current, history, historyWeight));
    float lumaResult = max(GLINT_RD_Luma(result), 0.001);
    float lumaHistory = max(GLINT_RD_Luma(history), 0.001);
    float difference = abs(lumaResult - lumaHistory) / max(max(lumaResult, lumaHistory), 0.5);
    float resultVariance = lerp(difference * difference, variance, historyWeight);

    GLINT_RD_StoreOutput(ipixel, float4(result, GLINT_FiniteOr(hitDistance, GLINT_RD_MISS_DISTANCE)));
    float storedVariance = clamp(GLINT_FiniteOr(resultVariance, 1.0), 0.0, 65504.0);
    GLINT_RD_StoreRadianceHistory(ipixel, float4(result, storedVariance));
    GLINT_RD_StoreVariance(ipixel, storedVariance);
    GLINT_RD_StoreLength(ipixel, historyLength);
}

#endif // GLINT_REFLECTIONS_DENOISER_RESOLVE_HLSLI
