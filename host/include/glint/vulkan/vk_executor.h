// Executes an EffectPlan (glint/glint_pass.h) on a command buffer: pipelines by name,
// descriptors bound by the shader's variable names, barriers from the declared accesses.
//
// Images are used in VK_IMAGE_LAYOUT_GENERAL throughout (sampled and storage alike); the
// application transitions them there once. Everything the plan reads must be written and
// visible to "all commands" before the command buffer reaches the plan; the executor's first
// barrier per resource waits for that external write.
#pragma once

#include "glint/glint_pass.h"
#include "glint/vulkan/vk_pipeline.h"
#include "glint/vulkan/vk_resources.h"

#include <functional>
#include <map>
#include <span>
#include <string>
#include <string_view>

namespace glint::vk {

struct ResourceTable {
    std::map<std::string, const Image*> images;
    std::map<std::string, const Buffer*> buffers;
    // Top-level acceleration structures, built and made visible to compute shaders
    // (VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR) before the command buffer reaches the plan.
    std::map<std::string, VkAccelerationStructureKHR> accelerationStructures;
};

// Called around each dispatch, e.g. to write timestamps or debug labels.
struct PassHooks {
    std::function<void(VkCommandBuffer, std::size_t passIndex)> beforeDispatch;
    std::function<void(VkCommandBuffer, std::size_t passIndex)> afterDispatch;
};

// Finds a pipeline's SPIR-V by name; empty when there is none.
using ShaderLookup = std::function<std::span<const uint32_t>(std::string_view)>;

struct Executor {
    const Device* device = nullptr;
    ShaderLookup findShader; // glint's embedded modules unless the caller adds its own
    std::map<std::string, ComputePipeline> pipelines; // created on first use
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
    // Sampler bindings get linear clamp-to-edge, or nearest when their name contains "point".
    VkSampler linearClampSampler = VK_NULL_HANDLE;
    VkSampler pointClampSampler = VK_NULL_HANDLE;
    Buffer constantRing; // per-pass constants, host-visible
    VkDeviceSize constantRingUsed = 0;
    // 1x1 images bound to storage-image array slots past an image's last level, one per
    // format, so that no spare slot ever aliases a live level (docs/conventions.md, defect DP1:
    // spare mip slots bound to mip 0 let late writes land there).
    std::map<VkFormat, Image> spareImages;
    std::vector<VkImage> spareImagesToInitialize; // created, not yet moved to GENERAL
};

Executor createExecutor(const Device& device);
void destroyExecutor(Executor& executor);

// Recycles descriptors and constant memory. Call only after the GPU finished every command
// buffer recorded since the previous reset.
void resetExecutor(Executor& executor);

// Records the plan. Throws std::runtime_error with one line naming the pass when the plan
// does not match its shaders (unknown binding, missing resource, group size mismatch...).
void recordPlan(Executor& executor, VkCommandBuffer cmd, const EffectPlan& plan,
                const ResourceTable& resources, const PassHooks& hooks = {});

} // namespace glint::vk
