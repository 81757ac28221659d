// Runs a harness-internal plan (the simulator's ray caster, a test's probe shaders) on the
// harness context: creates the resources the plan describes (images filled with NaN by default,
// so a texel no pass writes cannot pass for a result), executes it with a GPU timestamp around
// every dispatch, and hands back per-pass times. glint's effects do not come this way: they go
// through gpu::EffectRunner (gpu_effect_runner.h) and glint::vk::createEffect.
#pragma once

#include <gpu/gpu_context.h>

#include "glint/glint_pass.h"
#include "glint/vulkan/vk_executor.h"

#include <map>
#include <string>
#include <vector>

namespace glint::gpu {

// The images and buffers a plan defines (plan.images, plan.buffers), owned here.
struct PlanResources {
    std::map<std::string, vk::Image> images;
    std::map<std::string, vk::Buffer> buffers;
};

// Images are cleared to `imageFill` (NaN by default, so a texel a pass forgets to write
// cannot pass for a result) and left in GENERAL; buffers are zeroed.
PlanResources createPlanResources(const Context& context, const EffectPlan& plan, float imageFill = -1.0f);
void destroyPlanResources(const Context& context, PlanResources& resources);

// A table holding the plan's own resources plus the application's inputs and outputs.
vk::ResourceTable resourceTable(const PlanResources& owned,
                                const std::map<std::string, const vk::Image*>& external = {});

// GPU milliseconds of each pass in each run: times[run][pass]. Runs are separate
// submissions so that no run overlaps another; empty when the queue has no timestamps.
struct PlanTimings {
    std::vector<std::string> passes;
    std::vector<std::vector<double>> times;
};

PlanTimings executePlan(const Context& context, vk::Executor& executor, const EffectPlan& plan,
                        const vk::ResourceTable& resources, uint32_t runs = 1);

// Median of the per-run values of one pass.
double medianMilliseconds(const PlanTimings& timings, std::size_t pass);

} // namespace glint::gpu
