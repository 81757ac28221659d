// glint reflections denoiser, pass 2: prefilter (docs/reflections_denoiser.md). A
// variance-guided, edge-aware spatial filter over 15 fixed taps within 3 pixels, with normal,
// relative depth and radiance weights and a footprint that shrinks to zero toward mirrors.
// Mirrors and pixels with zero variance are copied through; pixels that are not glossy store
// (0, 0, 0, GLINT_RD_NOT_GLOSSY), which tells the resolve (with this frame's tile mask) that
// they are not glossy.
//
// Integration: the callbacks of glint_reflections_denoiser_common.hlsli (with the average), and
//
//   float4 GLINT_RD_LoadClamped(int2 pixel);       reproject's firefly-clamped sample, a = its
//                                                  temporal variance (GLINT_RD_NOT_GLOSSY: not glossy)
//   void   GLINT_RD_StorePrefiltered(int2 pixel, float4 radianceAndVariance);
//                                                  rgb, a = variance (GLINT_RD_NOT_GLOSSY: not glossy)
//
// Entry: from main, GLINT_RD_Prefilter(c, SV_GroupID.x, SV_GroupThreadID.xy), c the
// GLINT_ReflectionsDenoiserConstants in a cbuffer (glint_reflections_denoiser_common.hlsli).
// Dispatch: [numthreads(8, 8, 1)] (also in the 16-bit permutation), indirect (tiles, 1, 1) from
// SSSR's arguments at byte 12.
#ifndef GLINT_REFLECTIONS_DENOISER_PREFILTER_HLSLI
#define GLINT_REFLECTIONS_DENOISER_PREFILTER_HLSLI

#define GLINT_RD_USES_AVERAGE 1
#include "glint/reflections_denoiser/glint_reflections_denoiser_common.hlsli"

float4 GLINT_RD_LoadClamped(int2 pixel);
void GLINT_RD_StorePrefiltered(int2 pixel, float4 radianceAndVariance);

// The taps reach 3 pixels, so the prefilter loads a 14x14 span (tile plus a 3-pixel apron):
// 196 slots instead of the 16x16 span's 256, about a quarter fewer span loads. 64 threads
// load 4 slots each, the last of them only where it exists.
#define GLINT_RD_PREFILTER_APRON 3
#define GLINT_RD_PREFILTER_SPAN (GLINT_RD_TILE + 2 * GLINT_RD_PREFILTER_APRON)
#define GLINT_RD_PREFILTER_SLOTS (GLINT_RD_PREFILTER_SPAN * GLINT_RD_PREFILTER_SPAN)
#define GLINT_RD_PREFILTER_SLOTS_PER_THREAD \
    ((GLINT_RD_PREFILTER_SLOTS + GLINT_RD_TILE * GLINT_RD_TILE - 1) / (GLINT_RD_TILE * GLINT_RD_TILE))

groupshared GLINT_RD_SpanTexel g_glint_rd_prefilter_radiance[GLINT_RD_PREFILTER_SLOTS]; // rgb, variance
groupshared float4 g_glint_rd_prefilter_geometry[GLINT_RD_PREFILTER_SLOTS]; // normal, view depth (-1: not glossy)

float GLINT_RD_RadianceWeight(float3 average, float3 radiance, float variance)
{
    return max(exp(-(0.6 + 0.1 * variance) * length(average - radiance)), 0.01);
}

struct GLINT_RD_PrefilterSums
{
    float3 radiance;
    float variance; // sum of w^2 var
    float weight;
};

// The per-pixel factors of a tap's weight, in base-2 exponent units (see GLINT_RD_PrefilterTap).
struct GLINT_RD_PrefilterRates
{
    float depth;     // log2(e) 4 / z: relative depth difference
    float radiance;  // log2(e) (0.6 + 0.1 var): distance from the tile average
    float footprint; // log2(s) / 2, s = GLINT_RD_SpatialFootprint: per squared pixel of distance
};

// log2 of GLINT_RD_RadianceWeight's floor (0.01).
#define GLINT_RD_LOG2_RADIANCE_FLOOR -6.64385619

// One tap of the prefilter at a constant offset from the centre slot. Its weight is
// max(N.Nq, 0)^512 exp(-4 |z - zq| / z) GLINT_RD_RadianceWeight(...) s^(|offset|^2 / 2)
// varianceWeight, computed as one exp2 of the summed exponents (the radiance weight's floor
// applied to its exponent, which is monotonic): one log2, one exp2 and one length a tap instead
// of two exps and a pow. A normal at 90 degrees or more gives log2(0) = -inf and a weight of 0, as
// pow does; so does s = 0 (no exponent term is +inf, so the sum is -inf, never NaN).
void GLINT_RD_PrefilterTap(inout GLINT_RD_PrefilterSums sums, uint centre, int2 offset, float4 geometry,
                           float3 average, GLINT_RD_PrefilterRates rates, float varianceWeight)
{
    uint index = uint(int(centre) + offset.y * GLINT_RD_PREFILTER_SPAN + offset.x);
    float4 q = GLINT_RD_UnpackSpanTexel(g_glint_rd_prefilter_radiance[index]);
    float4 qGeometry = g_glint_rd_prefilter_geometry[index];
    // Relative depth difference (docs/conventions.md, defect RD5: the reference multiplies by z).
    float exponent = 512.0 * log2(max(dot(geometry.xyz, qGeometry.xyz), 0.0)) -
                     abs(geometry.w - qGeometry.w) * rates.depth +
                     max(-length(average - q.rgb) * rates.radiance, GLINT_RD_LOG2_RADIANCE_FLOOR) +
                     float(dot(offset, offset)) * rates.footprint;
    float w = exp2(exponent) * varianceWeight;
    // Only glossy neighbours count. A neighbour that is not glossy is weighted by an exact 0 (a
    // select, not a branch): everything in the span is finite (radiance sanitised, the normal
    // unit or (0, 0, 1), depth -1), so w is finite and its terms add exactly nothing.
    w = qGeometry.w > 0.0 ? w : 0.0;
    sums.radiance += w * q.rgb;
    sums.variance += w * w * q.a;
    sums.weight += w;
}

void GLINT_RD_Prefilter(GLINT_ReflectionsDenoiserConstants c, uint groupId, uint2 local)
{
    uint entry = GLINT_RD_LoadTile(groupId);
    uint2 tileOrigin = uint2(GLINT_WIRE_TileEntryX(entry), GLINT_WIRE_TileEntryY(entry));
    uint localIndex = local.y * GLINT_RD_TILE + local.x;
    uint2 pixel = tileOrigin + local;
    bool inImage = all(pixel < c.inputSize);
    uint2 clampedPixel = min(pixel, c.inputSize - 1);
    // The pixel's own roughness needs nothing from the group, and the tile averages are loaded
    // by nine threads: both with the span, so that they arrive while the group synchronises.
    float alpha = GLINT_FiniteOr(GLINT_RD_LoadRoughness(int2(clampedPixel)), 1.0);
    uint2 tile = tileOrigin / GLINT_RD_TILE;
    GLINT_RD_LoadTileAverages(c, tile, localIndex);
    // Unrolled (a fixed count of slots a thread) so that the loads of all of them are in flight
    // together instead of one slot's round trip after the other.
    //
    // A slot fetches depth, normal and clamped sample (rgb, a = variance or the not-glossy flag)
    // plus its tile's mask word: the clamped sample's alpha says whether the pixel is glossy,
    // where GLINT_RD_LoadSurface needed the roughness too, and a separate variance image. Only
    // listed tiles hold this frame's clamped samples; in the others no pixel is glossy
    // (GLINT_RD_PixelListed). Glossy pixels have a usable normal and a finite positive view
    // depth (reproject tested them), computed here exactly as GLINT_RD_LoadSurface does.
    [unroll] for (uint k = 0; k < GLINT_RD_PREFILTER_SLOTS_PER_THREAD; ++k)
    {
        uint i = localIndex + k * GLINT_RD_TILE * GLINT_RD_TILE;
        // Only the last round can run past the span (a constant for the others).
        if (k + 1 < GLINT_RD_PREFILTER_SLOTS_PER_THREAD || i < GLINT_RD_PREFILTER_SLOTS)
        {
            int2 spanPixel = GLINT_RD_SpanPixelOf(c, tileOrigin, i, GLINT_RD_PREFILTER_SPAN, GLINT_RD_PREFILTER_APRON);
            bool listed = GLINT_RD_PixelListed(spanPixel);
            float depth = GLINT_RD_LoadDepth(spanPixel);
            bool normalOk;
            float3 normal = GLINT_RD_UnpackNormal(c, GLINT_RD_LoadNormal(spanPixel), normalOk);
            float4 clamped = GLINT_RD_LoadClamped(spanPixel);
            bool glossy = listed && clamped.a >= 0.0;
            float variance = clamp(GLINT_FiniteOr(clamped.a, 1.0), 0.0, 65504.0);
            g_glint_rd_prefilter_radiance[i] = GLINT_RD_PackSpanTexel(
                glossy ? float4(GLINT_RD_SanitizeRadiance(clamped.rgb), variance) : float4(0.0, 0.0, 0.0, 0.0));
            g_glint_rd_prefilter_geometry[i] = float4(normal, glossy ? GLINT_RD_ViewDepth(c, depth) : -1.0);
        }
    }
    GroupMemoryBarrierWithGroupSync();

    if (!inImage)
        return;
    float3 average = GLINT_RD_AverageAt(clampedPixel, tile);
    uint centre = (local.y + GLINT_RD_PREFILTER_APRON) * GLINT_RD_PREFILTER_SPAN + local.x + GLINT_RD_PREFILTER_APRON;
    float4 own = GLINT_RD_UnpackSpanTexel(g_glint_rd_prefilter_radiance[centre]);
    float4 geometry = g_glint_rd_prefilter_geometry[centre];
    bool glossy = geometry.w > 0.0;
    bool filtered = glossy && own.a > 0.0 && alpha >= c.mirrorThreshold;
    if (!filtered)
    {
        GLINT_RD_StorePrefiltered(int2(pixel), glossy ? own : float4(0.0, 0.0, 0.0, GLINT_RD_NOT_GLOSSY));
        return;
    }
    float varianceWeight = max(0.1, 1.0 - exp(-4.4 * own.a));
    GLINT_RD_PrefilterRates rates;
    rates.depth = 1.44269504 * 4.0 / geometry.w;
    rates.radiance = 1.44269504 * (0.6 + 0.1 * own.a);
    // The footprint shrinks to the pixel itself as alpha falls to the mirror threshold.
    rates.footprint = 0.5 * log2(GLINT_RD_SpatialFootprint(c, alpha));
    float centreWeight = GLINT_RD_RadianceWeight(average, own.rgb, own.a);
    GLINT_RD_PrefilterSums sums;
    sums.radiance = centreWeight * own.rgb;
    sums.variance = centreWeight * centreWeight * own.a;
    sums.weight = centreWeight;
    // The reference's 15 fixed taps within 3 pixels (GLINT_RD_PREFILTER_APRON), in its order
    // (docs/reflections_denoiser.md, "Prefilter"). The reference calls them Halton(2, 3)
    // points, but the first one, (0, 1), is not: trunc(8h - 4) of Halton index 1 gives (0, -1).
    // The table is kept as specified; the CPU reference uses the same one. Written out call by
    // call, so that every offset is a constant: a static const table indexed by the loop counter
    // becomes a function-local array in SPIR-V, re-stored on every iteration.
    GLINT_RD_PrefilterTap(sums, centre, int2(0, 1), geometry, average, rates, varianceWeight);
    GLINT_RD_PrefilterTap(sums, centre, int2(-2, 1), geometry, average, rates, varianceWeight);
    GLINT_RD_PrefilterTap(sums, centre, int2(2, -3), geometry, average, rates, varianceWeight);
    GLINT_RD_PrefilterTap(sums, centre, int2(-3, 0), geometry, average, rates, varianceWeight);
    GLINT_RD_PrefilterTap(sums, centre, int2(1, 2), geometry, average, rates, varianceWeight);
    GLINT_RD_PrefilterTap(sums, centre, int2(-1, -2), geometry, average, rates, varianceWeight);
    GLINT_RD_PrefilterTap(sums, centre, int2(3, 0), geometry, average, rates, varianceWeight);
    GLINT_RD_PrefilterTap(sums, centre, int2(-3, 3), geometry, average, rates, varianceWeight);
    GLINT_RD_PrefilterTap(sums, centre, int2(0, -3), geometry, average, rates, varianceWeight);
    GLINT_RD_PrefilterTap(sums, centre, int2(-1, -1), geometry, average, rates, varianceWeight);
    GLINT_RD_PrefilterTap(sums, centre, int2(2, 1), geometry, average, rates, varianceWeight);
    GLINT_RD_PrefilterTap(sums, centre, int2(-2, -2), geometry, average, rates, varianceWeight);
    GLINT_RD_PrefilterTap(sums, centre, int2(1, 0), geometry, average, rates, varianceWeight);
    GLINT_RD_PrefilterTap(sums, centre, int2(0, 2), geometry, average, rates, varianceWeight);
    GLINT_RD_PrefilterTap(sums, centre, int2(3, -1), geometry, average, rates, varianceWeight);
    float4 result = float4(sums.radiance / sums.weight, sums.variance / (sums.weight * sums.weight));
    GLINT_RD_StorePrefiltered(int2(pixel), float4(GLINT_RD_SanitizeRadiance(result.rgb),
                                                  clamp(GLINT_FiniteOr(result.a, 1.0), 0.0, 65504.0)));
}

#endif // GLINT_REFLECTIONS_DENOISER_PREFILTER_HLSLI
