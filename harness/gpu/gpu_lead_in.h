// Benchmarks: unrelated GPU work recorded ahead of every timed run, in the same command buffer.
// A run timed on an idle GPU is not the run a frame sees: the clock drops between short
// submissions (medians 2-3x the minima on an H100 at 1080p), the first dispatch of a command
// buffer carries the start-up of the submission (about 4.5 us), and L2 still holds what the
// previous identical run left there. Buffer fills over a large buffer cure all three: the GPU
// is busy for about half a millisecond right before the effect, and the effect starts on a cold
// L2, as it would after a frame's other passes.
#pragma once

#include <gpu/gpu_context.h>

#include "vulkan/vk_resources.h"

namespace glint::gpu {

class BusyLeadIn {
  public:
    // Installs itself as context.timedLeadIn until destroyed. `bytes` is filled `fills` times.
    explicit BusyLeadIn(const Context& context, VkDeviceSize bytes = VkDeviceSize{256} << 20,
                        uint32_t fills = 4);
    ~BusyLeadIn();
    BusyLeadIn(const BusyLeadIn&) = delete;
    BusyLeadIn& operator=(const BusyLeadIn&) = delete;

  private:
    const Context& context_;
    vk::Buffer buffer_;
};

// Records context.timedLeadIn, if any, then a barrier that keeps it out of what follows.
void recordTimedLeadIn(const Context& context, VkCommandBuffer cmd);

} // namespace glint::gpu
