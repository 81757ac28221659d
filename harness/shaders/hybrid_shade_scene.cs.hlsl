// The hybrid effect's deferred shading in the harness: GLINT_HYBRID_ShadeHit by the
// simulator's own shading (the colour buffer's), so ray-traced reflections see the scene
// exactly as the reference does. GLINT_HYBRID_ShadeScreenHit shades the surface the hit pixel
// shows with the same function; the harness's G-buffer has no material channels, so it finds
// that surface's primitive by tracing the camera ray through the pixel (an engine reads its
// G-buffer there instead).
#include "entry/common/glint_entry_common.hlsli"
#include "glint/sssr/glint_sssr_constants.h"
#include "glint/hybrid/glint_hybrid_constants.h"
#include "glint/hybrid/glint_hybrid_shade.hlsli"
#include "entry/sssr/sssr_environment.hlsli"

#include "../harness/shaders/hybrid_ray_bindings.hlsli"
GLINT_BINDING(7, 0) StructuredBuffer<uint4> g_glint_hits;
GLINT_BINDING(8, 0) Texture2D<float4> g_glint_environment;
GLINT_BINDING(9, 0) SamplerState g_glint_linear_clamp;
#if GLINT_SSSR_HALF_STORAGE
GLINT_BINDING(10, 0) GLINT_IMAGE_FORMAT(rgba16f) RWTexture2D<float4> g_glint_radiance;
GLINT_BINDING(11, 0) GLINT_IMAGE_FORMAT(r16f) RWTexture2D<float> g_glint_confidence;
#else
GLINT_BINDING(10, 0) GLINT_IMAGE_FORMAT(rgba32f) RWTexture2D<float4> g_glint_radiance;
GLINT_BINDING(11, 0) GLINT_IMAGE_FORMAT(r32f) RWTexture2D<float> g_glint_confidence;
#endif

#include "../harness/shaders/hybrid_scene_bindings.hlsli"
GLINT_BINDING(23, 0) StructuredBuffer<SceneMaterial> g_scene_materials;
GLINT_BINDING(24, 0) StructuredBuffer<SceneLight> g_scene_lights;
#define g_scene_environment g_glint_environment
#include "../harness/shaders/scene_surface.hlsli"
#include "../harness/shaders/scene_light.hlsli"
#include "../harness/shaders/scene_shading.hlsli"

float3 GLINT_SSSR_SampleEnvironment(float3 direction, float lod)
{
    return SSSR_EntrySampleLatLong(g_glint_environment, g_glint_linear_clamp, direction, lod);
}
void GLINT_SSSR_StoreRadiance(int2 pixel, float4 value) { g_glint_radiance[pixel] = value; }
void GLINT_SSSR_StoreConfidence(int2 pixel, float confidence) { g_glint_confidence[pixel] = confidence; }
uint GLINT_HYBRID_LoadReshadedCount() { return g_glint_counters[GLINT_HYBRID_COUNTER_RESHADED_COPY]; }
uint4 GLINT_HYBRID_LoadHit(uint index) { return g_glint_hits[index]; }
float3 GLINT_HYBRID_ShadeHit(GLINT_HYBRID_Hit hit, float3 origin, float3 direction)
{
    SceneHit found;
    found.t = hit.t;
    found.prim = hit.primitive;
    return SceneShade(SceneSurfaceAt(found, origin, direction), -direction);
}
float3 GLINT_HYBRID_ShadeScreenHit(int2 hitPixel, float3 hitPosition, float3 origin, float3 direction)
{
    float2 uv = (float2(hitPixel) + 0.5) * g_glint_sssr.inverseInputSize;
    float3 viewPosition = GLINT_SSSR_ViewPosition(g_glint_sssr, uv, GLINT_SSSR_LoadDepth(hitPixel, 0));
    float3 camera = GLINT_SSSR_Mul(g_glint_sssr.worldFromView, float4(0.0, 0.0, 0.0, 1.0)).xyz;
    float3 toSurface = normalize(GLINT_SSSR_MulDirection(g_glint_sssr.worldFromView, viewPosition));
    SceneHit seen = SceneTrace(camera, toSurface, 3.0e38, false);
    if (seen.t < 0.0)
        return SceneEnvironment(toSurface); // what the camera sees through the pixel
    return SceneShade(SceneSurfaceAt(seen, camera, toSurface), -direction);
}

[numthreads(64, 1, 1)] void main(uint3 groupId : SV_GroupID, uint groupIndex : SV_GroupIndex)
{
    GLINT_HYBRID_ShadeRays(g_glint_sssr, g_glint_hybrid, HybridRayIndex(groupId, groupIndex));
}
