// glint hybrid reflections, pass 6: ray tracing (docs/hybrid.md). One thread per ray-traced
// list entry: the same GGX sample the screen-space march would have used (this frame's blue
// noise), from the surface offset robustly off itself, traced by the application's ray
// tracer; the hit (or miss) is stored as a 16-byte record for the deferred shading pass.
//
// Integration: the callbacks GLINT_SSSR_LoadDepth (mip 0), GLINT_SSSR_LoadNormal,
// GLINT_SSSR_LoadRoughness and GLINT_SSSR_LoadBlueNoise of glint_sssr_intersect.hlsli, and:
//
//   uint GLINT_HYBRID_LoadRayTracedCount();           counter 5 (copied by the arguments pass)
//   uint GLINT_HYBRID_LoadRayTracedRay(uint index);
//   GLINT_HYBRID_Hit GLINT_HYBRID_TraceRay(float3 origin, float3 direction, float tMin, float tMax);
//       world space, direction unit; the closest opaque hit, t < 0 for a miss. Engines:
//       RayQuery (hlsl/entry/hybrid/hybrid_trace_rayquery.cs.hlsl); glint's harness: a BVH.
//   void GLINT_HYBRID_StoreHit(uint index, uint4 record);   GLINT_HYBRID_PackHit(hit)
//
// Entry: from main, GLINT_HYBRID_TraceRays(c, h, rayIndex) with the SSSR intersection's ray
// index formula. Dispatch: [numthreads(64, 1, 1)], indirect at byte 24 of the arguments.
#ifndef GLINT_HYBRID_TRACE_HLSLI
#define GLINT_HYBRID_TRACE_HLSLI

#include "glint/hybrid/glint_hybrid_common.hlsli"
#include "glint/sssr/glint_sssr_intersect.hlsli"

// What the application's ray tracer found. Barycentrics and the primitive and instance ids
// are for the application's own shading callback (glint stores them and hands them back).
struct GLINT_HYBRID_Hit
{
    float t;             // world distance along the unit direction; < 0: miss
    uint primitive;      // e.g. RayQuery's CommittedPrimitiveIndex
    float2 barycentrics; // e.g. CommittedTriangleBarycentrics, each in [0, 1]
    uint instance;       // e.g. CommittedInstanceID, or a material id
};

uint GLINT_HYBRID_LoadRayTracedCount();
uint GLINT_HYBRID_LoadRayTracedRay(uint index);
GLINT_HYBRID_Hit GLINT_HYBRID_TraceRay(float3 origin, float3 direction, float tMin, float tMax);
void GLINT_HYBRID_StoreHit(uint index, uint4 record);

// The 16-byte hit record: t (fp32; -1 for a miss), primitive, barycentrics as two unorm16
// (rounded: 1.5e-5 of the triangle, unlike fp16 UVs), instance.
uint4 GLINT_HYBRID_PackHit(GLINT_HYBRID_Hit hit)
{
    float t = hit.t >= 0.0 ? hit.t : -1.0; // NaN is a miss
    uint2 b = uint2(round(saturate(hit.barycentrics) * 65535.0));
    return uint4(asuint(t), hit.primitive, b.x | (b.y << 16), hit.instance);
}

GLINT_HYBRID_Hit GLINT_HYBRID_UnpackHit(uint4 record)
{
    GLINT_HYBRID_Hit hit;
    hit.t = asfloat(record.x);
    hit.primitive = record.y;
    hit.barycentrics = float2(record.z & 0xFFFFu, record.z >> 16) / 65535.0;
    hit.instance = record.w;
    return hit;
}

// Moves a point off its surface along the (unit) normal by a few float steps of its own
// magnitude (integer offsets of the bits; a fixed offset near the origin, where the steps are
// tiny), so the offset is the same number of representable values at any distance (Waechter
// and Binder, "A Fast and Robust Method for Avoiding Self-Intersection", Ray Tracing Gems).
float3 GLINT_HYBRID_OffsetAlongNormal(float3 p, float3 n)
{
    int3 steps = int3(256.0 * n);
    float3 moved = asfloat(asint(p) + int3(p.x < 0.0 ? -steps.x : steps.x, p.y < 0.0 ? -steps.y : steps.y,
                                           p.z < 0.0 ? -steps.z : steps.z));
    float3 nearOrigin = p + n * (1.0 / 65536.0);
    return float3(abs(p.x) < 1.0 / 32.0 ? nearOrigin.x : moved.x, abs(p.y) < 1.0 / 32.0 ? nearOrigin.y : moved.y,
                  abs(p.z) < 1.0 / 32.0 ? nearOrigin.z : moved.z);
}

// The world-space ray of a listed pixel: origin on the reconstructed surface, pushed along the
// bent normal by rayOffset (the depth buffer's reconstruction error) and then robustly off it.
struct GLINT_HYBRID_Ray
{
    float3 origin;
    GLINT_SSSR_PixelSample sample;
};

GLINT_HYBRID_Ray GLINT_HYBRID_RayOf(GLINT_SssrConstants c, GLINT_HybridConstants h, uint2 pixel)
{
    GLINT_HYBRID_Ray ray;
    ray.sample = GLINT_SSSR_SamplePixel(c, pixel);
    float3 position = GLINT_SSSR_Mul(c.worldFromView, float4(ray.sample.viewPosition, 1.0)).xyz;
    ray.origin = GLINT_HYBRID_OffsetAlongNormal(position + ray.sample.normal * h.rayOffset, ray.sample.normal);
    return ray;
}

void GLINT_HYBRID_TraceRays(GLINT_SssrConstants c, GLINT_HybridConstants h, uint rayIndex)
{
    if (rayIndex >= GLINT_HYBRID_LoadRayTracedCount())
        return;
    uint entry = GLINT_HYBRID_LoadRayTracedRay(rayIndex);
    GLINT_HYBRID_Ray ray = GLINT_HYBRID_RayOf(c, h, GLINT_SSSR_UnpackRayPixel(entry));
    GLINT_HYBRID_Hit hit;
    hit.t = -1.0;
    hit.primitive = 0;
    hit.barycentrics = float2(0.0, 0.0);
    hit.instance = 0;
    // A non-finite ray (a NaN normal or depth slipped through) is a miss, never traced.
    if (GLINT_IsFinite(dot(ray.origin, ray.origin) + dot(ray.sample.direction, ray.sample.direction)))
        hit = GLINT_HYBRID_TraceRay(ray.origin, ray.sample.direction, 0.0, h.maxRayDistance);
    GLINT_HYBRID_StoreHit(rayIndex, GLINT_HYBRID_PackHit(hit));
}

#endif // GLINT_HYBRID_TRACE_HLSLI
