// Runs the shadow denoiser plan on the test context with the application's inputs uploaded
// from CPU arrays; the plan's own resources persist across frames.
#pragma once

#include "glint/glint_shadow_denoiser.h"
#include "vulkan/vk_executor.h"

#include <gpu/gpu_plan_runner.h>

#include <cstdint>
#include <vector>

namespace glint::test {

struct ShadowInputs {
    std::vector<float> visibility;    // W x H
    std::vector<float> depth;         // W x H device depth
    std::vector<float> previousDepth; // W x H
    std::vector<float> normals;       // RGBA per pixel
    std::vector<float> motion;        // RG per pixel
    std::vector<float> meanVariance;  // RG per pixel (the filter's input without classification)
};

struct ShadowOutputs {
    std::vector<std::uint32_t> mask;
    std::vector<std::uint32_t> metadata; // with classification
    std::vector<float> classified;       // RG of scratch 0 after classification (no filter)
    std::vector<float> moments;          // RGBA written this frame
    std::vector<float> filtered;         // RG of "shadow_output" (with the filter)
    std::uint32_t filteredTiles = 0;     // "shadow_filter_work" when tiles are skipped
};

class ShadowRunner {
  public:
    explicit ShadowRunner(const ShadowDenoiserDesc& desc);
    ~ShadowRunner();
    ShadowRunner(const ShadowRunner&) = delete;
    ShadowRunner& operator=(const ShadowRunner&) = delete;

    // Plans `desc` (same size and flags as the constructor's), uploads, runs, reads back.
    ShadowOutputs run(const ShadowDenoiserDesc& desc, const ShadowInputs& inputs);
    // Overwrites the moments history (read this frame with frameIndex) and scratch 1.
    void setHistory(std::uint32_t frameIndex, const std::vector<float>& moments,
                    const std::vector<float>& shadow);

  private:
    std::vector<vk::Image> inputs_;
    gpu::PlanResources owned_;
    vk::Executor executor_;
};

ShadowOutputs runShadowDenoiser(const ShadowDenoiserDesc& desc, const ShadowInputs& inputs);

// Deterministic inputs: binary visibility with structure plus noise, a sloped depth with a
// step and a sky region, normals with a crease, noisy (mean, variance), zero motion.
ShadowInputs makeShadowInputs(std::uint32_t width, std::uint32_t height, std::uint32_t seed);

} // namespace glint::test
