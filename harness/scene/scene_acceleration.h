// The scene's triangles as Vulkan acceleration structures (VK_KHR_acceleration_structure), for
// ray tracing modules that trace with RayQuery (hlsl/entry/hybrid/hybrid_trace_rayquery.cs.hlsl):
// one bottom-level structure holding every triangle in the order the BVH stores them, so that
// a hit's primitive index is the index into "scene_primitives" the BVH tracer reports, and one
// top-level structure with a single instance of it (identity transform, custom index
// kSceneInstanceCustomIndex, mask 0xFF, culling off, opaque). docs/hybrid.md, "Acceleration
// structures".
#pragma once

#include "scene_constants.h"

#include <gpu/gpu_context.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace glint::scene {

// The custom index of the top-level structure's one instance: what RayQuery's
// CommittedInstanceID() returns and the BVH tracer writes as a hit's instance.
inline constexpr std::uint32_t kSceneInstanceCustomIndex = 0;

// The first sphere among `primitives` (they cannot be triangles of the structure), or -1.
std::ptrdiff_t firstSphere(std::span<const shaders::ScenePrimitive> primitives);

class SceneAccelerationStructure {
  public:
    // The context's device must have ray queries enabled (vk::Device::rayQuery).
    explicit SceneAccelerationStructure(const gpu::Context& context);
    ~SceneAccelerationStructure();
    SceneAccelerationStructure(const SceneAccelerationStructure&) = delete;
    SceneAccelerationStructure& operator=(const SceneAccelerationStructure&) = delete;

    // Builds both levels over `primitives` (unless they are the ones already built) and waits,
    // leaving the top level visible to compute shaders. Throws SceneError naming the first
    // sphere: the structure holds triangles only.
    void build(std::span<const shaders::ScenePrimitive> primitives);
    VkAccelerationStructureKHR topLevel() const;

    struct Level; // a structure and the memory it lives in

  private:
    const gpu::Context& context_;
    std::vector<std::byte> built_; // the primitives of the current structures
    std::unique_ptr<Level> bottom_, top_;
};

} // namespace glint::scene
