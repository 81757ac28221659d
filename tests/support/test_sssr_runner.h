// The tests' adapter over the reflections effect (glint_reflections.h) on gpu::EffectRunner:
// uploads the application's inputs from CPU arrays (the environment with a box-filtered mip
// chain), records one frame of SSSR (and the reflections denoiser when asked), reads the
// owned resources back as the SSSR tests expect them.
#pragma once

#include <gpu/gpu_context.h>
#include <gpu/gpu_effect_runner.h>
#include <gpu/gpu_input_images.h>

#include "glint/glint_reflections.h"
#include "glint/glint_reflections_denoiser.h"
#include "glint/glint_sssr.h"
#include "glint/vulkan/vk_executor.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace glint::gpu {

struct SssrFrameInputs {
    std::vector<float> depth;             // W x H device depth
    std::vector<float> normals;           // RGBA
    std::vector<float> material;          // RGBA (roughness in desc.materialChannel)
    std::vector<float> color;             // RGBA lit colour
    std::vector<float> motion;            // RG
    std::vector<float> baseColorMetallic; // RGBA, composite only
    std::uint32_t environmentWidth = 0, environmentHeight = 0;
    std::vector<float> environment; // RGBA lat-long, level 0
};

struct SssrFrameOutputs {
    std::uint32_t width = 0, height = 0;
    std::vector<float> radiance;         // RGBA: rgb, hit distance
    std::vector<float> confidence;       // R
    std::vector<float> roughness;        // R, GGX alpha
    std::vector<float> rayInfo;          // RGBA, debugOutput only
    std::vector<float> rays;             // RGBA: direction, pdf; storeRays only
    std::vector<float> composite;        // RGBA, composite only
    std::vector<float> blueNoise;        // RG 128 x 128
    std::vector<std::uint32_t> rayList;  // counters[1] entries
    std::vector<std::uint32_t> tileList; // counters[3] entries
    std::uint32_t counters[4] = {};
    std::uint32_t arguments[6] = {};
};

class SssrRunner {
  public:
    // compactInputs: the application's images in the formats an engine would use (RGBA16F
    // normals and colour, R16F roughness from material channel 0, RG16F motion) instead of
    // 32-bit floats; for benchmarks. The tests keep 32 bits so that their references see
    // exactly the values the GPU reads. Throws std::runtime_error with the planner's message.
    SssrRunner(const Context& context, const SssrDesc& desc, bool compactInputs = false);
    ~SssrRunner();
    SssrRunner(const SssrRunner&) = delete;
    SssrRunner& operator=(const SssrRunner&) = delete;

    // Uploads the inputs that are non-empty (the environment's mips included) and keeps them.
    void upload(const SssrFrameInputs& inputs);
    // Records and submits one frame; with `timings`, per-pass GPU times (ms) in plan order.
    // With `denoiser` (the runner's desc has denoise), the reflections denoiser runs too and
    // readback().radiance is its output. `extraHooks` are recorded around every dispatch, outside
    // the timed span, e.g. for a test to copy an intermediate that a later pass overwrites.
    void run(const SssrDesc& frame, std::vector<double>* timings = nullptr,
             const ReflectionsDenoiserDesc* denoiser = nullptr, const vk::PassHooks* extraHooks = nullptr);
    SssrFrameOutputs readback() const;
    // The four counters alone (rays, tiles...), cheap enough to read between timed frames.
    std::array<std::uint32_t, 4> counters() const;
    // The first `count` words of a plan buffer (e.g. "sssr_ray_scratch").
    std::vector<std::uint32_t> bufferWords(const std::string& buffer, std::size_t count) const;
    // With `denoised`, the denoiser's passes for `spatialPath` follow the intersection.
    std::vector<std::string> passNames(const SssrDesc& frame, bool denoised = false,
                                       SpatialPath spatialPath = SpatialPath::Prefilter) const;
    // An owned image by name (e.g. "rd_radiance0"), for tests that poison histories.
    const vk::Image& ownedImage(const std::string& name) const;

  private:
    // `frame` with the runner's composite reflection (fixed at create).
    SssrDesc frameDesc(const SssrDesc& frame) const;

    const Context& context_;
    SssrDesc desc_;
    EffectRunner runner_;
    InputImages inputs_;
};

} // namespace glint::gpu
