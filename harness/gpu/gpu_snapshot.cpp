#include "gpu/gpu_snapshot.h"

#include <gpu/gpu_transfer.h>

namespace glint::gpu {

Snapshot::Snapshot(const Context& c, std::uint32_t width, std::uint32_t height, VkFormat format)
    : context(c) {
    image = vk::createImage2D(context.device, width, height, format);
    clearImage(context, image, VkClearColorValue{});
}

Snapshot::~Snapshot() {
    vk::destroyImage(context.device, image);
}

void Snapshot::record(VkCommandBuffer cmd, const vk::Image& source) const {
    VkMemoryBarrier before{VK_STRUCTURE_TYPE_MEMORY_BARRIER, nullptr, VK_ACCESS_SHADER_WRITE_BIT,
                           VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1,
                         &before, 0, nullptr, 0, nullptr);
    VkImageCopy region{};
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.dstSubresource = region.srcSubresource;
    region.extent = {image.width, image.height, 1};
    vkCmdCopyImage(cmd, source.image, VK_IMAGE_LAYOUT_GENERAL, image.image, VK_IMAGE_LAYOUT_GENERAL, 1,
                   &region);
    VkMemoryBarrier after{VK_STRUCTURE_TYPE_MEMORY_BARRIER, nullptr,
                          VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT,
                          VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1,
                         &after, 0, nullptr, 0, nullptr);
}

} // namespace glint::gpu
