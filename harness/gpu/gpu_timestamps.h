// GPU timestamps for benchmarks: a query pool written from command buffers and read after the
// submission finished. Only meaningful within one command buffer/queue; compare pairs.
#pragma once

#include "glint/vulkan/vk_device.h"

#include <cstdint>
#include <vector>

namespace glint::gpu {

struct TimestampPool {
    VkQueryPool pool = VK_NULL_HANDLE;
    uint32_t capacity = 0;
    uint32_t used = 0;      // queries written since the last resetTimestamps
    double periodNs = 0.0;  // VkPhysicalDeviceLimits::timestampPeriod
    uint32_t validBits = 0; // of the queue family; higher bits are garbage
};

// Throws std::runtime_error if the device's queue cannot write timestamps
// (vk::Device::timestamps is false).
TimestampPool createTimestampPool(const vk::Device& device, uint32_t capacity);
void destroyTimestampPool(const vk::Device& device, TimestampPool& pool);

// Records a reset of every query (vkCmdResetQueryPool) and starts counting from 0 again.
// Must precede the writes, outside any render pass.
void resetTimestamps(VkCommandBuffer cmd, TimestampPool& pool);
// Records a timestamp once all earlier commands reached `stage`; returns its query index.
// Throws std::out_of_range when the pool is full.
uint32_t writeTimestamp(VkCommandBuffer cmd, TimestampPool& pool, VkPipelineStageFlagBits stage);
// The `used` values (raw ticks, masked to validBits), waiting until they are available; call
// after the command buffer that wrote them was submitted.
std::vector<uint64_t> readTimestamps(const vk::Device& device, const TimestampPool& pool);

// Milliseconds from begin to end, in ticks masked to validBits so that a counter wrapping
// between the two still gives the right difference.
double timestampMilliseconds(const TimestampPool& pool, uint64_t begin, uint64_t end);

} // namespace glint::gpu
