#include "glint/vulkan/vk_executor.h"

#include "core/pass_model.h"
#include "core/shader_library.h"
#include "glint/vulkan/vk_check.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <mutex>
#include <stdexcept>
#include <vector>

namespace glint::vk {
namespace {

constexpr VkDeviceSize kConstantRingSize = 256 * 1024;
constexpr uint32_t kMaxSetsPerReset = 1024;

[[noreturn]] void fail(const Pass& pass, const std::string& problem) {
    throw std::runtime_error("pass '" + pass.name + "' (" + pass.pipeline + "): " + problem);
}

VkPipelineStageFlags stagesFor(uint32_t flags) {
    VkPipelineStageFlags stages = 0;
    if (flags & (core::kAccessShaderRead | core::kAccessShaderWrite))
        stages |= VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    if (flags & core::kAccessIndirectRead) stages |= VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT;
    if (flags & core::kAccessExternalWrite) stages |= VK_PIPELINE_STAGE_ALL_COMMANDS_BIT;
    if (flags & core::kAccessTransferWrite) stages |= VK_PIPELINE_STAGE_TRANSFER_BIT;
    return stages;
}

VkAccessFlags accessMaskFor(uint32_t flags) {
    VkAccessFlags mask = 0;
    if (flags & core::kAccessShaderRead) mask |= VK_ACCESS_SHADER_READ_BIT;
    if (flags & core::kAccessShaderWrite) mask |= VK_ACCESS_SHADER_WRITE_BIT;
    if (flags & core::kAccessIndirectRead) mask |= VK_ACCESS_INDIRECT_COMMAND_READ_BIT;
    if (flags & core::kAccessExternalWrite) mask |= VK_ACCESS_MEMORY_WRITE_BIT;
    if (flags & core::kAccessTransferWrite) mask |= VK_ACCESS_TRANSFER_WRITE_BIT;
    return mask;
}

// A developer's override of the embedded modules (shader iteration, A/B timings on a device
// without rebuilding the host): GLINT_SHADER_DIR=<dir> makes <dir>/<name>.spv replace the
// module of that name where the file exists. The modules read are kept for the process's life,
// since pipelines may be created from them at any time.
std::span<const uint32_t> overriddenShader(std::string_view name) {
    static const char* dir = std::getenv("GLINT_SHADER_DIR");
    if (!dir || !*dir) return {};
    static std::mutex mutex;
    static std::map<std::string, std::vector<uint32_t>, std::less<>> loaded;
    std::lock_guard lock(mutex);
    if (auto it = loaded.find(name); it != loaded.end()) return it->second;
    std::ifstream file(std::string(dir) + "/" + std::string(name) + ".spv", std::ios::binary);
    if (!file) return {};
    std::vector<char> bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    if (bytes.empty() || bytes.size() % 4 != 0)
        throw std::runtime_error("GLINT_SHADER_DIR: " + std::string(name) + ".spv is not a SPIR-V module");
    std::vector<uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), bytes.size());
    std::fprintf(stderr, "glint: pipeline %s from %s\n", std::string(name).c_str(), dir);
    return loaded.emplace(std::string(name), std::move(words)).first->second;
}

ComputePipeline& pipelineFor(Executor& executor, const std::string& name) {
    auto it = executor.pipelines.find(name);
    if (it == executor.pipelines.end()) {
        std::span<const uint32_t> code = overriddenShader(name);
        if (code.empty()) code = executor.findShader(name);
        if (code.empty()) {
            // Modules glint does not embed (hybrid_trace_rayquery, compiled by DXC only) come
            // from GLINT_SHADER_DIR.
            const char* dir = std::getenv("GLINT_SHADER_DIR");
            throw std::runtime_error(
                "no SPIR-V module '" + name + "': glint does not embed it and " +
                (dir && *dir ? "GLINT_SHADER_DIR (" + std::string(dir) + ") has no " + name + ".spv"
                             : std::string("GLINT_SHADER_DIR is not set")));
        }
        it = executor.pipelines.emplace(name, createComputePipeline(*executor.device, name, code)).first;
    }
    return it->second;
}

void recordBarriers(VkCommandBuffer cmd, const std::vector<core::PlannedBarrier>& barriers,
                    const ResourceTable& resources) {
    std::vector<VkImageMemoryBarrier> imageBarriers;
    std::vector<VkBufferMemoryBarrier> bufferBarriers;
    VkPipelineStageFlags srcStages = 0;
    VkPipelineStageFlags dstStages = 0;
    for (const core::PlannedBarrier& planned : barriers) {
        srcStages |= stagesFor(planned.src);
        dstStages |= stagesFor(planned.dst);
        if (auto image = resources.images.find(planned.resource); image != resources.images.end()) {
            VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
            barrier.srcAccessMask = accessMaskFor(planned.src);
            barrier.dstAccessMask = accessMaskFor(planned.dst);
            barrier.oldLayout = VK_IMAGE_LAYOUT_GENERAL;
            barrier.newLayout = VK_IMAGE_LAYOUT_GENERAL;
            barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            barrier.image = image->second->image;
            barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, VK_REMAINING_MIP_LEVELS, 0, 1};
            imageBarriers.push_back(barrier);
        } else if (auto buffer = resources.buffers.find(planned.resource);
                   buffer != resources.buffers.end()) {
            VkBufferMemoryBarrier barrier{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
            barrier.srcAccessMask = accessMaskFor(planned.src);
            barrier.dstAccessMask = accessMaskFor(planned.dst);
            barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            barrier.buffer = buffer->second->buffer;
            barrier.size = VK_WHOLE_SIZE;
            bufferBarriers.push_back(barrier);
        }
    }
    if (imageBarriers.empty() && bufferBarriers.empty()) return;
    vkCmdPipelineBarrier(cmd, srcStages, dstStages, 0, 0, nullptr,
                         static_cast<uint32_t>(bufferBarriers.size()), bufferBarriers.data(),
                         static_cast<uint32_t>(imageBarriers.size()), imageBarriers.data());
}

const Image& spareImage(Executor& executor, VkFormat format) {
    auto it = executor.spareImages.find(format);
    if (it == executor.spareImages.end()) {
        it = executor.spareImages.emplace(format, createImage2D(*executor.device, 1, 1, format)).first;
        executor.spareImagesToInitialize.push_back(it->second.image);
    }
    return it->second;
}

// Storage images bind one mip per array element, and slots past the last level get a spare
// image; sampled images see every mip.
void addImageInfos(Executor& executor, const ReflectedBinding& binding, const Image& image,
                   std::vector<VkDescriptorImageInfo>& infos) {
    for (uint32_t element = 0; element < binding.count; ++element) {
        VkDescriptorImageInfo info{};
        info.imageLayout = VK_IMAGE_LAYOUT_GENERAL;
        if (binding.type != VK_DESCRIPTOR_TYPE_STORAGE_IMAGE)
            info.imageView = image.view;
        else if (element < image.mipLevels)
            info.imageView = image.mipViews[element];
        else
            info.imageView = spareImage(executor, image.format).mipViews[0];
        infos.push_back(info);
    }
}

// Moves spare images created while recording into GENERAL before the first dispatch.
void initializeSpareImages(Executor& executor, VkCommandBuffer cmd) {
    std::vector<VkImageMemoryBarrier> barriers;
    for (VkImage image : executor.spareImagesToInitialize) {
        VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
        barrier.srcAccessMask = 0;
        barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
        barrier.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        barrier.newLayout = VK_IMAGE_LAYOUT_GENERAL;
        barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        barrier.image = image;
        barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        barriers.push_back(barrier);
    }
    executor.spareImagesToInitialize.clear();
    if (barriers.empty()) return;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 0,
                         nullptr, 0, nullptr, static_cast<uint32_t>(barriers.size()), barriers.data());
}

// The plan's resource descriptions are the single source of truth for sizes, formats and
// level counts; a bound resource that disagrees is a host bug caught here, not on the GPU.
void checkResources(const EffectPlan& plan, const ResourceTable& resources) {
    for (const ImageDesc& desc : plan.images) {
        const auto it = resources.images.find(desc.name);
        if (it == resources.images.end())
            throw std::runtime_error("effect '" + plan.effect + "': image '" + desc.name +
                                     "' is not in the resource table");
        const Image& image = *it->second;
        if (image.width != desc.width || image.height != desc.height || image.mipLevels != desc.mipLevels ||
            image.format != toVkFormat(desc.format))
            throw std::runtime_error(
                "effect '" + plan.effect + "': image '" + desc.name + "' is " + std::to_string(image.width) +
                "x" + std::to_string(image.height) + " with " + std::to_string(image.mipLevels) +
                " levels; the plan needs " + std::to_string(desc.width) + "x" + std::to_string(desc.height) +
                " with " + std::to_string(desc.mipLevels) + " levels in its declared format");
    }
    for (const BufferDesc& desc : plan.buffers) {
        const auto it = resources.buffers.find(desc.name);
        if (it == resources.buffers.end())
            throw std::runtime_error("effect '" + plan.effect + "': buffer '" + desc.name +
                                     "' is not in the resource table");
        if (it->second->size < desc.size)
            throw std::runtime_error("effect '" + plan.effect + "': buffer '" + desc.name +
                                     "' is smaller than the " + std::to_string(desc.size) +
                                     " bytes the plan needs");
    }
}

VkDescriptorSet writeDescriptors(Executor& executor, const ComputePipeline& pipeline, const Pass& pass,
                                 const ResourceTable& resources) {
    const Device& device = *executor.device;
    VkDescriptorSetAllocateInfo allocInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    allocInfo.descriptorPool = executor.descriptorPool;
    allocInfo.descriptorSetCount = 1;
    allocInfo.pSetLayouts = &pipeline.setLayout;
    VkDescriptorSet set = VK_NULL_HANDLE;
    GLINT_VK_CHECK(vkAllocateDescriptorSets(device.device, &allocInfo, &set));

    // Writes point into these vectors, so both are sized up front and never reallocate.
    std::size_t imageCount = 0;
    for (const ReflectedBinding& binding : pipeline.shader.bindings) imageCount += binding.count;
    std::vector<VkDescriptorImageInfo> imageInfos;
    std::vector<VkDescriptorBufferInfo> bufferInfos;
    std::vector<VkWriteDescriptorSetAccelerationStructureKHR> accelerationInfos;
    imageInfos.reserve(imageCount);
    bufferInfos.reserve(pipeline.shader.bindings.size());
    accelerationInfos.reserve(pipeline.shader.bindings.size());
    std::vector<VkWriteDescriptorSet> writes;
    for (const ReflectedBinding& binding : pipeline.shader.bindings) {
        VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        write.dstSet = set;
        write.dstBinding = binding.binding;
        write.descriptorType = binding.type;
        write.descriptorCount = binding.count;
        if (binding.type == VK_DESCRIPTOR_TYPE_SAMPLER) {
            for (uint32_t i = 0; i < binding.count; ++i)
                imageInfos.push_back(
                    {executor.linearClampSampler, VK_NULL_HANDLE, VK_IMAGE_LAYOUT_UNDEFINED});
            write.pImageInfo = &imageInfos[imageInfos.size() - binding.count];
            writes.push_back(write);
            continue;
        }
        if (binding.name == pass.constantsBinding && binding.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER) {
            if (pass.constants.size() != binding.blockSize)
                fail(pass, "constants are " + std::to_string(pass.constants.size()) +
                               " bytes, the shader's '" + binding.name + "' is " +
                               std::to_string(binding.blockSize));
            const VkDeviceSize alignment =
                std::max<VkDeviceSize>(device.properties.limits.minUniformBufferOffsetAlignment, 16);
            const VkDeviceSize offset = (executor.constantRingUsed + alignment - 1) / alignment * alignment;
            if (offset + pass.constants.size() > executor.constantRing.size)
                fail(pass, "constant ring exhausted; reset the executor between frames");
            std::memcpy(static_cast<std::byte*>(executor.constantRing.mapped) + offset, pass.constants.data(),
                        pass.constants.size());
            executor.constantRingUsed = offset + pass.constants.size();
            bufferInfos.push_back({executor.constantRing.buffer, offset, pass.constants.size()});
            write.pBufferInfo = &bufferInfos.back();
            writes.push_back(write);
            continue;
        }
        const auto use = std::find_if(pass.uses.begin(), pass.uses.end(),
                                      [&](const ResourceUse& u) { return u.binding == binding.name; });
        if (use == pass.uses.end()) fail(pass, "shader binding '" + binding.name + "' has no resource");
        if ((core::accessFlags(use->access) & core::kAccessShaderWrite) && !binding.writable)
            fail(pass, "'" + binding.name + "' is declared written but the shader cannot write it");
        const bool isBuffer = binding.type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER ||
                              binding.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
        if (binding.type == VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR) {
            const auto found = resources.accelerationStructures.find(use->resource);
            if (found == resources.accelerationStructures.end())
                fail(pass, "acceleration structure '" + use->resource + "' is not in the resource table");
            VkWriteDescriptorSetAccelerationStructureKHR info{
                VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR};
            info.accelerationStructureCount = 1;
            info.pAccelerationStructures = &found->second;
            accelerationInfos.push_back(info);
            write.pNext = &accelerationInfos.back();
        } else if (isBuffer) {
            const auto buffer = resources.buffers.find(use->resource);
            if (buffer == resources.buffers.end())
                fail(pass, "buffer '" + use->resource + "' is not in the resource table");
            bufferInfos.push_back({buffer->second->buffer, 0, VK_WHOLE_SIZE});
            write.pBufferInfo = &bufferInfos.back();
        } else {
            const auto image = resources.images.find(use->resource);
            if (image == resources.images.end())
                fail(pass, "image '" + use->resource + "' is not in the resource table");
            // A storage image must be written in its real format (docs/conventions.md §8 and
            // defect SS14: GLSL ports declared rgba32f on RGBA16F images, a source of
            // GPU-specific corruption).
            if (binding.type == VK_DESCRIPTOR_TYPE_STORAGE_IMAGE &&
                binding.imageFormat != VK_FORMAT_UNDEFINED && binding.imageFormat != image->second->format)
                fail(pass, "'" + binding.name + "' declares VkFormat " + std::to_string(binding.imageFormat) +
                               " but image '" + use->resource + "' is VkFormat " +
                               std::to_string(image->second->format));
            const std::size_t first = imageInfos.size();
            addImageInfos(executor, binding, *image->second, imageInfos);
            write.pImageInfo = &imageInfos[first];
        }
        writes.push_back(write);
    }
    for (const ResourceUse& use : pass.uses) {
        const bool bound = std::any_of(pipeline.shader.bindings.begin(), pipeline.shader.bindings.end(),
                                       [&](const ReflectedBinding& b) { return b.name == use.binding; });
        if (!bound && use.access != Access::IndirectArgs)
            fail(pass, "resource '" + use.resource + "' names binding '" + use.binding +
                           "', which the shader lacks");
    }
    vkUpdateDescriptorSets(device.device, static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);
    return set;
}

} // namespace

Executor createExecutor(const Device& device) {
    Executor executor;
    executor.device = &device;
    executor.findShader = core::findShader;
    try {
        std::vector<VkDescriptorPoolSize> sizes = {
            {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kMaxSetsPerReset},
            {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kMaxSetsPerReset * 8},
            {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kMaxSetsPerReset * 16},
            {VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, kMaxSetsPerReset * 8},
            {VK_DESCRIPTOR_TYPE_SAMPLER, kMaxSetsPerReset * 2},
            {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kMaxSetsPerReset * 2},
        };
        // The descriptor type exists only with the extension enabled.
        if (device.rayQuery)
            sizes.push_back({VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, kMaxSetsPerReset});
        VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
        poolInfo.maxSets = kMaxSetsPerReset;
        poolInfo.poolSizeCount = static_cast<uint32_t>(sizes.size());
        poolInfo.pPoolSizes = sizes.data();
        GLINT_VK_CHECK(vkCreateDescriptorPool(device.device, &poolInfo, nullptr, &executor.descriptorPool));

        VkSamplerCreateInfo samplerInfo{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
        samplerInfo.magFilter = VK_FILTER_LINEAR;
        samplerInfo.minFilter = VK_FILTER_LINEAR;
        // Trilinear: a fractional LOD (SSSR's roughness-aware environment lookups) blends two
        // levels instead of snapping between them.
        samplerInfo.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
        samplerInfo.addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        samplerInfo.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        samplerInfo.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        samplerInfo.maxLod = VK_LOD_CLAMP_NONE;
        GLINT_VK_CHECK(vkCreateSampler(device.device, &samplerInfo, nullptr, &executor.linearClampSampler));
        samplerInfo.magFilter = VK_FILTER_NEAREST;
        samplerInfo.minFilter = VK_FILTER_NEAREST;
        samplerInfo.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
        GLINT_VK_CHECK(vkCreateSampler(device.device, &samplerInfo, nullptr, &executor.pointClampSampler));

        executor.constantRing =
            createBuffer(device, kConstantRingSize, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryUse::Upload);
    } catch (...) {
        destroyExecutor(executor);
        throw;
    }
    return executor;
}

void destroyExecutor(Executor& executor) {
    if (!executor.device) return;
    const Device& device = *executor.device;
    for (auto& [name, pipeline] : executor.pipelines) destroyComputePipeline(device, pipeline);
    for (auto& [format, image] : executor.spareImages) destroyImage(device, image);
    destroyBuffer(device, executor.constantRing);
    if (executor.linearClampSampler) vkDestroySampler(device.device, executor.linearClampSampler, nullptr);
    if (executor.pointClampSampler) vkDestroySampler(device.device, executor.pointClampSampler, nullptr);
    if (executor.descriptorPool) vkDestroyDescriptorPool(device.device, executor.descriptorPool, nullptr);
    executor = Executor{};
}

void resetExecutor(Executor& executor) {
    GLINT_VK_CHECK(vkResetDescriptorPool(executor.device->device, executor.descriptorPool, 0));
    executor.constantRingUsed = 0;
}

void recordPlan(Executor& executor, VkCommandBuffer cmd, const EffectPlan& plan,
                const ResourceTable& resources, const PassHooks& hooks) {
    if (const std::string error = core::validatePlan(plan); !error.empty()) throw std::runtime_error(error);
    checkResources(plan, resources);
    const std::vector<core::PlannedBarrier> barriers = core::planBarriers(plan);
    auto nextBarrier = barriers.begin();
    auto takeBarriers = [&](std::size_t index, core::BarrierPoint point) {
        std::vector<core::PlannedBarrier> taken;
        for (;
             nextBarrier != barriers.end() && nextBarrier->beforePass == index && nextBarrier->point == point;
             ++nextBarrier)
            taken.push_back(*nextBarrier);
        return taken;
    };
    for (std::size_t index = 0; index < plan.passes.size(); ++index) {
        const Pass& pass = plan.passes[index];
        ComputePipeline& pipeline = pipelineFor(executor, pass.pipeline);
        for (int axis = 0; axis < 3; ++axis)
            if (pipeline.shader.localSize[axis] != pass.groupSize[axis])
                fail(pass, "declared group size differs from the shader's [numthreads]");
        const VkDescriptorSet set = writeDescriptors(executor, pipeline, pass, resources);

        initializeSpareImages(executor, cmd);

        recordBarriers(cmd, takeBarriers(index, core::BarrierPoint::BeforeFills), resources);
        for (const std::string& name : pass.zeroBuffers) {
            const auto buffer = resources.buffers.find(name);
            if (buffer == resources.buffers.end())
                fail(pass, "buffer '" + name + "' is not in the resource table");
            vkCmdFillBuffer(cmd, buffer->second->buffer, 0, VK_WHOLE_SIZE, 0);
        }
        recordBarriers(cmd, takeBarriers(index, core::BarrierPoint::BeforeDispatch), resources);

        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.pipeline);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.layout, 0, 1, &set, 0, nullptr);
        if (hooks.beforeDispatch) hooks.beforeDispatch(cmd, index);
        if (const auto* direct = std::get_if<DirectDispatch>(&pass.dispatch)) {
            if (direct->groupsX && direct->groupsY && direct->groupsZ)
                vkCmdDispatch(cmd, direct->groupsX, direct->groupsY, direct->groupsZ);
        } else {
            const auto& indirect = std::get<IndirectDispatch>(pass.dispatch);
            const auto buffer = resources.buffers.find(indirect.resource);
            if (buffer == resources.buffers.end())
                fail(pass,
                     "indirect argument buffer '" + indirect.resource + "' is not in the resource table");
            vkCmdDispatchIndirect(cmd, buffer->second->buffer, indirect.offset);
        }
        if (hooks.afterDispatch) hooks.afterDispatch(cmd, index);
    }
}

} // namespace glint::vk
