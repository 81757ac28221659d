// Stub definitions of the hybrid callbacks that take or return a hit record
// (GLINT_HYBRID_Hit, glint_hybrid_trace.hlsli): the trace and shade header checks.
#ifndef GLINT_CHECK_HYBRID_HIT_STUBS_HLSLI
#define GLINT_CHECK_HYBRID_HIT_STUBS_HLSLI

#include "check/stubs/hybrid.stubs.hlsli"

GLINT_HYBRID_Hit GLINT_HYBRID_TraceRay(float3 origin, float3 direction, float tMin, float tMax)
{
    GLINT_HYBRID_Hit hit;
    hit.t = dot(origin, direction) > tMin ? tMax : -1.0;
    hit.primitive = 1;
    hit.barycentrics = origin.xy;
    hit.instance = 2;
    return hit;
}
float3 GLINT_HYBRID_ShadeHit(GLINT_HYBRID_Hit hit, float3 origin, float3 direction)
{
    return origin * hit.t + direction * float(hit.primitive) + float3(hit.barycentrics, float(hit.instance));
}

#endif // GLINT_CHECK_HYBRID_HIT_STUBS_HLSLI
