// Constants and GPU data layouts of the scene simulator's ray caster, compiled by both C++
// (harness/scene) and HLSL (harness/shaders). One definition, so the host packing and the
// shader's view of the buffers cannot drift apart; static_asserts pin the C++ side.
#ifndef GLINT_SCENE_CONSTANTS_H
#define GLINT_SCENE_CONSTANTS_H

#include "glint/common/glint_shared_types.h"

// Primitive kinds in ScenePrimitive::kind.
#define GLINT_SCENE_PRIM_TRIANGLE 0
#define GLINT_SCENE_PRIM_SPHERE 1
// Light kinds in SceneLight::kind.
#define GLINT_SCENE_LIGHT_DIRECTIONAL 0
#define GLINT_SCENE_LIGHT_SPHERE 1
// Traversal stack depth; the CPU builder never makes a deeper tree (kMaxBvhDepth).
#define GLINT_SCENE_STACK_SIZE 64

#ifdef __cplusplus
namespace glint::shaders {
GLINT_SHARED_USING;
struct float3 { float x, y, z; };
#define GLINT_SCENE_MATRIX(name) float4 name[4]
#else
// Matrices are four float4 rows rather than a (row_major) float4x4: the row-major qualifier
// on a member of a ConstantBuffer<T> struct is not honoured by every front end, and rows
// leave no doubt. SCENE_MUL(m, v) is m.v.
#define GLINT_SCENE_MATRIX(name) float4 name[4]
#define SCENE_MUL(m, v) float4(dot((m)[0], (v)), dot((m)[1], (v)), dot((m)[2], (v)), dot((m)[3], (v)))
#endif

// Binary BVH node. count > 0: leaf holding primitives first .. first + count - 1; count == 0
// and first > 0: interior node whose children are nodes `first` and `first + 1`; count == 0
// and first == 0 (only ever the root, as no child has index 0): an empty scene.
struct SceneBvhNode {
    float3 boundsMin;
    uint first;
    float3 boundsMax;
    uint count;
};

// A world-space triangle (p0, p1, p2) or sphere (centre p0, radius p1.x).
struct ScenePrimitive {
    float3 p0;
    uint kind;
    float3 p1;
    uint material;
    float3 p2;
    uint object; // index into the object table (previous-frame transforms)
};

// GGX material. Perceptual roughness r = lerp(roughness, roughnessEnd, t) with
// t = saturate(dot(p, rampPlane.xyz) + rampPlane.w); rampPlane = 0 disables the ramp.
struct SceneMaterial {
    float3 baseColor;
    float metallic;
    float3 emissive;
    float roughness;
    float4 rampPlane;
    float roughnessEnd;
    float padding0;
    float padding1;
    float padding2;
};

// Rows of the 3x4 matrix that takes a world point on this object now to where the same
// material point was in the previous frame (previousWorld * inverse(currentWorld)).
struct SceneObject {
    float4 toPrevious[3];
};

// Every light is seen from a point as a cone: directional lights have a fixed direction and
// angular radius, sphere lights subtend asin(radius / distance). `radiance` is the irradiance
// (times colour) the light delivers at normal incidence (directional) or at unit distance
// (sphere: irradiance = radiance / distance^2).
struct SceneLight {
    float3 where;  // directional: unit direction toward the light; sphere: centre
    uint kind;
    float3 radiance;
    float size;    // directional: angular radius in radians; sphere: radius
};

// One texel of the environment map's sampling table (alias method, Walker/Vose): slot i keeps
// texel i when a uniform u < keep and takes texel `alias` otherwise. `probability` is texel i's
// own probability (the table's probabilities sum to 1), which gives the density of a direction.
struct SceneEnvironmentSample {
    float keep;
    uint alias;
    float probability;
    uint padding;
};

GLINT_CONSTANTS_BEGIN(GLINT_SceneConstants)
    GLINT_SCENE_MATRIX(viewProjection);     // world -> clip (unjittered), row-major
    GLINT_SCENE_MATRIX(invViewProjection);  // clip -> world, computed in double
    GLINT_SCENE_MATRIX(prevViewProjection); // world -> previous clip
    float4 eye;          // xyz: camera position (world)
    uint2 size;          // W x H
    uint frameIndex;     // drives the per-frame random numbers
    uint seed;           // scene seed
    uint lightCount;
    uint samples;        // samples per pixel of this pass (references, noisy shadow = 1)
    uint shadowSamples;  // cone samples of the converged visibility used when shading
    uint shadowLight;    // light whose visibility the shadow passes write
    float backgroundDepth; // device depth of the far plane (1 standard, 0 reversed)
    uint ndcYDown;       // 1: Vulkan-style NDC (+y down)
    float environmentIntensity;
    uint passSalt;       // decorrelates the random numbers of different passes
    // References run in chunks of `samples` (llvmpipe stops an invocation after 65535 loop
    // iterations in all, which silently truncated references at high spp): this chunk covers
    // samples [sampleStart, sampleStart + samples) of sampleTotal and accumulates into the image.
    uint sampleStart;
    uint sampleTotal;
    // References accumulate over a run of frames whose camera, geometry and lights are all
    // unchanged: sampleBase samples per pixel came from the run's earlier frames (0 on its first
    // frame, which starts afresh), and sequenceFrame, the run's first frame, seeds the random
    // numbers that the run's samples share.
    uint sampleBase;
    uint sequenceFrame;
    uint environmentSampling; // 1: reflection references also sample the environment map (MIS)
    // A sphere shadow light's tan(angular radius) as the camera sees it, the frame's
    // glint.shadowLightTanHalfAngle: its blocker layer is scaled to it (scene_shadow.cs.hlsl).
    // 0 for a directional light, whose blocker distances stay as they are.
    float shadowLightTanReference;
    // Reflection references: every pixel's samples a frame (the later chunks of the frame, up
    // to sampleTotal, sample only pixels whose estimate's relative standard error is at or
    // above referenceNoiseTarget; 0: none do).
    uint referenceFrameSamples;
    float referenceNoiseTarget;
    // Only pixels whose GGX alpha is below this take the samples past referenceFrameSamples.
    float referenceNoiseAlphaBelow;
    uint constantsPadding0;
    uint constantsPadding1;
    uint constantsPadding2;
GLINT_CONSTANTS_END(GLINT_SceneConstants);

#ifdef __cplusplus
static_assert(sizeof(SceneBvhNode) == 32);
static_assert(sizeof(ScenePrimitive) == 48);
static_assert(sizeof(SceneMaterial) == 64);
static_assert(sizeof(SceneObject) == 48);
static_assert(sizeof(SceneLight) == 32);
static_assert(sizeof(SceneEnvironmentSample) == 16);
static_assert(offsetof(GLINT_SceneConstants, eye) == 192);
static_assert(offsetof(GLINT_SceneConstants, size) == 208);
static_assert(sizeof(GLINT_SceneConstants) == 304);
} // namespace glint::shaders
#endif

#endif // GLINT_SCENE_CONSTANTS_H
