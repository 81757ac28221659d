// glint reflections denoiser, ratio-estimator path, pass 2: spatial reconstruction
// (docs/reflections_denoiser.md, "Ratio-estimator path"). Used instead of the prefilter when
// ReflectionsDenoiserDesc::spatialPath is RatioEstimator. Every glossy, non-mirror pixel
// reuses the samples of its neighbours (Frostbite's ratio estimator): each neighbour's traced
// ray is weighted by the centre's own GGX BRDF for that direction divided by the density the
// neighbour drew it with, so a neighbour's sample counts as much as the centre's lobe wants it.
// The taps are the centre plus 8 points of a disk of radius reconstructionRadius * sat(5 r)
// pixels (r = perceptual roughness), rotated per pixel (4x4 Bayer) and per frame. The output
// goes where the prefilter's would ("rd_prefiltered"), so the resolve runs unchanged after it.
//
// Integration: the callbacks of glint_reflections_denoiser_common.hlsli, and
//
//   float4 GLINT_RD_LoadClamped(int2 pixel);    reproject's firefly-clamped sample (rgb is read)
//   float4 GLINT_RD_LoadRay(int2 pixel);        SSSR's ray (GLINT_SSSR_STORE_RAY): world unit direction, pdf
//   float  GLINT_RD_LoadVariance(int2 pixel);   reproject's temporal variance (this frame)
//   void   GLINT_RD_StoreReconstructed(int2 pixel, float4 radianceAndVariance);
//                                               a = GLINT_RD_NOT_GLOSSY for pixels that are not glossy
//
// Only glossy pixels are read as neighbours; every glossy pixel has a ray this frame (SSSR
// traces it or copies its quad donor's ray along with the radiance). A glossy pixel whose ray
// is empty (a zero direction, or a pdf that is negative or not finite) still counts, with
// weight 1e-6 (reference: untraced pixels).
//
// Entry: from main, GLINT_RD_Reconstruct(r, SV_GroupID.x, SV_GroupThreadID.xy), r the
// GLINT_ReflectionsDenoiserRatioConstants (glint_reflections_denoiser_ratio_constants.h) in a
// cbuffer, as in glint_reflections_denoiser_common.hlsli.
// Dispatch: [numthreads(8, 8, 1)] (also in the 16-bit permutation), indirect (tiles, 1, 1) from
// SSSR's arguments at byte 12.
#ifndef GLINT_REFLECTIONS_DENOISER_RECONSTRUCT_HLSLI
#define GLINT_REFLECTIONS_DENOISER_RECONSTRUCT_HLSLI

#include "glint/common/glint_ggx.hlsli"
#include "glint/reflections_denoiser/glint_reflections_denoiser_common.hlsli"
#include "glint/reflections_denoiser/glint_reflections_denoiser_ratio_constants.h"

float4 GLINT_RD_LoadClamped(int2 pixel);
float4 GLINT_RD_LoadRay(int2 pixel);
float GLINT_RD_LoadVariance(int2 pixel);
void GLINT_RD_StoreReconstructed(int2 pixel, float4 radianceAndVariance);

// 8 points of the unit disk: a Vogel (golden-angle) spiral, r_k = sqrt((k + 0.5) / 8),
// theta_k = k * pi (3 - sqrt 5). Evenly spread like a Poisson-disk set, and reproducible
// from its formula (the CPU reference in tests/reflections_denoiser/ratio_test.cpp does).
static const float2 g_glint_rd_ratio_taps[8] = {float2(0.250000, 0.000000),   float2(-0.319290, 0.292496),
                                                float2(0.048872, -0.556877),  float2(0.402444, 0.524918),
                                                float2(-0.738535, -0.130636), float2(0.699605, -0.445031),
                                                float2(-0.234004, 0.870484),  float2(-0.446271, -0.859268)};

// 4x4 Bayer matrix, row-major: the per-pixel part of the taps' rotation.
static const uint g_glint_rd_ratio_bayer[16] = {0u, 8u,  2u, 10u, 12u, 4u, 14u, 6u,
                                                3u, 11u, 1u, 9u,  15u, 7u, 13u, 5u};

// The taps' rotation at a pixel: 2 pi ((Bayer4x4(p) + frame) mod 16) / 16.
float GLINT_RD_RatioAngle(uint2 pixel, uint frameIndex)
{
    uint step = (g_glint_rd_ratio_bayer[(pixel.y & 3u) * 4u + (pixel.x & 3u)] + frameIndex) & 15u;
    return float(step) * (2.0 * GLINT_GGX_PI / 16.0);
}

// Height-correlated Smith visibility G2 / (4 N.L N.V) for GGX (Heitz 2014), for N.L, N.V > 0.
float GLINT_RD_SmithVisibility(float NdotL, float NdotV, float alpha)
{
    float a = GLINT_GGX_ClampAlpha(alpha);
    float a2 = a * a;
    float lambdaV = NdotL * sqrt(NdotV * NdotV * (1.0 - a2) + a2);
    float lambdaL = NdotV * sqrt(NdotL * NdotL * (1.0 - a2) + a2);
    return 0.5 / max(lambdaV + lambdaL, 1e-30);
}

// The ratio-estimator weight of a sample drawn along L with density pdf, for the centre's
// lobe (unit N, V with N.V > 0, alpha): D(N.H) Vis(N.L, N.V) N.L / max(pdf, 1e-5); 0 below the
// centre's horizon.
float GLINT_RD_RatioWeight(float3 N, float3 V, float NdotV, float alpha, float3 L, float pdf)
{
    float NdotL = dot(N, L);
    if (!(NdotL > 0.0)) return 0.0;
    float3 H = GLINT_GGX_SafeNormalize(V + L, N);
    float brdf = GLINT_GGX_D(dot(N, H), alpha) * GLINT_RD_SmithVisibility(NdotL, NdotV, alpha) * NdotL;
    return brdf / max(pdf, 1e-5);
}

// The view direction of a pixel in world space (towards the camera).
float3 GLINT_RD_WorldView(GLINT_ReflectionsDenoiserRatioConstants r, float3 viewPosition)
{
    float3 toPoint =
        float3(dot(r.worldFromView[0].xyz, viewPosition), dot(r.worldFromView[1].xyz, viewPosition),
               dot(r.worldFromView[2].xyz, viewPosition));
    return -GLINT_GGX_SafeNormalize(toPoint, float3(0.0, 0.0, 1.0));
}

void GLINT_RD_Reconstruct(GLINT_ReflectionsDenoiserRatioConstants r, uint groupId, uint2 local)
{
    GLINT_ReflectionsDenoiserConstants c = r.common;
    uint entry = GLINT_RD_LoadTile(groupId);
    uint2 tileOrigin = uint2(GLINT_WIRE_TileEntryX(entry), GLINT_WIRE_TileEntryY(entry));
    uint2 pixel = tileOrigin + local;
    if (any(pixel >= c.inputSize)) return;
    int2 ipixel = int2(pixel);
    GLINT_RD_Surface surface = GLINT_RD_LoadSurface(c, ipixel);
    if (!surface.glossy)
    {
        // The prefilter's marking, which the resolve reads instead of the surface.
        GLINT_RD_StoreReconstructed(ipixel, float4(0.0, 0.0, 0.0, GLINT_RD_NOT_GLOSSY));
        return;
    }
    float3 own = GLINT_RD_SanitizeRadiance(GLINT_RD_LoadClamped(ipixel).rgb);
    float temporalVariance = clamp(GLINT_FiniteOr(GLINT_RD_LoadVariance(ipixel), 1.0), 0.0, 65504.0);
    if (surface.alpha < c.mirrorThreshold)
    {
        // Mirrors keep their own sample (no spatial reuse), as in the prefilter.
        GLINT_RD_StoreReconstructed(ipixel, float4(own, temporalVariance));
        return;
    }

    float2 uv = (float2(pixel) + 0.5) * c.inverseInputSize;
    float3 V = GLINT_RD_WorldView(r, GLINT_RD_ViewPosition(c, uv, surface.depth));
    // SSSR sampled around the normal bent toward V; weigh with the same lobe.
    float3 N = GLINT_GGX_BendNormalTowardView(surface.normal, V);
    float NdotV = max(dot(N, V), GLINT_GGX_BENT_NDOTV);
    float perceptual = GLINT_PerceptualRoughnessFromAlpha(surface.alpha);
    float radius = clamp(GLINT_FiniteOr(r.reconstructionRadius, 0.0), 0.0, GLINT_RD_RATIO_MAX_RADIUS) *
                   GLINT_Saturate(5.0 * perceptual);
    float angle = GLINT_RD_RatioAngle(pixel, r.frameIndex);
    float cosAngle = cos(angle), sinAngle = sin(angle);

    // Weighted mean of the radiance and weighted (West/Welford) moments of its luminance.
    float3 sum = float3(0.0, 0.0, 0.0);
    float weightSum = 0.0;
    float lumaMean = 0.0;
    float lumaM2 = 0.0;
    for (uint tap = 0; tap < 9; ++tap)
    {
        // Tap 0 is the centre itself; taps 1..8 the rotated disk, Gaussian-weighted by their
        // radius in the unit disk (sigma 0.9).
        float2 unit = tap == 0 ? float2(0.0, 0.0) : g_glint_rd_ratio_taps[tap - 1];
        float2 rotated = float2(cosAngle * unit.x - sinAngle * unit.y, sinAngle * unit.x + cosAngle * unit.y);
        int2 q = ipixel + int2(floor(rotated * radius + 0.5));
        if (any(q < 0) || any(q >= int2(c.inputSize))) continue;
        if (tap > 0 && !GLINT_RD_LoadSurface(c, q).glossy) continue;
        float4 ray = GLINT_RD_LoadRay(q);
        float3 L = GLINT_RD_Finite3(ray.xyz);
        float lengthSquared = dot(L, L);
        // An empty ray (not traced, or not a usable ray) still counts, barely.
        float w = 1e-6;
        if (lengthSquared > 0.25 && GLINT_IsFinite(ray.w) && ray.w >= 0.0)
        {
            float spatial = exp(-dot(unit, unit) / (2.0 * 0.9 * 0.9));
            w = spatial * GLINT_RD_RatioWeight(N, V, NdotV, surface.alpha, L * rsqrt(lengthSquared), ray.w);
        }
        if (!(w > 0.0) || !GLINT_IsFinite(w)) continue;
        float3 radiance = tap == 0 ? own : GLINT_RD_SanitizeRadiance(GLINT_RD_LoadClamped(q).rgb);
        float luma = GLINT_RD_Luma(radiance);
        sum += w * radiance;
        weightSum += w;
        float delta = luma - lumaMean;
        lumaMean += delta * (w / weightSum);
        lumaM2 += w * delta * (luma - lumaMean);
    }
    float3 result = own;
    float spatialVariance = 0.0;
    if (weightSum > 0.0 && GLINT_IsFinite(weightSum))
    {
        result = sum / weightSum;
        float lumaFloor = max(lumaMean, 0.5);
        spatialVariance = max(lumaM2 / weightSum, 0.0) / (lumaFloor * lumaFloor);
    }
    // The variance the resolve blends and the cleanup reads: this frame's relative luminance
    // variance of the reconstruction, smoothed over time with the temporal variance reproject
    // carried forward (DiligentFX: lerp(current, history, 0.9); 1 where history was rejected).
    float variance = lerp(spatialVariance, temporalVariance, 0.9);
    GLINT_RD_StoreReconstructed(ipixel, float4(GLINT_RD_SanitizeRadiance(result),
                                               clamp(GLINT_FiniteOr(variance, 1.0), 0.0, 65504.0)));
}

#endif // GLINT_REFLECTIONS_DENOISER_RECONSTRUCT_HLSLI
