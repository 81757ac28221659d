#include "gpu/gpu_lead_in.h"

namespace glint::gpu {

BusyLeadIn::BusyLeadIn(const Context& context, VkDeviceSize bytes, uint32_t fills) : context_(context) {
    buffer_ = vk::createBuffer(context.device, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                               vk::MemoryUse::DeviceLocal);
    const VkBuffer buffer = buffer_.buffer;
    context.timedLeadIn = [buffer, fills](VkCommandBuffer cmd) {
        for (uint32_t fill = 0; fill < fills; ++fill) {
            // Each fill waits for the last: they are back to back, never concurrent.
            if (fill > 0) {
                VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
                barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
                barrier.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
                vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                                     1, &barrier, 0, nullptr, 0, nullptr);
            }
            vkCmdFillBuffer(cmd, buffer, 0, VK_WHOLE_SIZE, fill);
        }
    };
}

BusyLeadIn::~BusyLeadIn() {
    context_.timedLeadIn = nullptr;
    vk::destroyBuffer(context_.device, buffer_);
}

void recordTimedLeadIn(const Context& context, VkCommandBuffer cmd) {
    if (!context.timedLeadIn) return;
    context.timedLeadIn(cmd);
    // Nothing of the effect starts before the lead-in has finished.
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 1,
                         &barrier, 0, nullptr, 0, nullptr);
}

} // namespace glint::gpu
