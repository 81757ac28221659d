#include "glint/vulkan/vk_pipeline.h"

#include "glint/vulkan/vk_check.h"

#include <cinttypes>
#include <cstdio>
#include <stdexcept>
#include <vector>

namespace glint::vk {

namespace {

std::string formatStatistic(const VkPipelineExecutableStatisticKHR& statistic) {
    char buffer[64] = {};
    switch (statistic.format) {
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_BOOL32_KHR:
        return statistic.value.b32 ? "true" : "false";
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_INT64_KHR:
        std::snprintf(buffer, sizeof(buffer), "%" PRId64, statistic.value.i64);
        break;
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_UINT64_KHR:
        std::snprintf(buffer, sizeof(buffer), "%" PRIu64, statistic.value.u64);
        break;
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_FLOAT64_KHR:
        std::snprintf(buffer, sizeof(buffer), "%g", statistic.value.f64);
        break;
    default:
        return "?";
    }
    return buffer;
}

// One stderr line per executable of the pipeline: "pipeline-stats <name>: <stat>=<value>; ...".
// Only called where device.pipelineStatistics says the extension and feature are enabled.
void printPipelineStatistics(const Device& device, const ComputePipeline& pipeline) {
    const auto getProperties = reinterpret_cast<PFN_vkGetPipelineExecutablePropertiesKHR>(
        vkGetDeviceProcAddr(device.device, "vkGetPipelineExecutablePropertiesKHR"));
    const auto getStatistics = reinterpret_cast<PFN_vkGetPipelineExecutableStatisticsKHR>(
        vkGetDeviceProcAddr(device.device, "vkGetPipelineExecutableStatisticsKHR"));
    if (!getProperties || !getStatistics) return;

    VkPipelineInfoKHR pipelineInfo{VK_STRUCTURE_TYPE_PIPELINE_INFO_KHR};
    pipelineInfo.pipeline = pipeline.pipeline;
    uint32_t executableCount = 0;
    if (getProperties(device.device, &pipelineInfo, &executableCount, nullptr) != VK_SUCCESS) return;
    std::vector<VkPipelineExecutablePropertiesKHR> executables(
        executableCount,
        VkPipelineExecutablePropertiesKHR{VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_PROPERTIES_KHR});
    if (getProperties(device.device, &pipelineInfo, &executableCount, executables.data()) < VK_SUCCESS)
        return;
    executables.resize(executableCount);

    for (uint32_t index = 0; index < executableCount; ++index) {
        VkPipelineExecutableInfoKHR executableInfo{VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_INFO_KHR};
        executableInfo.pipeline = pipeline.pipeline;
        executableInfo.executableIndex = index;
        uint32_t statisticCount = 0;
        if (getStatistics(device.device, &executableInfo, &statisticCount, nullptr) != VK_SUCCESS) continue;
        std::vector<VkPipelineExecutableStatisticKHR> statistics(
            statisticCount,
            VkPipelineExecutableStatisticKHR{VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_STATISTIC_KHR});
        if (getStatistics(device.device, &executableInfo, &statisticCount, statistics.data()) < VK_SUCCESS) {
            continue;
        }
        statistics.resize(statisticCount);

        std::string line = "pipeline-stats " + pipeline.name;
        // Pipelines with several executables (none for compute on most drivers) name each one.
        if (executableCount > 1) line += std::string(" [") + executables[index].name + "]";
        line += ":";
        for (size_t i = 0; i < statistics.size(); ++i) {
            line += (i == 0 ? " " : "; ");
            line += statistics[i].name;
            line += "=";
            line += formatStatistic(statistics[i]);
        }
        line += "\n";
        std::fputs(line.c_str(), stderr);
    }
}

} // namespace

ComputePipeline createComputePipeline(const Device& device, const std::string& name,
                                      std::span<const uint32_t> code) {
    ComputePipeline pipeline;
    pipeline.name = name;
    pipeline.shader = reflectComputeShader(code, name);
    for (const ReflectedBinding& reflected : pipeline.shader.bindings)
        if (reflected.type == VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR && !device.rayQuery)
            throw std::runtime_error(name + ": traces rays with RayQuery ('" + reflected.name +
                                     "'), but the device has no VK_KHR_ray_query enabled");

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
        if (device.pipelineStatistics) pipelineInfo.flags |= VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR;
        GLINT_VK_CHECK(vkCreateComputePipelines(device.device, VK_NULL_HANDLE, 1, &pipelineInfo, nullptr,
                                                &pipeline.pipeline));
        if (device.pipelineStatistics) printPipelineStatistics(device, pipeline);
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
