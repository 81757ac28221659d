// The device glint runs on. The application (or the harness) owns every handle here; glint
// only borrows them, so an engine can hand over its own device and queue.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>

namespace glint::vk {

struct Device {
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE; // must support compute
    uint32_t queueFamily = 0;
    VkPhysicalDeviceProperties properties{};
    VkPhysicalDeviceMemoryProperties memory{};
    uint32_t subgroupSize = 0; // VkPhysicalDeviceSubgroupProperties::subgroupSize
    bool timestamps = false;   // queue family has timestampValidBits > 0
    uint32_t timestampValidBits = 0;
    // VK_KHR_pipeline_executable_properties with pipelineExecutableInfo is enabled: pipelines are
    // created with statistics capture and their statistics printed (GLINT_PIPELINE_STATS=1).
    bool pipelineStatistics = false;
    // VK_KHR_acceleration_structure and VK_KHR_ray_query are enabled, with bufferDeviceAddress:
    // modules that trace with RayQuery (an acceleration structure binding) can run.
    bool rayQuery = false;
};

} // namespace glint::vk
