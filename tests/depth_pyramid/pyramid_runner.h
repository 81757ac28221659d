// Runs the depth pyramid plan on the test context, the way an application would: the input
// depth image plus every resource the plan lists, created from the plan's own descriptions.
// One runner can build many times (the race test); every level is read back after each build.
#pragma once

#include "reference/depth_pyramid_reference.h"

#include "glint/glint_depth_pyramid.h"
#include "glint/vulkan/vk_executor.h"

#include <gpu/gpu_context.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace glint::test {

class PyramidRunner {
  public:
    PyramidRunner(gpu::Context& context, const DepthPyramidDesc& desc);
    ~PyramidRunner();
    PyramidRunner(const PyramidRunner&) = delete;
    PyramidRunner& operator=(const PyramidRunner&) = delete;

    // Uploads `depth` (W x H floats, row-major), fills every level of the pyramid with NaN so
    // that a texel the pass forgets cannot pass a check, optionally writes `counterBefore`
    // into the completion counter (a stale count left by an aborted frame), records the plan,
    // waits, and reads back every level.
    reference::Pyramid build(const std::vector<float>& depth,
                             std::optional<std::uint32_t> counterBefore = {});

    bool hasCounter() const { return counter_.buffer != VK_NULL_HANDLE; }
    std::uint32_t readCounter() const; // requires hasCounter()
    const EffectPlan& plan() const { return plan_; }

  private:
    gpu::Context& context_;
    DepthPyramidDesc desc_;
    EffectPlan plan_;
    vk::Executor executor_;
    vk::Image depth_;
    vk::Image pyramid_;
    vk::Buffer counter_;
};

// Checks a pyramid read back from the device: bit for bit against the CPU reference for the
// same desc and input, and against the contract with the independent property checker.
// Both reports go into the assertion message.
void checkPyramid(const std::vector<float>& depth, const DepthPyramidDesc& desc,
                  const reference::Pyramid& actual);

// "1920x1080 reversed closest+farthest levels 0", for INFO.
std::string describe(const DepthPyramidDesc& desc);

} // namespace glint::test
