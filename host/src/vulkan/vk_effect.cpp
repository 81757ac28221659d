// Any effect on Vulkan: owned resources at create, their initialization on the first dispatch.
#include "glint/vulkan/vk_effect.h"

#include <cstring>
#include <exception>
#include <set>
#include <string>
#include <vector>

namespace glint::vk {
namespace {

Result fail(std::string* error, const std::string& effect, const std::string& message) {
    if (error) *error = effect + ": " + message;
    return Result::InvalidArgument;
}

bool sameImage(const ImageDesc& a, const ImageDesc& b) {
    return a.name == b.name && a.width == b.width && a.height == b.height && a.mipLevels == b.mipLevels &&
           a.format == b.format;
}

bool sameBuffer(const BufferDesc& a, const BufferDesc& b) {
    return a.name == b.name && a.size == b.size && a.indirectArgs == b.indirectArgs;
}

// Empty when `plan` declares exactly the resources `effect` was created with.
std::string resourceChange(const EffectInstance& effect, const EffectPlan& plan) {
    if (plan.images.size() != effect.imageDescs.size() || plan.buffers.size() != effect.bufferDescs.size())
        return "the plan's resources differ from the ones created (a setting that changes resources needs a "
               "new instance)";
    for (std::size_t i = 0; i < plan.images.size(); ++i)
        if (!sameImage(plan.images[i], effect.imageDescs[i]))
            return "image '" + plan.images[i].name + "' differs from the one created";
    for (std::size_t i = 0; i < plan.buffers.size(); ++i)
        if (!sameBuffer(plan.buffers[i], effect.bufferDescs[i]))
            return "buffer '" + plan.buffers[i].name + "' differs from the one created";
    return {};
}

void recordInitialization(EffectInstance& effect, VkCommandBuffer cmd) {
    std::vector<VkImageMemoryBarrier> toGeneral;
    for (auto& [name, image] : effect.images) {
        VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
        barrier.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        barrier.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        barrier.newLayout = VK_IMAGE_LAYOUT_GENERAL;
        barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        barrier.image = image.image;
        barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, image.mipLevels, 0, 1};
        toGeneral.push_back(barrier);
    }
    if (!toGeneral.empty())
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0,
                             nullptr, 0, nullptr, static_cast<uint32_t>(toGeneral.size()), toGeneral.data());
    const VkClearColorValue zero{};
    for (auto& [name, image] : effect.images) {
        const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, image.mipLevels, 0, 1};
        vkCmdClearColorImage(cmd, image.image, VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &range);
    }
    for (auto& [name, buffer] : effect.buffers) vkCmdFillBuffer(cmd, buffer.buffer, 0, VK_WHOLE_SIZE, 0);
    VkMemoryBarrier cleared{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    cleared.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    cleared.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &cleared,
                         0, nullptr, 0, nullptr);
    VkDeviceSize offset = 0;
    for (const ImageDesc& desc : effect.imageDescs) {
        if (!desc.initialTexels) continue;
        const Image& image = effect.images.at(desc.name);
        VkBufferImageCopy copy{};
        copy.bufferOffset = offset;
        copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        copy.imageExtent = {image.width, image.height, 1};
        vkCmdCopyBufferToImage(cmd, effect.staging.buffer, image.image, VK_IMAGE_LAYOUT_GENERAL, 1, &copy);
        offset += desc.initialTexels->size() * sizeof(float);
    }
    // The executor's first barrier per resource waits for "all commands" writes.
    VkMemoryBarrier done{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    done.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    done.dstAccessMask =
        VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_INDIRECT_COMMAND_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT, 0, 1,
                         &done, 0, nullptr, 0, nullptr);
}

} // namespace

Result createEffect(const Device& device, const EffectPlan& plan, EffectInstance& effect,
                    std::string* error) {
    effect = EffectInstance{};
    effect.device = &device;
    effect.effect = plan.effect;
    effect.imageDescs = plan.images;
    effect.bufferDescs = plan.buffers;
    try {
        VkDeviceSize stagedBytes = 0;
        for (const ImageDesc& image : plan.images) {
            const VkFormat format = toVkFormat(image.format);
            if (effect.images.contains(image.name)) {
                destroyEffect(effect);
                return fail(error, plan.effect, "image '" + image.name + "' is declared twice");
            }
            effect.images[image.name] =
                createImage2D(device, image.width, image.height, format, image.mipLevels);
            if (!image.initialTexels) continue;
            const VkDeviceSize bytes = image.initialTexels->size() * sizeof(float);
            if (bytes != VkDeviceSize{image.width} * image.height * formatTexelSize(format)) {
                destroyEffect(effect);
                return fail(error, plan.effect, "initial texels of '" + image.name + "' do not fill level 0");
            }
            stagedBytes += bytes;
        }
        for (const BufferDesc& buffer : plan.buffers) {
            // Bound whole as storage buffers: a larger one is beyond what a descriptor may cover.
            const VkDeviceSize limit = device.properties.limits.maxStorageBufferRange;
            if (buffer.size > limit) {
                destroyEffect(effect);
                fail(error, plan.effect,
                     "buffer '" + buffer.name + "' needs " + std::to_string(buffer.size) +
                         " bytes, more than this device's maxStorageBufferRange (" + std::to_string(limit) +
                         "); use a smaller resolution");
                return Result::Unsupported;
            }
            VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
            if (buffer.indirectArgs) usage |= VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT;
            effect.buffers[buffer.name] = createBuffer(device, buffer.size, usage, MemoryUse::DeviceLocal);
        }
        if (stagedBytes > 0) {
            effect.staging =
                createBuffer(device, stagedBytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::Upload);
            VkDeviceSize offset = 0;
            for (const ImageDesc& image : plan.images) {
                if (!image.initialTexels) continue;
                const std::size_t bytes = image.initialTexels->size() * sizeof(float);
                std::memcpy(static_cast<char*>(effect.staging.mapped) + offset, image.initialTexels->data(),
                            bytes);
                offset += bytes;
            }
            flushBuffer(device, effect.staging);
        }
    } catch (const std::exception& exception) {
        destroyEffect(effect);
        return fail(error, plan.effect, exception.what());
    }
    return Result::Ok;
}

Result dispatchEffect(EffectInstance& effect, Executor& executor, VkCommandBuffer cmd, const EffectPlan& plan,
                      const ResourceTable& inputs, const PassHooks& hooks, std::string* error) {
    if (!effect.device) return fail(error, plan.effect, "the effect was not created");
    if (const std::string change = resourceChange(effect, plan); !change.empty())
        return fail(error, plan.effect, change);
    ResourceTable table = inputs;
    for (const auto& [name, image] : effect.images) table.images[name] = &image;
    for (const auto& [name, buffer] : effect.buffers) table.buffers[name] = &buffer;
    for (const Pass& pass : plan.passes)
        for (const ResourceUse& use : pass.uses)
            if (!table.images.contains(use.resource) && !table.buffers.contains(use.resource) &&
                !table.accelerationStructures.contains(use.resource))
                return fail(error, plan.effect, "input '" + use.resource + "' is missing");
    initializeEffect(effect, cmd);
    try {
        recordPlan(executor, cmd, plan, table, hooks);
    } catch (const std::exception& exception) {
        if (error) *error = exception.what();
        return Result::Unsupported;
    }
    return Result::Ok;
}

void initializeEffect(EffectInstance& effect, VkCommandBuffer cmd) {
    if (!effect.device || effect.initialized) return;
    recordInitialization(effect, cmd);
    effect.initialized = true;
}

void destroyEffect(EffectInstance& effect) {
    if (!effect.device) return;
    for (auto& [name, image] : effect.images) destroyImage(*effect.device, image);
    for (auto& [name, buffer] : effect.buffers) destroyBuffer(*effect.device, buffer);
    destroyBuffer(*effect.device, effect.staging);
    effect = EffectInstance{};
}

} // namespace glint::vk
