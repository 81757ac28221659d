// Runs any effect's plan on the harness context (glint/vulkan/vk_effect.h underneath): records
// one frame with a GPU timestamp around every dispatch, copies the outputs that a later pass
// overwrites right after the pass that produced them, and reads outputs and counters back,
// decoded as the plan says. The one road by which replay, benchmarks and tests reach every
// effect.
#pragma once

#include <gpu/gpu_context.h>
#include <gpu/gpu_timestamps.h>

#include "glint/glint_pass.h"
#include "glint/vulkan/vk_effect.h"

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

namespace glint::gpu {

struct DecodedOutput {
    std::string name; // "denoised", "mip3"
    std::string pass; // the pass that wrote it
    std::uint32_t width = 0, height = 0, channels = 0;
    std::vector<float> pixels;
    bool intermediate = false;
};

struct FrameRun {
    std::vector<std::string> passes;
    std::vector<double> milliseconds; // per pass; empty when the queue has no timestamps
};

class EffectRunner {
  public:
    // Creates the resources `plan` owns; throws std::runtime_error with the planner's or the
    // backend's one-line message.
    // `applicationShaders` finds the modules the application provides (the hybrid effect's
    // ray tracing and shading passes: the harness's scene::findShader), tried before glint's own.
    EffectRunner(const Context& context, const EffectPlan& plan, vk::ShaderLookup applicationShaders = {});
    ~EffectRunner();
    EffectRunner(const EffectRunner&) = delete;
    EffectRunner& operator=(const EffectRunner&) = delete;

    // Initializes the owned resources now (zeroed, tables copied in) instead of in the first
    // run, so that a caller may upload into one (a history) before the first frame. Nothing
    // once initialized.
    void initialize();

    // Records and submits one frame. `inputs` holds the application's images by the plan's
    // names. With `snapshots`, outputs whose resource a later pass overwrites are copied after
    // their own pass (needed to read them back). `extraHooks` run around every dispatch,
    // outside the timed span.
    FrameRun run(const EffectPlan& plan, const vk::ResourceTable& inputs, bool snapshots = false,
                 const vk::PassHooks* extraHooks = nullptr);

    // Frames recorded by the caller into its own command buffers (sustained benchmarks, which
    // submit several frames at once): beginFrames releases the descriptor sets and constants
    // of earlier frames, none of which may still be pending; then each record() adds one
    // frame, with a timestamp pair around every dispatch in `timestamps` (when not null).
    // Throws std::runtime_error with the backend's message.
    void beginFrames();
    void record(VkCommandBuffer cmd, const EffectPlan& plan, const vk::ResourceTable& inputs,
                TimestampPool* timestamps, const vk::PassHooks* extraHooks = nullptr);

    // The plan's outputs after the last run (intermediates only with `intermediates`), those
    // `wanted` accepts by name ("denoised", "mip3") when it is set.
    std::vector<DecodedOutput> readOutputs(const EffectPlan& plan, bool intermediates,
                                           const std::function<bool(const std::string&)>& wanted = {}) const;
    // The plan's counters: (name, value) pairs, fractions included.
    std::vector<std::pair<std::string, double>> readCounters(const EffectPlan& plan) const;

    const vk::Image& image(const std::string& name) const;
    const vk::Buffer& buffer(const std::string& name) const;
    bool hasImage(const std::string& name) const { return effect_.images.contains(name); }
    bool hasBuffer(const std::string& name) const { return effect_.buffers.contains(name); }
    std::vector<std::uint32_t> readWords(const std::string& buffer, std::size_t count = SIZE_MAX) const;

  private:
    const vk::Image& outputImage(const OutputDesc& output) const;
    // Copies to take after their pass: (pass index, source, snapshot).
    using SnapshotCopies = std::vector<std::tuple<std::size_t, const vk::Image*, const vk::Image*>>;
    // The snapshots `plan` needs, created or resized.
    SnapshotCopies prepareSnapshots(const EffectPlan& plan);
    // record() without the throw: the backend's message, empty when the frame was recorded.
    std::string recordFrame(VkCommandBuffer cmd, const EffectPlan& plan, const vk::ResourceTable& inputs,
                            TimestampPool* timestamps, const vk::PassHooks* extraHooks,
                            const SnapshotCopies& copies);
    const Context& context_;
    vk::EffectInstance effect_;
    vk::Executor executor_;
    std::map<std::string, vk::Image> snapshots_; // by output name
    Extent2D size_;
};

// The plan's pass names in order.
std::vector<std::string> passNames(const EffectPlan& plan);

} // namespace glint::gpu
