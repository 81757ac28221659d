// Primary visibility at pixel centres: device depth, world normal, exact motion (convention
// A, from the previous frame's camera and object transforms) and, with SCENE_WRITE_MATERIAL,
// perceptual roughness and base colour + metallic. Background: far depth, normal = -view
// direction, motion of a point at infinity.
#include "entry/common/glint_entry_common.hlsli"
#include "../harness/shaders/scene_constants.h"

GLINT_BINDING(0, 0) ConstantBuffer<GLINT_SceneConstants> g_scene;
GLINT_BINDING(1, 0) StructuredBuffer<SceneBvhNode> g_scene_nodes;
GLINT_BINDING(2, 0) StructuredBuffer<ScenePrimitive> g_scene_primitives;
GLINT_BINDING(3, 0) StructuredBuffer<SceneObject> g_scene_objects;
GLINT_BINDING(4, 0) GLINT_IMAGE_FORMAT(r32f) RWTexture2D<float> g_depth;
GLINT_BINDING(5, 0) GLINT_IMAGE_FORMAT(rgba32f) RWTexture2D<float4> g_normal;
GLINT_BINDING(6, 0) GLINT_IMAGE_FORMAT(rg32f) RWTexture2D<float2> g_motion;
#if SCENE_WRITE_MATERIAL
GLINT_BINDING(7, 0) StructuredBuffer<SceneMaterial> g_scene_materials;
GLINT_BINDING(8, 0) GLINT_IMAGE_FORMAT(r32f) RWTexture2D<float> g_roughness;
GLINT_BINDING(9, 0) GLINT_IMAGE_FORMAT(rgba32f) RWTexture2D<float4> g_material;
#endif

#include "../harness/shaders/scene_trace.hlsli"
#if SCENE_WRITE_MATERIAL
#include "../harness/shaders/scene_surface.hlsli"
#endif

[numthreads(8, 8, 1)] void main(uint3 id : SV_DispatchThreadID)
{
    if (any(id.xy >= g_scene.size)) return;
    float3 origin, dir;
    ScenePrimaryRay(id.xy, origin, dir);
    SceneHit hit = SceneTrace(origin, dir, 3.0e38, false);
    bool inside = false;
    float depth = g_scene.backgroundDepth;
    float3 position = origin;
    if (hit.t > 0.0) {
        position = origin + dir * hit.t;
        depth = SceneDeviceDepth(position, inside);
    }
    float2 uv = SceneUvOfPixel(id.xy);
    float2 motion;
    float3 normal;
    if (inside) {
        SceneObject o = g_scene_objects[g_scene_primitives[hit.prim].object];
        float4 p = float4(position, 1.0);
        float3 previous = float3(dot(o.toPrevious[0], p), dot(o.toPrevious[1], p), dot(o.toPrevious[2], p));
        motion = SceneUvOfClip(SCENE_MUL(g_scene.prevViewProjection, float4(previous, 1.0))) - uv;
        normal = SceneHitNormal(hit, origin, dir);
    } else {
        motion = SceneUvOfClip(SCENE_MUL(g_scene.prevViewProjection, float4(dir, 0.0))) - uv;
        normal = -dir;
    }
    g_depth[id.xy] = depth;
    g_normal[id.xy] = float4(normal, 0.0);
    g_motion[id.xy] = float2(isfinite(motion.x) ? motion.x : 0.0, isfinite(motion.y) ? motion.y : 0.0);
#if SCENE_WRITE_MATERIAL
    float roughness = 1.0;
    float4 material = float4(0.0, 0.0, 0.0, 0.0);
    if (inside) {
        SceneSurface s = SceneSurfaceAt(hit, origin, dir);
        roughness = s.perceptualRoughness;
        material = float4(s.baseColor, s.metallic);
    }
    g_roughness[id.xy] = roughness;
    g_material[id.xy] = material;
#endif
}
