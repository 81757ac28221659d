// glint hybrid reflections, pass 7: deferred shading of the ray-traced rays (docs/hybrid.md).
// One thread per ray-traced list entry, after the ray tracing pass: a hit is shaded by the
// application's material and light callback, a miss (or a hit beyond maxRayDistance, which the
// tracer never reports) takes the prefiltered environment at the sample's footprint, exactly
// as an SSSR miss does. Results fade to the environment over SSSR's roughness fade band like
// screen-space ones, and are written to the pixel and its quad copies with confidence 1 for a
// hit and 0 for a miss.
//
// Integration: the callbacks of glint_hybrid_trace.hlsli except GLINT_HYBRID_TraceRay and
// GLINT_HYBRID_StoreHit, SSSR's GLINT_SSSR_SampleEnvironment, GLINT_SSSR_StoreRadiance and
// GLINT_SSSR_StoreConfidence, and:
//
//   uint4  GLINT_HYBRID_LoadHit(uint index);   the record the tracing pass stored
//   float3 GLINT_HYBRID_ShadeHit(GLINT_HYBRID_Hit hit, float3 origin, float3 direction);
//       radiance leaving the hit point toward the ray's origin (emission plus lights)
//
// Entry: from main, GLINT_HYBRID_ShadeRays(c, h, rayIndex) as the tracing pass. Dispatch:
// [numthreads(64, 1, 1)], indirect at byte 24 of the arguments.
#ifndef GLINT_HYBRID_SHADE_HLSLI
#define GLINT_HYBRID_SHADE_HLSLI

#include "glint/hybrid/glint_hybrid_trace.hlsli"

uint4 GLINT_HYBRID_LoadHit(uint index);
float3 GLINT_HYBRID_ShadeHit(GLINT_HYBRID_Hit hit, float3 origin, float3 direction);

void GLINT_HYBRID_ShadeRays(GLINT_SssrConstants c, GLINT_HybridConstants h, uint rayIndex)
{
    if (rayIndex >= GLINT_HYBRID_LoadRayTracedCount())
        return;
    uint entry = GLINT_HYBRID_LoadRayTracedRay(rayIndex);
    GLINT_HYBRID_Ray ray = GLINT_HYBRID_RayOf(c, h, GLINT_SSSR_UnpackRayPixel(entry));
    GLINT_HYBRID_Hit hit = GLINT_HYBRID_UnpackHit(GLINT_HYBRID_LoadHit(rayIndex));
    bool found = hit.t >= 0.0;
    float weight = found ? 1.0 : 0.0;
    bool mirror = ray.sample.alpha < c.mirrorThreshold;
    if (!mirror && c.roughnessFadeBand > 0.0)
        weight *= GLINT_Saturate((c.roughnessThreshold - ray.sample.alpha) / c.roughnessFadeBand);
    float3 hitRadiance = float3(0.0, 0.0, 0.0);
    if (found)
        hitRadiance = GLINT_SSSR_SanitizeRadiance(GLINT_HYBRID_ShadeHit(hit, ray.origin, ray.sample.direction));
    float3 environment = float3(0.0, 0.0, 0.0);
    if (weight < 1.0)
    {
        float pdf = GLINT_GGX_ReflectionPdf(ray.sample.NdotV, ray.sample.NdotH, ray.sample.alpha);
        environment = GLINT_SSSR_SanitizeRadiance(
            GLINT_SSSR_SampleEnvironment(ray.sample.direction, GLINT_SSSR_EnvironmentLod(c, pdf)) * c.iblFactor);
    }
    float3 radiance = GLINT_SSSR_SanitizeRadiance(lerp(environment, hitRadiance, weight));
    float distance = found && weight > 0.0 ? min(hit.t, GLINT_SSSR_MISS_DISTANCE) : GLINT_SSSR_MISS_DISTANCE;
    GLINT_SSSR_RayResult unused = (GLINT_SSSR_RayResult)0;
    GLINT_SSSR_StoreResult(entry, float4(radiance, GLINT_FiniteOr(distance, GLINT_SSSR_MISS_DISTANCE)), weight, unused);
}

#endif // GLINT_HYBRID_SHADE_HLSLI
