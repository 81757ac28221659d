// The simulated scene as the hybrid effect's ray tracer and shading see it (harness only):
// the BVH and materials the simulator renders with, its lights, and its constants as a
// one-element structured buffer (the pass's own cbuffer holds the SSSR and hybrid constants).
// Bindings 20 and up, after the entry's own.
#ifndef HYBRID_SCENE_BINDINGS_HLSLI
#define HYBRID_SCENE_BINDINGS_HLSLI

#include "../harness/shaders/scene_constants.h"

GLINT_BINDING(20, 0) StructuredBuffer<GLINT_SceneConstants> g_scene_constants;
GLINT_BINDING(21, 0) StructuredBuffer<SceneBvhNode> g_scene_nodes;
GLINT_BINDING(22, 0) StructuredBuffer<ScenePrimitive> g_scene_primitives;
#define g_scene (g_scene_constants[0])

#include "../harness/shaders/scene_trace.hlsli"

// A triangle hit's barycentrics as ray tracing APIs define them: the weights of p1 and p2 (the
// point is p0 + b.x (p1 - p0) + b.y (p2 - p0)), as the traversal computed them; (0, 0) for a sphere.
float2 HybridSceneBarycentrics(ScenePrimitive p, float3 origin, float3 direction)
{
    if (p.kind != GLINT_SCENE_PRIM_TRIANGLE)
        return float2(0.0, 0.0);
    float3 e1 = p.p1 - p.p0;
    float3 e2 = p.p2 - p.p0;
    float3 pv = cross(direction, e2);
    float invDet = 1.0 / dot(e1, pv);
    float3 tv = origin - p.p0;
    float3 qv = cross(tv, e1);
    return float2(dot(tv, pv) * invDet, dot(direction, qv) * invDet);
}

// The record an acceleration structure over the same primitives gives (scene_acceleration.h):
// the primitive's index in g_scene_primitives, its barycentrics, and the custom index of the
// structure's one instance, 0.
GLINT_HYBRID_Hit GLINT_HYBRID_TraceRay(float3 origin, float3 direction, float tMin, float tMax)
{
    SceneHit found = SceneTrace(origin, direction, tMax, false);
    GLINT_HYBRID_Hit hit;
    hit.t = found.t > tMin ? found.t : -1.0;
    hit.primitive = found.prim;
    hit.barycentrics = hit.t > 0.0 ? HybridSceneBarycentrics(g_scene_primitives[found.prim], origin, direction)
                                   : float2(0.0, 0.0);
    hit.instance = 0;
    return hit;
}

#endif // HYBRID_SCENE_BINDINGS_HLSLI
