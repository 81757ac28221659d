// Visibility of light g_scene.shadowLight from the primary hit, averaged over g_scene.samples
// cone samples toward the light's disc: 1 sample = the noisy `shadow` layer, many = the
// `reference.shadow` layer, run in chunks (sampleStart, sampleTotal) that accumulate a running
// mean in the image, over a run of unchanged frames too (sampleBase). New random numbers every
// frame (frameIndex seeds them).
// Background pixels are lit (1).
// Permutation "blocker" (SCENE_WRITE_BLOCKER=1, one sample per pixel): also writes the distance
// along the sample's ray to the closest blocker into g_blocker (0 when lit or on the background),
// the `shadow_blocker` layer the shadow denoiser's penumbra estimate reads.
#include "entry/common/glint_entry_common.hlsli"
#include "../harness/shaders/scene_constants.h"

GLINT_BINDING(0, 0) ConstantBuffer<GLINT_SceneConstants> g_scene;
GLINT_BINDING(1, 0) StructuredBuffer<SceneBvhNode> g_scene_nodes;
GLINT_BINDING(2, 0) StructuredBuffer<ScenePrimitive> g_scene_primitives;
GLINT_BINDING(3, 0) StructuredBuffer<SceneLight> g_scene_lights;
GLINT_BINDING(4, 0) GLINT_IMAGE_FORMAT(r32f) RWTexture2D<float> g_visibility;
#if SCENE_WRITE_BLOCKER
GLINT_BINDING(5, 0) GLINT_IMAGE_FORMAT(r32f) RWTexture2D<float> g_blocker;
#endif

#include "../harness/shaders/scene_trace.hlsli"
#include "../harness/shaders/scene_light.hlsli"

[numthreads(8, 8, 1)] void main(uint3 id : SV_DispatchThreadID)
{
    if (any(id.xy >= g_scene.size)) return;
    float3 origin, dir;
    SceneHit hit;
    bool inside = ScenePrimaryHit(id.xy, origin, dir, hit);
    float visibility = 1.0;
    float blocker = 0.0;
    if (inside) {
        float3 position = origin + dir * hit.t;
        float3 normal = SceneHitNormal(hit, origin, dir);
        uint rng = SceneSeed(id.xy, g_scene.frameIndex, g_scene.passSalt);
#if SCENE_WRITE_BLOCKER
        visibility = SceneVisibilityOneSample(position, normal, SceneLightConeAt(g_scene.shadowLight, position), rng,
                                              blocker);
        // Below the surface there is no blocker (-1). On a sphere the terminator's penumbra is
        // the band where the light's cone crosses the horizon, 2 r tan(angular radius) wide, as
        // a blocker at distance r would cast: its radius stands in. A flat face is below the
        // horizon as a whole, so its edge is as hard as the geometry: 0.
        if (blocker < 0.0) {
            ScenePrimitive surface = g_scene_primitives[hit.prim];
            blocker = surface.kind == GLINT_SCENE_PRIM_SPHERE ? surface.p1.x : 0.0;
        }
        // A sphere light's angular size varies over the frame; the denoiser takes one (the
        // camera's, g_scene.shadowLightTanReference). Its penumbra at this receiver is
        // 2 b r / (d - b) wide (r the light's radius, d its distance): the blocker distance is
        // scaled by (r / (d - b)) / tan_reference so that 2 b' tan_reference is that width.
        if (g_scene.shadowLightTanReference > 0.0 && blocker > 0.0) {
            SceneLight light = g_scene_lights[g_scene.shadowLight];
            float toLight = length(light.where - position);
            blocker *= light.size / max(toLight - blocker, 1e-6) / g_scene.shadowLightTanReference;
        }
#else
        float sum = SceneVisibilitySum(position, normal, SceneLightConeAt(g_scene.shadowLight, position),
                                       g_scene.sampleStart, g_scene.samples, g_scene.sampleTotal, rng);
        // Running mean over the samples so far: the frame's earlier chunks and, over a run of
        // unchanged frames, the run's earlier frames (each frame its own stratification); the
        // image holds their mean.
        uint earlier = g_scene.sampleBase + g_scene.sampleStart;
        float previous = earlier == 0u ? 0.0 : g_visibility[id.xy] * float(earlier);
        visibility = (previous + sum) / float(max(earlier + g_scene.samples, 1u));
#endif
    }
    g_visibility[id.xy] = visibility;
#if SCENE_WRITE_BLOCKER
    g_blocker[id.xy] = blocker;
#endif
}
