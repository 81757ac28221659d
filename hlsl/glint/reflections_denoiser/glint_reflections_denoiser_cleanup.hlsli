// glint reflections denoiser, ratio-estimator path, pass 4: bilateral cleanup
// (docs/reflections_denoiser.md, "Ratio-estimator path"). Runs after the resolve: a small
// edge-aware blur of the resolved radiance where its variance says noise is left, written over
// the effect's output. The radiance history keeps the unblurred resolve result, so the blur
// never feeds back into next frame.
//
// Per glossy pixel: nothing when variance <= 5e-5; otherwise the radius is
// floor(min(2 sigma, sat(8 r) (variance > 1e-3 ? 2 : 0))) pixels (r = perceptual roughness,
// sigma = cleanupSigma): 3x3 at the defaults, none for mirrors. Tap weight
// exp(-|d|^2 / (2 sigma^2)) exp(-|z - z_q| / (|d . grad z| + 1e-6)) max(0, N.N_q)^128, over
// glossy taps only; grad z is the view depth's screen gradient, from the smaller one-sided
// difference on each axis (so a depth edge on one side does not inflate it). The tile and a
// 2-pixel apron of guides and radiance are loaded into groupshared memory once.
//
// Integration: the callbacks of glint_reflections_denoiser_common.hlsli, and
//
//   float3 GLINT_RD_LoadResolved(int2 pixel);    this frame's resolved radiance (the radiance history)
//   float  GLINT_RD_LoadVariance(int2 pixel);    this frame's final variance (the resolve's)
//   float4 GLINT_RD_LoadOutput(int2 pixel);      the effect's output; its alpha (hit distance) is kept
//   void   GLINT_RD_StoreOutput(int2 pixel, float4 radianceAndHitDistance);
//
// Entry: from main, GLINT_RD_Cleanup(r, SV_GroupID.x, SV_GroupThreadID.xy), r the
// GLINT_ReflectionsDenoiserRatioConstants (glint_reflections_denoiser_ratio_constants.h) in a
// cbuffer, as in glint_reflections_denoiser_common.hlsli.
// Dispatch: [numthreads(8, 8, 1)] (also in the 16-bit permutation), indirect (tiles, 1, 1) from
// SSSR's arguments at byte 12.
#ifndef GLINT_REFLECTIONS_DENOISER_CLEANUP_HLSLI
#define GLINT_REFLECTIONS_DENOISER_CLEANUP_HLSLI

#include "glint/reflections_denoiser/glint_reflections_denoiser_common.hlsli"
#include "glint/reflections_denoiser/glint_reflections_denoiser_ratio_constants.h"

float3 GLINT_RD_LoadResolved(int2 pixel);
float GLINT_RD_LoadVariance(int2 pixel);
float4 GLINT_RD_LoadOutput(int2 pixel);
void GLINT_RD_StoreOutput(int2 pixel, float4 radianceAndHitDistance);

#define GLINT_RD_CLEANUP_EXIT_VARIANCE 5e-5
#define GLINT_RD_CLEANUP_FULL_RADIUS_VARIANCE 1e-3
// The radius is at most 2 (2 sat(8 r)), so the tile plus a 2-pixel apron holds every tap.
#define GLINT_RD_CLEANUP_APRON 2
#define GLINT_RD_CLEANUP_SPAN (GLINT_RD_TILE + 2 * GLINT_RD_CLEANUP_APRON)

// Per span texel: normal and view depth (-1: outside the image or not glossy), and the
// resolved radiance.
groupshared float4 g_glint_rd_cleanup_geometry[GLINT_RD_CLEANUP_SPAN * GLINT_RD_CLEANUP_SPAN];
groupshared float3 g_glint_rd_cleanup_radiance[GLINT_RD_CLEANUP_SPAN * GLINT_RD_CLEANUP_SPAN];

// d(view depth)/d(pixel) along one axis: the one-sided difference of smaller magnitude among
// the glossy sides (the forward one on a tie), 0 when neither side is glossy.
float GLINT_RD_CleanupSlope(float before, float centre, float after)
{
    float backward = before > 0.0 ? centre - before : 3.0e38;
    float forward = after > 0.0 ? after - centre : 3.0e38;
    float slope = abs(backward) < abs(forward) ? backward : forward;
    return abs(slope) < 1.0e38 ? slope : 0.0;
}

void GLINT_RD_Cleanup(GLINT_ReflectionsDenoiserRatioConstants r, uint groupId, uint2 local)
{
    GLINT_ReflectionsDenoiserConstants c = r.common;
    uint entry = GLINT_RD_LoadTile(groupId);
    uint2 tileOrigin = uint2(GLINT_WIRE_TileEntryX(entry), GLINT_WIRE_TileEntryY(entry));
    uint localIndex = local.y * GLINT_RD_TILE + local.x;
    for (uint i = localIndex; i < GLINT_RD_CLEANUP_SPAN * GLINT_RD_CLEANUP_SPAN;
         i += GLINT_RD_TILE * GLINT_RD_TILE)
    {
        int2 q = int2(tileOrigin) + int2(i % GLINT_RD_CLEANUP_SPAN, i / GLINT_RD_CLEANUP_SPAN) -
                 GLINT_RD_CLEANUP_APRON;
        bool inImage = all(q >= 0) && all(q < int2(c.inputSize));
        int2 clamped = clamp(q, int2(0, 0), int2(c.inputSize) - 1); // no load leaves the image
        GLINT_RD_Surface s = GLINT_RD_LoadSurface(c, clamped);
        bool usable = inImage && s.glossy;
        float3 resolved = GLINT_RD_SanitizeRadiance(GLINT_RD_LoadResolved(clamped));
        g_glint_rd_cleanup_geometry[i] = float4(s.normal, usable ? s.viewDepth : -1.0);
        g_glint_rd_cleanup_radiance[i] = usable ? resolved : float3(0.0, 0.0, 0.0);
    }
    GroupMemoryBarrierWithGroupSync();

    uint2 pixel = tileOrigin + local;
    if (any(pixel >= c.inputSize)) return;
    int2 ipixel = int2(pixel);
    int centre =
        int((local.y + GLINT_RD_CLEANUP_APRON) * GLINT_RD_CLEANUP_SPAN + local.x + GLINT_RD_CLEANUP_APRON);
    float4 geometry = g_glint_rd_cleanup_geometry[centre];
    if (!(geometry.w > 0.0)) return; // not glossy: the resolve kept classification's value there
    float variance = clamp(GLINT_FiniteOr(GLINT_RD_LoadVariance(ipixel), 1.0), 0.0, 65504.0);
    if (variance <= GLINT_RD_CLEANUP_EXIT_VARIANCE) return; // converged: the resolve's output stands
    float sigma = clamp(GLINT_FiniteOr(r.cleanupSigma, 0.0), 1e-3, 2.0);
    float alpha = GLINT_FiniteOr(GLINT_RD_LoadRoughness(ipixel), 1.0);
    float perceptual = GLINT_PerceptualRoughnessFromAlpha(alpha);
    float reach =
        GLINT_Saturate(8.0 * perceptual) * (variance > GLINT_RD_CLEANUP_FULL_RADIUS_VARIANCE ? 2.0 : 0.0);
    int radius = min(int(floor(min(2.0 * sigma, reach))), GLINT_RD_CLEANUP_APRON);
    if (radius <= 0) return;

    float2 gradient = float2(
        GLINT_RD_CleanupSlope(g_glint_rd_cleanup_geometry[centre - 1].w, geometry.w,
                              g_glint_rd_cleanup_geometry[centre + 1].w),
        GLINT_RD_CleanupSlope(g_glint_rd_cleanup_geometry[centre - GLINT_RD_CLEANUP_SPAN].w, geometry.w,
                              g_glint_rd_cleanup_geometry[centre + GLINT_RD_CLEANUP_SPAN].w));
    float3 sum = float3(0.0, 0.0, 0.0);
    float weightSum = 0.0;
    for (int y = -radius; y <= radius; ++y)
        for (int x = -radius; x <= radius; ++x)
        {
            int index = centre + y * GLINT_RD_CLEANUP_SPAN + x;
            float4 q = g_glint_rd_cleanup_geometry[index];
            if (!(q.w > 0.0)) continue;
            float2 d = float2(float(x), float(y));
            float w = exp(-0.5 * dot(d, d) / (sigma * sigma)) *
                      exp(-abs(geometry.w - q.w) / (abs(dot(d, gradient)) + 1e-6)) *
                      pow(max(dot(geometry.xyz, q.xyz), 0.0), 128.0);
            sum += w * g_glint_rd_cleanup_radiance[index];
            weightSum += w;
        }
    // The centre has weight 1, so weightSum >= 1.
    float3 result = GLINT_RD_SanitizeRadiance(sum / max(weightSum, 1e-6));
    float hitDistance = GLINT_RD_LoadOutput(ipixel).a;
    GLINT_RD_StoreOutput(ipixel, float4(result, clamp(GLINT_FiniteOr(hitDistance, GLINT_RD_MISS_DISTANCE),
                                                      0.0, GLINT_RD_MISS_DISTANCE)));
}

#endif // GLINT_REFLECTIONS_DENOISER_CLEANUP_HLSLI
