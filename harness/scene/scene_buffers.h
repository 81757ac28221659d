// A scene's GPU data for shaders that trace and shade it outside the simulator's own passes
// (the hybrid effect's ray tracing and shading modules): the BVH of one frame's geometry, the
// materials, that frame's lights and the constants the shading reads, as storage buffers named
// "scene_constants", "scene_nodes", "scene_primitives", "scene_materials", "scene_lights", and
// optionally the same triangles as an acceleration structure, "scene_acceleration_structure"
// (scene_acceleration.h), for modules that trace with RayQuery.
#pragma once

#include "scene/scene_acceleration.h"
#include "scene/scene_bvh.h"
#include "scene/scene_geometry.h"
#include "scene/scene_types.h"

#include <gpu/gpu_context.h>

#include "glint/vulkan/vk_executor.h"

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

namespace glint::scene {

// The GPU layout of the scene's materials and of lights (never empty: a zero-sized storage
// buffer cannot be bound).
std::vector<shaders::SceneMaterial> packMaterials(const Scene& scene);
std::vector<shaders::SceneLight> packLights(const std::vector<LightDesc>& lights);

class SceneBuffers {
  public:
    // Loads the scene's meshes (SceneError naming the file) and uploads frame 0; with
    // `accelerationStructure` also builds it (the device must have ray queries; SceneError when
    // the scene has a sphere).
    SceneBuffers(const gpu::Context& context, Scene scene, bool accelerationStructure = false);
    ~SceneBuffers();
    SceneBuffers(const SceneBuffers&) = delete;
    SceneBuffers& operator=(const SceneBuffers&) = delete;

    // The geometry, BVH and lights of scene frame `frame` (clamped to the scene's last frame).
    // The device must be idle for these buffers (the replay waits for each frame).
    void setFrame(std::uint32_t frame);
    void addTo(vk::ResourceTable& table) const;

  private:
    // A buffer and the bytes last uploaded to it.
    struct Stored {
        vk::Buffer buffer;
        std::vector<std::byte> bytes;
    };
    // Uploads `bytes` unless the buffer holds them already (recreated when the size changes).
    void refresh(Stored& stored, std::span<const std::byte> bytes);
    void release();
    const gpu::Context& context_;
    Scene scene_;
    std::vector<Mesh> meshes_;
    Stored constants_, nodes_, primitives_, lights_;
    vk::Buffer materials_;
    std::unique_ptr<SceneAccelerationStructure> acceleration_;
};

// The resource name of the scene's top-level acceleration structure.
inline constexpr const char* kSceneAccelerationStructure = "scene_acceleration_structure";

} // namespace glint::scene
