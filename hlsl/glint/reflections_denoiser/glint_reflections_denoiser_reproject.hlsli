// glint reflections denoiser, pass 1: reproject (docs/reflections_denoiser.md). For every
// pixel of a listed tile: neighbourhood statistics of the noisy sample, a firefly clamp, the
// history fetched along the surface motion or the reflection's parallax (whichever fits),
// the history length and temporal variance, this frame's guides for next frame, and the
// tile's luminance-weighted average radiance.
//
// Integration: the callbacks of glint_reflections_denoiser_common.hlsli, and
//
//   float4 GLINT_RD_LoadNoisy(int2 pixel);              SSSR radiance: rgb, a = hit distance (65504 = miss)
//   float2 GLINT_RD_LoadMotion(int2 pixel);             motion vector (scaled by motionScale: convention A)
//   bool   GLINT_RD_HistoryTileListed(uint2 tile);      last frame's tile mask (false on a reset)
//   float4 GLINT_RD_LoadHistoryGuides(int2 pixel);      last frame's (octahedral normal, view depth, alpha); depth 0: not glossy
//   float3 GLINT_RD_LoadHistoryRadiance(int2 pixel);    last frame's resolved radiance
//   float  GLINT_RD_LoadHistoryVariance(int2 pixel);
//   float  GLINT_RD_LoadHistoryLength(int2 pixel);
//   void   GLINT_RD_StoreClamped(int2 pixel, float4 radianceAndHitDistance);
//   void   GLINT_RD_StoreReprojected(int2 pixel, float4 historyAndValidity);
//   void   GLINT_RD_StoreVariance(int2 pixel, float variance);
//   void   GLINT_RD_StoreHistoryLength(int2 pixel, float length);
//   void   GLINT_RD_StoreGuides(int2 pixel, float4 guides);
//   void   GLINT_RD_StoreAverage(uint2 tile, float4 average);   rgb, a = weight sum
//   void   GLINT_RD_MarkTile(uint2 tile);                        this frame's tile mask
//
// Dispatch: [numthreads(8, 8, 1)], indirect (tiles, 1, 1) from SSSR's arguments at byte 12.
#ifndef GLINT_REFLECTIONS_DENOISER_REPROJECT_HLSLI
#define GLINT_REFLECTIONS_DENOISER_REPROJECT_HLSLI

#include "glint/reflections_denoiser/glint_reflections_denoiser_common.hlsli"

float4 GLINT_RD_LoadNoisy(int2 pixel);
float2 GLINT_RD_LoadMotion(int2 pixel);
bool GLINT_RD_HistoryTileListed(uint2 tile);
float4 GLINT_RD_LoadHistoryGuides(int2 pixel);
float3 GLINT_RD_LoadHistoryRadiance(int2 pixel);
float GLINT_RD_LoadHistoryVariance(int2 pixel);
float GLINT_RD_LoadHistoryLength(int2 pixel);
void GLINT_RD_StoreClamped(int2 pixel, float4 radianceAndHitDistance);
void GLINT_RD_StoreReprojected(int2 pixel, float4 historyAndValidity);
void GLINT_RD_StoreVariance(int2 pixel, float variance);
void GLINT_RD_StoreHistoryLength(int2 pixel, float length);
void GLINT_RD_StoreGuides(int2 pixel, float4 guides);
void GLINT_RD_StoreAverage(uint2 tile, float4 average);
void GLINT_RD_MarkTile(uint2 tile);

// Noisy rgb (0 for pixels that are not glossy) and hit distance (-1: not glossy).
groupshared float4 g_glint_rd_noisy[GLINT_RD_SPAN * GLINT_RD_SPAN];
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

// Bilinear history at uv from the 2x2 taps that were glossy last frame, in a tile listed last
// frame, and whose normal and depth match this pixel's (disocclusion weight >= 0.9 per tap).
// Accepted when the accepted taps carry at least half of the bilinear weight.
GLINT_RD_History GLINT_RD_SampleHistory(GLINT_ReflectionsDenoiserConstants c, float2 uv, GLINT_RD_Surface surface,
                                        float expectedViewDepth)
{
    GLINT_RD_History h = (GLINT_RD_History)0;
    h.valid = false;
    // Tested after the loads, so that no branch stands between the two candidates' loads: the
    // taps are clamped to the image whatever uv is (a non-finite one included).
    bool usable = all(uv > 0.0) && all(uv < 1.0) && (c.flags & GLINT_RD_FLAG_RESET) == 0;
    float2 p = clamp(uv, -1.0, 2.0) * float2(c.inputSize) - 0.5;
    float2 base = floor(p);
    float2 f = p - base;
    // All loads of the four taps are issued before any of them is tested, so their latencies
    // overlap (testing a tap's guides before fetching its radiance serialised three memory
    // round trips per tap). A rejected tap's values are selected away, never multiplied by 0:
    // they may be NaN.
    int2 pixels[4];
    float weights[4];
    float4 guides[4];
    bool listed[4];
    float3 radiances[4];
    float variances[4];
    float lengths[4];
    [unroll] for (uint tap = 0; tap < 4; ++tap)
    {
        int2 offset = int2(tap & 1u, tap >> 1);
        pixels[tap] = clamp(int2(base) + offset, int2(0, 0), int2(c.inputSize) - 1);
        weights[tap] = (offset.x == 1 ? f.x : 1.0 - f.x) * (offset.y == 1 ? f.y : 1.0 - f.y);
        listed[tap] = GLINT_RD_HistoryTileListed(uint2(pixels[tap]) / GLINT_RD_TILE);
        guides[tap] = GLINT_RD_LoadHistoryGuides(pixels[tap]);
        radiances[tap] = GLINT_RD_LoadHistoryRadiance(pixels[tap]);
        variances[tap] = GLINT_RD_LoadHistoryVariance(pixels[tap]);
        lengths[tap] = GLINT_RD_LoadHistoryLength(pixels[tap]);
    }
    float total = 0.0;
    float3 normalSum = float3(0.0, 0.0, 0.0);
    [unroll] for (uint t = 0; t < 4; ++t)
    {
        float w = weights[t];
        // Taps that were glossy last frame, in a tile listed last frame, whose normal and depth
        // match this pixel's (disocclusion weight >= 0.9).
        bool accepted = w > 0.0 && listed[t] && guides[t].z > 0.0 && GLINT_IsFinite(guides[t].z);
        float3 n = GLINT_RD_DecodeNormal(clamp(GLINT_RD_Finite3(float3(guides[t].xy, 0.0)).xy, -1.0, 1.0));
        float fit = exp(-abs(1.0 - max(0.0, dot(n, surface.normal))) * 1.4) *
                    exp(-abs(guides[t].z - expectedViewDepth) / expectedViewDepth);
        accepted = accepted && fit >= 0.9;
        if (!accepted)
            continue;
        h.radiance += w * GLINT_RD_SanitizeRadiance(radiances[t]);
        h.variance += w * clamp(GLINT_FiniteOr(variances[t], 1.0), 0.0, 65504.0);
        h.length += w * clamp(GLINT_FiniteOr(lengths[t], 0.0), 0.0, 65504.0);
        h.alpha += w * GLINT_Saturate(GLINT_FiniteOr(guides[t].w, 1.0));
        normalSum += w * n;
        total += w;
    }
    if (!usable || total < 0.5)
        return (GLINT_RD_History)0;
    float inverse = 1.0 / total;
    h.radiance *= inverse;
    h.variance *= inverse;
    h.length *= inverse;
    h.alpha *= inverse;
    h.normal = normalize(normalSum);
    h.valid = true;
    return h;
}

void GLINT_RD_Reproject(GLINT_ReflectionsDenoiserConstants c, uint groupId, uint2 local)
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
        float4 noisy = GLINT_RD_LoadNoisy(pixel);
        g_glint_rd_noisy[i] = s.glossy ? float4(GLINT_RD_SanitizeRadiance(noisy.rgb),
                                                clamp(GLINT_FiniteOr(noisy.a, GLINT_RD_MISS_DISTANCE), 0.0,
                                                      GLINT_RD_MISS_DISTANCE))
                                       : float4(0.0, 0.0, 0.0, -1.0);
    }
    GroupMemoryBarrierWithGroupSync();

    uint2 pixel = tileOrigin + local;
    bool inImage = all(pixel < c.inputSize);
    int2 ipixel = int2(min(pixel, c.inputSize - 1));
    GLINT_RD_Surface surface = GLINT_RD_LoadSurface(c, ipixel);
    uint centre = (local.y + GLINT_RD_APRON) * GLINT_RD_SPAN + local.x + GLINT_RD_APRON;
    float3 current = g_glint_rd_noisy[centre].rgb;

    // 9x9 Gaussian statistics over glossy neighbours, and the nearest hit of the 3x3 (one noisy
    // hit distance is a poor parallax estimate: reference defect 11).
    float3 sum = float3(0.0, 0.0, 0.0);
    float3 sumSquares = float3(0.0, 0.0, 0.0);
    float weightSum = 0.0;
    float hitDistance = GLINT_RD_MISS_DISTANCE;
    for (int y = -GLINT_RD_APRON; y <= GLINT_RD_APRON; ++y)
        for (int x = -GLINT_RD_APRON; x <= GLINT_RD_APRON; ++x)
        {
            float4 q = g_glint_rd_noisy[centre + y * GLINT_RD_SPAN + x];
            if (q.a < 0.0)
                continue;
            float w = GLINT_RD_GaussianWeight(x) * GLINT_RD_GaussianWeight(y);
            sum += w * q.rgb;
            sumSquares += w * q.rgb * q.rgb;
            weightSum += w;
            if (abs(x) <= 1 && abs(y) <= 1)
                hitDistance = min(hitDistance, q.a);
        }
    float3 mean = weightSum > 0.0 ? sum / weightSum : current;
    float3 variance3 = weightSum > 0.0 ? abs(sumSquares / weightSum - mean * mean) : float3(0.0, 0.0, 0.0);
    float3 sigma = sqrt(variance3);
    // Firefly clamp before any spatial reuse (reference defect 14).
    current = min(current, mean + 3.0 * sigma);

    float2 uv = (float2(ipixel) + 0.5) * c.inverseInputSize;
    GLINT_RD_History history = (GLINT_RD_History)0;
    history.valid = false;
    float3 viewPosition = GLINT_RD_ViewPosition(c, uv, surface.depth);
    if (surface.glossy)
    {
        float expectedViewDepth;
        GLINT_RD_PreviousUv(c, viewPosition, expectedViewDepth);
        expectedViewDepth = max(expectedViewDepth, 1e-6);
        float2 motion = GLINT_RD_LoadMotion(ipixel) * c.motionScale;
        float2 surfaceUv = uv + float2(GLINT_FiniteOr(motion.x, 1e9), GLINT_FiniteOr(motion.y, 1e9));
        // Parallax: the reflected point continued behind the mirror, reprojected. A miss's
        // "infinite" distance makes it rotation-only. Both positions first, so that the two
        // candidates' loads can be in flight together.
        float viewLength = length(viewPosition);
        float3 virtualPoint = viewPosition / max(viewLength, 1e-12) * (viewLength + hitDistance);
        float unused;
        float2 virtualUv = GLINT_RD_PreviousUv(c, virtualPoint, unused);
        GLINT_RD_History onSurface = GLINT_RD_SampleHistory(c, surfaceUv, surface, expectedViewDepth);
        GLINT_RD_History virtualHistory = GLINT_RD_SampleHistory(c, virtualUv, surface, expectedViewDepth);
        float virtualFit = dot(virtualHistory.normal, surface.normal);
        float surfaceFit = onSurface.valid ? dot(onSurface.normal, surface.normal) : -1.0;
        bool useVirtual = virtualHistory.valid && virtualFit > 0.9999 && virtualFit + 1e-3 > surfaceFit &&
                          (!onSurface.valid ||
                           abs(virtualHistory.alpha - surface.alpha) < abs(onSurface.alpha - surface.alpha) + 1e-3);
        float3 surfaceOffset = onSurface.radiance - mean;
        if (useVirtual)
            history = virtualHistory;
        else if (onSurface.valid && dot(surfaceOffset, surfaceOffset) < 1.5 * length(variance3) + 1e-6)
            history = onSurface;
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
        // (reference defect 10: the reference weights the history by 1/n instead).
        temporalVariance = lerp(history.variance, difference * difference, 1.0 / historyLength);
        reprojected = history.radiance;
        contribution = lerp(current, history.radiance, 0.3);
    }
    else if (surface.glossy)
    {
        temporalVariance = 1.0;
        historyLength = 1.0;
    }

    // The tile's luminance-weighted average (bright outliers weigh less).
    float weight = surface.glossy && inImage ? max(exp(-0.3 * GLINT_RD_Luma(contribution)), 0.01) : 0.0;
    g_glint_rd_average[localIndex] = float4(contribution * weight, weight);
    GroupMemoryBarrierWithGroupSync();
    for (uint stride = GLINT_RD_TILE * GLINT_RD_TILE / 2; stride > 0; stride >>= 1)
    {
        if (localIndex < stride)
            g_glint_rd_average[localIndex] += g_glint_rd_average[localIndex + stride];
        GroupMemoryBarrierWithGroupSync();
    }
    uint2 tile = tileOrigin / GLINT_RD_TILE;
    if (localIndex == 0)
    {
        float4 total = g_glint_rd_average[0];
        GLINT_RD_StoreAverage(tile, float4(GLINT_RD_SanitizeRadiance(total.rgb / max(total.a, 1e-3)), total.a));
        GLINT_RD_MarkTile(tile);
    }
    if (!inImage)
        return;
    float hitOut = surface.glossy ? hitDistance : GLINT_RD_MISS_DISTANCE;
    GLINT_RD_StoreClamped(ipixel, float4(GLINT_RD_SanitizeRadiance(current), hitOut));
    GLINT_RD_StoreReprojected(ipixel, float4(GLINT_RD_SanitizeRadiance(reprojected), history.valid ? 1.0 : 0.0));
    GLINT_RD_StoreVariance(ipixel, clamp(GLINT_FiniteOr(temporalVariance, 1.0), 0.0, 65504.0));
    GLINT_RD_StoreHistoryLength(ipixel, historyLength);
    GLINT_RD_StoreGuides(ipixel, float4(GLINT_RD_EncodeNormal(surface.normal), surface.glossy ? surface.viewDepth : 0.0,
                                        surface.alpha));
}

#endif // GLINT_REFLECTIONS_DENOISER_REPROJECT_HLSLI
