// One frame of the hybrid plan (glint_hybrid.h) on the test device from a synthetic SSSR view,
// with a chosen feedback history, everything the tests compare read back.
#pragma once

#include "glint/glint_hybrid.h"
#include "glint/vulkan/vk_executor.h"
#include "glint/vulkan/vk_resources.h"

#include "scene/scene_bvh.h"
#include "sssr/sssr_test_scene.h"
#include <gpu/gpu_input_images.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace glint::test {

// A scene for the harness's ray tracing and shading modules: its BVH over `primitives`, its
// materials and lights, and constants with `lightCount` lights, on the test device.
class HybridTestScene {
  public:
    HybridTestScene(std::vector<shaders::ScenePrimitive> primitives,
                    const std::vector<shaders::SceneMaterial>& materials,
                    const std::vector<shaders::SceneLight>& lights);
    ~HybridTestScene();
    HybridTestScene(const HybridTestScene&) = delete;
    HybridTestScene& operator=(const HybridTestScene&) = delete;
    const scene::Bvh& bvh() const { return bvh_; }
    void addTo(vk::ResourceTable& table) const;

  private:
    scene::Bvh bvh_;
    vk::Buffer constants_, nodes_, primitives_, materials_, lights_;
};

struct HybridFrame {
    std::vector<std::uint32_t> tileClass, feedback; // per tile: this frame's class and counter
    std::vector<std::uint32_t> counters, arguments; // all words
    std::vector<std::uint32_t> swList;              // counter 1 entries
    std::vector<std::uint32_t> hwList;              // counter 5 entries (counter 4 without hw_args)
    std::vector<std::uint32_t> tileList;            // counter 3 entries
    std::vector<float> radiance, confidence;        // RGBA, R
    std::vector<std::uint32_t> hits;                // 4 words per ray-traced ray (GLINT_HYBRID_PackHit)
    // The screen-space hits to re-shade (counter 7 entries, counter 6 without hw_args), in
    // append order (from the ray-traced list's end down), and their 4-word records.
    std::vector<std::uint32_t> reshadedList, reshadedHits;
};

// Uploads the view's non-empty inputs (and its environment) and names them as the plans do.
vk::ResourceTable uploadInputs(gpu::InputImages& inputs, const SssrTestView& view);

// Adds the scene's buffers for the ray tracing and shading passes to an input table.
using AddScene = std::function<void(vk::ResourceTable&)>;

// Runs frame desc.sssr.frameIndex with `history` as last frame's feedback counters, leaving out
// the passes named in `skipPasses`; `addScene` feeds the ray tracing and shading passes.
HybridFrame runHybridFrame(const HybridDesc& desc, const SssrTestView& view,
                           const std::vector<std::uint32_t>& history,
                           const std::vector<std::string>& skipPasses, const AddScene& addScene);
HybridFrame runHybridFrame(const HybridDesc& desc, const SssrTestView& view,
                           const std::vector<std::uint32_t>& history,
                           const std::vector<std::string>& skipPasses = {},
                           const HybridTestScene* sceneInputs = nullptr);

} // namespace glint::test
