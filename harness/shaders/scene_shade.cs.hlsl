// The lit colour buffer: direct light with converged visibility on hits, the environment on
// the background (and beyond the far plane).
#include "entry/common/glint_entry_common.hlsli"
#include "../harness/shaders/scene_constants.h"

GLINT_BINDING(0, 0) ConstantBuffer<GLINT_SceneConstants> g_scene;
GLINT_BINDING(1, 0) StructuredBuffer<SceneBvhNode> g_scene_nodes;
GLINT_BINDING(2, 0) StructuredBuffer<ScenePrimitive> g_scene_primitives;
GLINT_BINDING(3, 0) StructuredBuffer<SceneMaterial> g_scene_materials;
GLINT_BINDING(4, 0) StructuredBuffer<SceneLight> g_scene_lights;
GLINT_BINDING(5, 0) Texture2D<float4> g_scene_environment;
GLINT_BINDING(6, 0) GLINT_IMAGE_FORMAT(rgba32f) RWTexture2D<float4> g_color;

#include "../harness/shaders/scene_trace.hlsli"
#include "../harness/shaders/scene_surface.hlsli"
#include "../harness/shaders/scene_light.hlsli"
#include "../harness/shaders/scene_shading.hlsli"

[numthreads(8, 8, 1)] void main(uint3 id : SV_DispatchThreadID)
{
    if (any(id.xy >= g_scene.size)) return;
    float3 origin, dir;
    SceneHit hit;
    bool inside = ScenePrimaryHit(id.xy, origin, dir, hit);
    float3 color = inside ? SceneShade(SceneSurfaceAt(hit, origin, dir), -dir) : SceneEnvironment(dir);
    g_color[id.xy] = float4(SceneFinite(color), 1.0);
}
