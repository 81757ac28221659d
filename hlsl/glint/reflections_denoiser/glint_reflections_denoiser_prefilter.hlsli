// glint reflections denoiser, pass 2: prefilter (docs/reflections_denoiser.md). A
// variance-guided, edge-aware spatial filter over 15 fixed taps within 3 pixels, with normal,
// relative depth and radiance weights. Mirrors, pixels with zero variance and pixels that are
// not glossy are copied through.
//
// Integration: the callbacks of glint_reflections_denoiser_common.hlsli (with the average), and
//
//   float4 GLINT_RD_LoadClamped(int2 pixel);       reproject's firefly-clamped sample, a = hit distance
//   float  GLINT_RD_LoadVariance(int2 pixel);      reproject's temporal variance (this frame)
//   void   GLINT_RD_StorePrefiltered(int2 pixel, float4 radianceAndVariance);
//
// Dispatch: [numthreads(8, 8, 1)], indirect (tiles, 1, 1).
#ifndef GLINT_REFLECTIONS_DENOISER_PREFILTER_HLSLI
#define GLINT_REFLECTIONS_DENOISER_PREFILTER_HLSLI

#define GLINT_RD_USES_AVERAGE 1
#include "glint/reflections_denoiser/glint_reflections_denoiser_common.hlsli"

float4 GLINT_RD_LoadClamped(int2 pixel);
float GLINT_RD_LoadVariance(int2 pixel);
void GLINT_RD_StorePrefiltered(int2 pixel, float4 radianceAndVariance);

groupshared float4 g_glint_rd_prefilter_radiance[GLINT_RD_SPAN * GLINT_RD_SPAN]; // rgb, variance
groupshared float4 g_glint_rd_prefilter_geometry[GLINT_RD_SPAN * GLINT_RD_SPAN]; // normal, view depth (-1: not glossy)

// The 15 fixed taps within 3 pixels of reference/reflections_denoiser.md. They are described
// there as Halton(2, 3) points, but the first one, (0, 1), is not: trunc(8h - 4) of Halton
// index 1 gives (0, -1). The table is kept as specified; the CPU reference uses the same one.
static const int2 g_glint_rd_prefilter_taps[15] = {
    int2(0, 1), int2(-2, 1), int2(2, -3), int2(-3, 0), int2(1, 2), int2(-1, -2), int2(3, 0), int2(-3, 3),
    int2(0, -3), int2(-1, -1), int2(2, 1), int2(-2, -2), int2(1, 0), int2(0, 2), int2(3, -1)};

float GLINT_RD_RadianceWeight(float3 average, float3 radiance, float variance)
{
    return max(exp(-(0.6 + 0.1 * variance) * length(average - radiance)), 0.01);
}

void GLINT_RD_Prefilter(GLINT_ReflectionsDenoiserConstants c, uint groupId, uint2 local)
{
    uint entry = GLINT_RD_LoadTile(groupId);
    uint2 tileOrigin = uint2(entry & 0xFFFFu, entry >> 16);
    uint localIndex = local.y * GLINT_RD_TILE + local.x;
    // Unrolled (exactly 4 span slots a thread) so that the loads of all four are in flight
    // together instead of one slot's round trip after the other.
    [unroll] for (uint k = 0; k < GLINT_RD_SPAN * GLINT_RD_SPAN / (GLINT_RD_TILE * GLINT_RD_TILE); ++k)
    {
        uint i = localIndex + k * GLINT_RD_TILE * GLINT_RD_TILE;
        int2 pixel = GLINT_RD_SpanPixel(c, tileOrigin, i);
        GLINT_RD_Surface s = GLINT_RD_LoadSurface(c, pixel);
        float4 clamped = GLINT_RD_LoadClamped(pixel);
        float variance = clamp(GLINT_FiniteOr(GLINT_RD_LoadVariance(pixel), 1.0), 0.0, 65504.0);
        g_glint_rd_prefilter_radiance[i] = s.glossy ? float4(GLINT_RD_SanitizeRadiance(clamped.rgb), variance)
                                                    : float4(0.0, 0.0, 0.0, 0.0);
        g_glint_rd_prefilter_geometry[i] = float4(s.normal, s.glossy ? s.viewDepth : -1.0);
    }
    GroupMemoryBarrierWithGroupSync();

    uint2 pixel = tileOrigin + local;
    if (any(pixel >= c.inputSize))
        return;
    uint centre = (local.y + GLINT_RD_APRON) * GLINT_RD_SPAN + local.x + GLINT_RD_APRON;
    float4 own = g_glint_rd_prefilter_radiance[centre];
    float4 geometry = g_glint_rd_prefilter_geometry[centre];
    float alpha = GLINT_FiniteOr(GLINT_RD_LoadRoughness(int2(pixel)), 1.0);
    bool filtered = geometry.w > 0.0 && own.a > 0.0 && alpha >= c.mirrorThreshold;
    if (!filtered)
    {
        GLINT_RD_StorePrefiltered(int2(pixel), own);
        return;
    }
    float3 average = GLINT_RD_AverageAt(c, pixel);
    float varianceWeight = max(0.1, 1.0 - exp(-4.4 * own.a));
    float centreWeight = GLINT_RD_RadianceWeight(average, own.rgb, own.a);
    float3 sum = centreWeight * own.rgb;
    float varianceSum = centreWeight * centreWeight * own.a;
    float weightSum = centreWeight;
    for (uint tap = 0; tap < 15; ++tap)
    {
        int2 offset = g_glint_rd_prefilter_taps[tap];
        uint index = uint(int(centre) + offset.y * GLINT_RD_SPAN + offset.x);
        float4 q = g_glint_rd_prefilter_radiance[index];
        float4 qGeometry = g_glint_rd_prefilter_geometry[index];
        if (!(qGeometry.w > 0.0))
            continue;
        // Relative depth difference (reference defect 5: the reference multiplies by z).
        float w = pow(max(dot(geometry.xyz, qGeometry.xyz), 0.0), 512.0) *
                  exp(-4.0 * abs(geometry.w - qGeometry.w) / geometry.w) *
                  GLINT_RD_RadianceWeight(average, q.rgb, own.a) * varianceWeight;
        sum += w * q.rgb;
        varianceSum += w * w * q.a;
        weightSum += w;
    }
    float4 result = float4(sum / weightSum, varianceSum / (weightSum * weightSum));
    GLINT_RD_StorePrefiltered(int2(pixel), float4(GLINT_RD_SanitizeRadiance(result.rgb),
                                                  clamp(GLINT_FiniteOr(result.a, 1.0), 0.0, 65504.0)));
}

#endif // GLINT_REFLECTIONS_DENOISER_PREFILTER_HLSLI
