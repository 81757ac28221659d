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

GLINT_HYBRID_Hit GLINT_HYBRID_TraceRay(float3 origin, float3 direction, float tMin, float tMax)
{
    SceneHit found = SceneTrace(origin, direction, tMax, false);
    GLINT_HYBRID_Hit hit;
    hit.t = found.t > tMin ? found.t : -1.0;
    hit.primitive = found.prim;
    hit.barycentrics = float2(0.0, 0.0); // the scene's shading recomputes the point from t
    hit.instance = 0;
    return hit;
}

#endif // HYBRID_SCENE_BINDINGS_HLSLI
