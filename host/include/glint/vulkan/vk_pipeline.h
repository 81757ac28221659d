// Compute pipelines built from embedded SPIR-V, with the descriptor set layout that
// reflection of the same module gives.
#pragma once

#include "glint/vulkan/vk_device.h"
#include "glint/vulkan/vk_reflect.h"

#include <span>
#include <string>

namespace glint::vk {

struct ComputePipeline {
    std::string name;
    ReflectedShader shader;
    VkShaderModule module = VK_NULL_HANDLE;
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
};

// code is the SPIR-V of the module called name (used in messages). Throws on an empty module,
// reflection problems and Vulkan errors.
ComputePipeline createComputePipeline(const Device& device, const std::string& name,
                                      std::span<const uint32_t> code);
void destroyComputePipeline(const Device& device, ComputePipeline& pipeline);

} // namespace glint::vk
