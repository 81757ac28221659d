// glint hybrid reflections, pass 7: deferred shading (docs/hybrid.md). One thread per
// ray-traced list entry and per re-shaded screen-space hit, after the ray tracing pass: a
// ray-traced hit is shaded by the application's material and light callback, a screen-space hit
// by its G-buffer counterpart (the same lighting, so both paths agree), a miss (or a hit beyond
// maxRayDistance, which the tracer never reports) takes the prefiltered environment at the
// sample's footprint, exactly as an SSSR miss does. Ray-traced results fade to the environment
// over SSSR's roughness fade band like screen-space ones (whose confidence carries it), and are
// written to the pixel and its quad copies with confidence 1 for a hit and 0 for a miss;
// screen-space hits keep their confidence.
//
// Integration: the callbacks of glint_hybrid_trace.hlsli except GLINT_HYBRID_TraceRay and
// GLINT_HYBRID_StoreHit, SSSR's GLINT_SSSR_SampleEnvironment, GLINT_SSSR_StoreRadiance and
// GLINT_SSSR_StoreConfidence, and:
//
//   uint   GLINT_HYBRID_LoadReshadedCount();   counter 7 (copied by the arguments pass)
//   uint4  GLINT_HYBRID_LoadHit(uint index);   the record the tracing or intersection pass stored
//   float3 GLINT_HYBRID_ShadeHit(GLINT_HYBRID_Hit hit, float3 origin, float3 direction);
//       radiance leaving the hit point toward the ray's origin (emission plus lights)
//   float3 GLINT_HYBRID_ShadeScreenHit(int2 hitPixel, float3 hitPosition, float3 origin, float3 direction);
//       the same for the surface the G-buffer holds at hitPixel, which the screen-space ray hit
//       at about hitPosition (world)
//
// Entry: from main, GLINT_HYBRID_ShadeRays(c, h, rayIndex) as the tracing pass. Dispatch:
// [numthreads(64, 1, 1)], indirect at byte 36 of the arguments.
#ifndef GLINT_HYBRID_SHADE_HLSLI
#define GLINT_HYBRID_SHADE_HLSLI

#include "glint/hybrid/glint_hybrid_trace.hlsli"

uint GLINT_HYBRID_LoadReshadedCount();
uint4 GLINT_HYBRID_LoadHit(uint index);
float3 GLINT_HYBRID_ShadeHit(GLINT_HYBRID_Hit hit, float3 origin, float3 direction);
float3 GLINT_HYBRID_ShadeScreenHit(int2 hitPixel, float3 hitPosition, float3 origin, float3 direction);

void GLINT_HYBRID_ShadeRays(GLINT_SssrConstants c, GLINT_HybridConstants h, uint rayIndex)
{
    uint traced = GLINT_HYBRID_LoadRayTracedCount();
    if (rayIndex >= traced + GLINT_HYBRID_LoadReshadedCount())
        return;
    bool screenSpace = rayIndex >= traced;
    uint index = screenSpace ? GLINT_HYBRID_ReshadedSlot(c.inputSize, rayIndex - traced) : rayIndex;
    uint entry = GLINT_HYBRID_LoadRayTracedRay(index);
    GLINT_HYBRID_Ray ray = GLINT_HYBRID_RayOf(c, h, GLINT_SSSR_UnpackRayPixel(entry));
    uint4 record = GLINT_HYBRID_LoadHit(index);
    float weight;
    float distance;
    float3 hitRadiance = float3(0.0, 0.0, 0.0);
    if (screenSpace)
    {
        GLINT_HYBRID_ScreenHit hit = GLINT_HYBRID_UnpackScreenHit(record);
        weight = GLINT_Saturate(GLINT_FiniteOr(hit.confidence, 0.0));
        distance = GLINT_FiniteOr(hit.distance, GLINT_SSSR_MISS_DISTANCE);
        if (weight > 0.0)
            hitRadiance = GLINT_SSSR_SanitizeRadiance(GLINT_HYBRID_ShadeScreenHit(
                hit.pixel, ray.origin + distance * ray.sample.direction, ray.origin, ray.sample.direction));
    }
    else
    {
        GLINT_HYBRID_Hit hit = GLINT_HYBRID_UnpackHit(record);
        bool found = hit.t >= 0.0;
        weight = found ? 1.0 : 0.0;
        bool mirror = ray.sample.alpha < c.mirrorThreshold;
        if (!mirror && c.roughnessFadeBand > 0.0)
            weight *= GLINT_Saturate((c.roughnessThreshold - ray.sample.alpha) / c.roughnessFadeBand);
        if (found)
            hitRadiance = GLINT_SSSR_SanitizeRadiance(GLINT_HYBRID_ShadeHit(hit, ray.origin, ray.sample.direction));
        distance = found ? hit.t : GLINT_SSSR_MISS_DISTANCE;
    }
    float3 environment = float3(0.0, 0.0, 0.0);
    if (weight < 1.0)
    {
        float pdf = GLINT_GGX_ReflectionPdf(ray.sample.NdotV, ray.sample.NdotH, ray.sample.alpha);
        environment = GLINT_SSSR_SanitizeRadiance(
            GLINT_SSSR_SampleEnvironment(ray.sample.direction, GLINT_SSSR_EnvironmentLod(c, pdf)) * c.iblFactor);
    }
    float3 radiance = GLINT_SSSR_SanitizeRadiance(lerp(environment, hitRadiance, weight));
    distance = weight > 0.0 ? min(distance, GLINT_SSSR_MISS_DISTANCE) : GLINT_SSSR_MISS_DISTANCE;
    GLINT_SSSR_RayResult unused = (GLINT_SSSR_RayResult)0;
    GLINT_SSSR_StoreResult(entry, float4(radiance, GLINT_FiniteOr(distance, GLINT_SSSR_MISS_DISTANCE)), weight, unused);
}

#endif // GLINT_HYBRID_SHADE_HLSLI
