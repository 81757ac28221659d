// The tests' adapter over the shadow denoiser plan (glint_shadow_denoiser.h) on
// gpu::EffectRunner: uploads the application's inputs from CPU arrays, records one frame, reads
// the outputs back. The plan's own resources (histories, masks) persist across frames.
#pragma once

#include <gpu/gpu_context.h>
#include <gpu/gpu_effect_runner.h>

#include "glint/glint_shadow_denoiser.h"
#include "glint/vulkan/vk_resources.h"

#include <cstdint>
#include <vector>

namespace glint::gpu {

struct ShadowInputs {
    std::vector<float> visibility;    // W x H
    std::vector<float> depth;         // W x H device depth
    std::vector<float> previousDepth; // W x H
    std::vector<float> normals;       // RGBA per pixel
    std::vector<float> motion;        // RG per pixel
    std::vector<float> meanVariance;  // RG per pixel (the filter's input without classification)
    // W x H: distance to the visibility sample's blocker (0 lit, < 0 unknown); read by the
    // filter when the plan's penumbra estimate is on (shadowPenumbraActive).
    std::vector<float> blockerDistance;
};

struct ShadowOutputs {
    std::vector<std::uint32_t> mask;
    std::vector<std::uint32_t> metadata; // with classification
    std::vector<float> classified;       // RG of scratch 0 after classification (no filter)
    std::vector<float> moments;          // RGBA written this frame
    // "shadow_output" (with the filter) as RG (shadow, variance) whatever its format: R8Unorm and
    // R16Float carry no variance, so .y is 0 for them.
    std::vector<float> filtered;
    std::uint32_t filteredTiles = 0; // "shadow_filter_work" when tiles are skipped
};

class ShadowRunner {
  public:
    // Throws std::invalid_argument with the planner's message when `desc` is not valid.
    // compactInputs: the application's images in the formats an engine would bind (R8 visibility,
    // 16-bit float normals and motion) instead of 32-bit floats; for benchmarks.
    ShadowRunner(const Context& context, const ShadowDenoiserDesc& desc, bool compactInputs = false);
    ~ShadowRunner();
    ShadowRunner(const ShadowRunner&) = delete;
    ShadowRunner& operator=(const ShadowRunner&) = delete;

    // Plans `desc` (same size and flags as the constructor's), uploads the non-empty inputs,
    // runs, reads back (only filteredTiles without `readback`). With `timings`, the pass names
    // and GPU milliseconds of this frame.
    ShadowOutputs run(const ShadowDenoiserDesc& desc, const ShadowInputs& inputs, FrameRun* timings = nullptr,
                      bool readback = true);
    // Overwrites the moments history (read this frame with frameIndex) and scratch 1.
    void setHistory(std::uint32_t frameIndex, const std::vector<float>& moments,
                    const std::vector<float>& shadow);

  private:
    const Context& context_;
    EffectRunner runner_;
    std::vector<vk::Image> inputs_;
};

} // namespace glint::gpu
