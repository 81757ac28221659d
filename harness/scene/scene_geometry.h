// World-space geometry of a scene at one frame: every object instanced with its keyframed
// transform into triangles and spheres, plus each object's map to its previous-frame pose
// (for exact motion vectors), and the camera matrices of the frame and the frame before.
#pragma once

#include "scene/scene_types.h"
#include "scene_constants.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace glint::scene {

// Triangles of a model file in its own space (all nodes' transforms applied), loaded once per
// object and reused for every frame.
struct Mesh {
    std::vector<Vec3> positions; // 3 per triangle
};

// Loads every mesh object's file through assimp; throws SceneError naming the file.
std::vector<Mesh> loadMeshes(const Scene& scene);

struct FrameGeometry {
    std::vector<shaders::ScenePrimitive> primitives;
    std::vector<shaders::SceneObject> objects; // one per scene object
};

// The object's world matrix (column vectors) at a possibly fractional frame.
capture::Mat4 objectMatrix(const ObjectDesc& object, double frame);
FrameGeometry buildGeometry(const Scene& scene, const std::vector<Mesh>& meshes, std::uint32_t frame);

// The light at a possibly fractional frame: its keys interpolated (directions linearly, then
// renormalised; positions linearly) and clamped outside their range, like object keys.
LightDesc lightAt(const LightDesc& light, double frame);
// Every light of the scene at a frame, in the scene's order.
std::vector<LightDesc> lightsAt(const Scene& scene, std::uint32_t frame);

struct FrameCamera {
    capture::Camera camera; // view, projection, prevViewProjection, depth convention, near/far
    Vec3 eye{};
};
FrameCamera cameraAt(const Scene& scene, std::uint32_t frame);
// A look-at camera's eye and target at a possibly fractional frame: its keys interpolated
// linearly and clamped outside their range.
std::pair<Vec3, Vec3> cameraEyeTarget(const CameraDesc& camera, double frame);

} // namespace glint::scene
