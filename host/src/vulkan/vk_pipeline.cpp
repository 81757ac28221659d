#include "vulkan/vk_pipeline.h"

#include "vulkan/vk_check.h"

#include <vector>

namespace glint::vk {

ComputePipeline createComputePipeline(const Device& device, const std::string& name,
                                      std::span<const uint32_t> code) {
    ComputePipeline pipeline;
    pipeline.name = name;
    pipeline.shader = reflectComputeShader(code, name);

    std::vector<VkDescriptorSetLayoutBinding> bindings;
    for (const ReflectedBinding& reflected : pipeline.shader.bindings) {
        VkDescriptorSetLayoutBinding binding{};
        binding.binding = reflected.binding;
        binding.descriptorType = reflected.type;
        binding.descriptorCount = reflected.count;
        binding.stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
        bindings.push_back(binding);
    }
    VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    setInfo.bindingCount = static_cast<uint32_t>(bindings.size());
    setInfo.pBindings = bindings.data();
    try {
        GLINT_VK_CHECK(vkCreateDescriptorSetLayout(device.device, &setInfo, nullptr, &pipeline.setLayout));

        VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
        layoutInfo.setLayoutCount = 1;
        layoutInfo.pSetLayouts = &pipeline.setLayout;
        GLINT_VK_CHECK(vkCreatePipelineLayout(device.device, &layoutInfo, nullptr, &pipeline.layout));

        VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
        moduleInfo.codeSize = code.size_bytes();
        moduleInfo.pCode = code.data();
        GLINT_VK_CHECK(vkCreateShaderModule(device.device, &moduleInfo, nullptr, &pipeline.module));

        VkComputePipelineCreateInfo pipelineInfo{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
        pipelineInfo.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
        pipelineInfo.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
        pipelineInfo.stage.module = pipeline.module;
        pipelineInfo.stage.pName = "main";
        pipelineInfo.layout = pipeline.layout;
        GLINT_VK_CHECK(vkCreateComputePipelines(device.device, VK_NULL_HANDLE, 1, &pipelineInfo, nullptr,
                                                &pipeline.pipeline));
    } catch (...) {
        destroyComputePipeline(device, pipeline);
        throw;
    }
    return pipeline;
}

void destroyComputePipeline(const Device& device, ComputePipeline& pipeline) {
    if (pipeline.pipeline) vkDestroyPipeline(device.device, pipeline.pipeline, nullptr);
    if (pipeline.module) vkDestroyShaderModule(device.device, pipeline.module, nullptr);
    if (pipeline.layout) vkDestroyPipelineLayout(device.device, pipeline.layout, nullptr);
    if (pipeline.setLayout) vkDestroyDescriptorSetLayout(device.device, pipeline.setLayout, nullptr);
    pipeline = ComputePipeline{};
}

} // namespace glint::vk
