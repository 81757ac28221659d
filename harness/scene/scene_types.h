// The scene description the simulator renders (docs/scenes.md): plain data, filled by
// loadScene (scene_file.h) or directly by tests. Positions in world units, angles in degrees
// (as written in scene files), colours linear.
#pragma once

#include "capture/capture_frame.h"

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace glint::scene {

using Vec3 = std::array<float, 3>;

// Keyframed values are linearly interpolated by frame number; outside the keyframes the
// first or last value holds (so frame 0's "previous frame" at -1 is the first keyframe).
struct CameraKey {
    float frame = 0.0f;
    Vec3 position{0.0f, 1.0f, 5.0f};
    Vec3 target{0.0f, 0.0f, 0.0f};
};

struct CameraDesc {
    std::vector<CameraKey> keys{CameraKey{}}; // at least one
    Vec3 up{0.0f, 1.0f, 0.0f};
    double fovYDegrees = 50.0;
    double nearZ = 0.1;
    double farZ = 100.0; // ignored (infinite) for ReversedInfinite
    capture::DepthConvention depth = capture::DepthConvention::Standard;
    bool ndcYDown = false;
    // Explicit matrices (column-vector convention) replace look-at / perspective when set.
    std::optional<capture::Mat4> view;
    std::optional<capture::Mat4> projection;
};

enum class EnvironmentKind { Sky, Map };

struct EnvironmentDesc {
    EnvironmentKind kind = EnvironmentKind::Sky;
    std::filesystem::path file; // lat-long EXR for Map
    float intensity = 1.0f;
    Vec3 zenith{0.25f, 0.45f, 0.9f};
    Vec3 horizon{0.85f, 0.85f, 0.85f};
    Vec3 ground{0.3f, 0.28f, 0.25f};
    bool sunDisc = true; // draw each directional light's disc into the sky
    std::uint32_t width = 256, height = 128;
};

enum class LightKind { Directional, Sphere };

// A light's pose at one frame; the direction is interpolated linearly and renormalised.
struct LightKey {
    float frame = 0.0f;
    Vec3 direction{0.3f, 1.0f, 0.2f}; // unit
    Vec3 position{0.0f, 3.0f, 0.0f};
};

struct LightDesc {
    LightKind kind = LightKind::Directional;
    Vec3 direction{0.3f, 1.0f, 0.2f}; // directional: toward the light (normalized on load)
    Vec3 position{0.0f, 3.0f, 0.0f};  // sphere
    Vec3 color{1.0f, 1.0f, 1.0f};
    float intensity = 3.0f;             // directional: irradiance; sphere: irradiance at 1 unit
    float angularRadiusDegrees = 0.27f; // directional
    float radius = 0.1f;                // sphere
    // Empty: the light holds `direction` and `position` on every frame. Otherwise these keys
    // replace them (lightAt in scene_geometry.h), in increasing frame order.
    std::vector<LightKey> keys;
};

struct MaterialDesc {
    std::string name;
    Vec3 baseColor{0.8f, 0.8f, 0.8f};
    float metallic = 0.0f;
    float roughness = 0.5f; // perceptual
    Vec3 emissive{0.0f, 0.0f, 0.0f};
    // Optional linear roughness ramp between two world points.
    bool ramp = false;
    Vec3 rampStart{}, rampEnd{};
    float rampRoughnessEnd = 1.0f;
};

enum class ShapeKind { Plane, Box, Sphere, Mesh };

struct ObjectKey {
    float frame = 0.0f;
    Vec3 position{0.0f, 0.0f, 0.0f};
    Vec3 rotationDegrees{0.0f, 0.0f, 0.0f}; // applied X, then Y, then Z
    Vec3 scale{1.0f, 1.0f, 1.0f};
};

struct ObjectDesc {
    std::string name;
    ShapeKind shape = ShapeKind::Box;
    std::uint32_t material = 0;
    Vec3 size{1.0f, 1.0f, 1.0f}; // plane: x and z extent (normal +y); box: edge lengths
    float radius = 0.5f;         // sphere
    std::filesystem::path file;  // mesh (glTF 2.0 or anything assimp reads)
    float fitSize = 0.0f;        // mesh: > 0 scales the model so its largest extent is this
    // mesh: -1 every triangle of the file; k >= 0 only the triangles the file gives its
    // material k (assimp's material order), as loadGeometryScene makes one object per material.
    std::int32_t fileMaterial = -1;
    std::vector<ObjectKey> keys{ObjectKey{}};
};

enum class Effect { Reflections, Shadows, Hybrid };

struct ReferenceDesc {
    bool reflections = false;
    bool shadows = false;
    std::uint32_t samplesPerPixel = 64;
    // Reflection references pair each GGX sample with a sample of the environment map's
    // brightness, combined by multiple importance sampling (docs/scenes.md).
    bool environmentSampling = true;
    // Frames whose camera, geometry and lights are all those of the previous frame continue its
    // references: a frame's reference is the mean of every sample since the last change.
    bool accumulate = true;
    // Reflection references: past samplesPerPixel, a frame samples the pixels whose estimate's
    // relative standard error (over max(luminance, 0.05)) is still at or above noiseTarget, up
    // to maxSamplesPerPixel samples in the frame (0: samplesPerPixel). noiseTarget 0: none.
    float noiseTarget = 0.0f;
    std::uint32_t maxSamplesPerPixel = 0;
    // Only pixels whose GGX alpha is below this take samples past samplesPerPixel (the scored
    // reflections cover alpha below roughnessThreshold); 1: every pixel.
    float noiseTargetAlphaBelow = 1.0f;
};

// The most samples a pixel's reflection reference takes in a frame.
inline std::uint32_t maxReferenceSamples(const ReferenceDesc& reference) {
    return reference.noiseTarget > 0.0f ? std::max(reference.maxSamplesPerPixel, reference.samplesPerPixel)
                                        : reference.samplesPerPixel;
}

struct Scene {
    std::filesystem::path file; // where it was loaded from (for messages), may be empty
    std::uint32_t width = 160, height = 90;
    std::uint32_t frameCount = 1;
    double frameRate = 30.0;
    std::uint32_t seed = 1;
    std::uint32_t shadowSamples = 16; // converged visibility when shading colour
    std::uint32_t shadowLight = 0;    // the light the shadow layers describe
    CameraDesc camera;
    EnvironmentDesc environment;
    std::vector<LightDesc> lights;
    std::vector<MaterialDesc> materials;
    std::vector<ObjectDesc> objects;
    std::vector<Effect> effects;
    ReferenceDesc reference;
};

bool hasEffect(const Scene& scene, Effect effect);
// Reflection layers are needed by both reflections and hybrid reflections.
bool needsReflections(const Scene& scene);
bool needsShadows(const Scene& scene);
// The effect a scene file's `effects` spells `name` ("reflections", "shadows", "hybrid");
// std::invalid_argument for another name.
Effect effectNamed(std::string_view name);
// Asks for the reference a capture holds as the layer "reference.<layer>" ("reflection",
// "shadow"); std::invalid_argument for a layer no scene renders.
void requestReference(ReferenceDesc& reference, std::string_view layer);

} // namespace glint::scene
