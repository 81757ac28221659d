// A consumer of the installed glint package, written as an engine would: its own Vulkan
// instance and device, glint::core to plan an effect, glint::vulkan to run it. It plans the
// depth pyramid of a small odd-sized depth image, runs it, reads level 1 back and compares it
// with the minimum of each 2x2 footprint (the far value outside the image). Exits 1 on a
// mismatch or a validation error, 2 when no Vulkan device is there.
#include <glint/glint_depth_pyramid.h>
#include <glint/glint_sssr_tables.h>
#include <glint/vulkan/vk_effect.h>
#include <glint/vulkan/vk_reflect.h>
#include <glint/vulkan/vk_resources.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "glint_sssr_tables_data.h"

namespace {

int validationErrors = 0;

VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                         VkDebugUtilsMessageTypeFlagsEXT,
                                         const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
    if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) {
        ++validationErrors;
        std::fprintf(stderr, "validation: %s\n", data->pMessage);
    }
    return VK_FALSE;
}

bool hasLayer(const char* name) {
    std::uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    return std::any_of(layers.begin(), layers.end(), [&](const VkLayerProperties& layer) {
        return std::strcmp(layer.layerName, name) == 0;
    });
}

void check(VkResult result, const char* what) {
    if (result != VK_SUCCESS) {
        std::fprintf(stderr, "consumer: %s failed (VkResult %d)\n", what, static_cast<int>(result));
        std::exit(2);
    }
}

void barrier(VkCommandBuffer cmd, VkPipelineStageFlags src, VkAccessFlags srcAccess, VkPipelineStageFlags dst,
             VkAccessFlags dstAccess) {
    VkMemoryBarrier memory{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    memory.srcAccessMask = srcAccess;
    memory.dstAccessMask = dstAccess;
    vkCmdPipelineBarrier(cmd, src, dst, 0, 1, &memory, 0, nullptr, 0, nullptr);
}

} // namespace

// The installed table files and header hold exactly what the library computes.
int tableMismatches() {
    std::ifstream file(std::string(GLINT_CONSUMER_TABLES_DIR) + "/sssr_blue_noise_rg32f.bin",
                       std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    const std::vector<float>& noise = glint::sssrBlueNoise();
    int mismatches = bytes.size() == noise.size() * sizeof(float) &&
                             std::memcmp(bytes.data(), noise.data(), bytes.size()) == 0
                         ? 0
                         : 1;
    const std::vector<float> lut = glint::sssrBrdfLut(glint::kSssrBrdfLutSize);
    for (std::size_t i = 0; i < lut.size(); ++i) mismatches += lut[i] != glint::tables::kSssrBrdfLut[i];
    for (std::size_t i = 0; i < noise.size(); ++i) mismatches += noise[i] != glint::tables::kSssrBlueNoise[i];
    return mismatches;
}

std::vector<std::uint32_t> readSpirv(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    std::vector<std::uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), words.size() * 4);
    return words;
}

// The engine entry files put no two resources on one Vulkan binding, and the collision example
// (b0/s0 and t1/u1 in one space, which spirv-val accepts) is caught with both pairs named.
int bindingProblems() {
    const std::string dir = GLINT_CONSUMER_SPIRV_DIR;
    int problems = 0;
    for (const char* entry : {"engine_shadow_filter", "engine_sssr_intersect"})
        for (const std::string& line :
             glint::vk::sharedBindings(readSpirv(dir + "/" + entry + ".spv"), entry)) {
            std::fprintf(stderr, "consumer: %s\n", line.c_str());
            ++problems;
        }
    const std::vector<std::string> caught = glint::vk::sharedBindings(
        readSpirv(dir + "/engine_binding_collision.spv"), "engine_binding_collision");
    const auto names = [&](const char* a, const char* b, const char* slot) {
        return std::any_of(caught.begin(), caught.end(), [&](const std::string& line) {
            return line.find(std::string("'") + a + "'") != std::string::npos &&
                   line.find(std::string("'") + b + "'") != std::string::npos &&
                   line.find(slot) != std::string::npos;
        });
    };
    if (caught.size() != 2 || !names("EngineConstants", "EngineLinearClamp", "set 1, binding 0") ||
        !names("EngineMoments", "EngineFiltered", "set 1, binding 1")) {
        std::fprintf(stderr,
                     "consumer: the binding collisions of engine_binding_collision were not both found "
                     "(%zu reported)\n",
                     caught.size());
        for (const std::string& line : caught) std::fprintf(stderr, "  %s\n", line.c_str());
        ++problems;
    }
    return problems;
}

int main() {
    if (const int problems = bindingProblems(); problems != 0) return 1;
    if (const int mismatches = tableMismatches(); mismatches != 0) {
        std::fprintf(stderr, "consumer: the installed tables differ from the library's in %d places\n",
                     mismatches);
        return 1;
    }
    const char* layer = "VK_LAYER_KHRONOS_validation";
    const bool validate = hasLayer(layer);
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.apiVersion = VK_API_VERSION_1_1;
    VkInstanceCreateInfo instanceInfo{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    instanceInfo.pApplicationInfo = &app;
    const char* extension = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
    if (validate) {
        instanceInfo.enabledLayerCount = 1;
        instanceInfo.ppEnabledLayerNames = &layer;
        instanceInfo.enabledExtensionCount = 1;
        instanceInfo.ppEnabledExtensionNames = &extension;
    }
    VkInstance instance = VK_NULL_HANDLE;
    check(vkCreateInstance(&instanceInfo, nullptr, &instance), "vkCreateInstance");
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    if (validate) {
        VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
        info.messageSeverity =
            VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT;
        info.messageType =
            VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT;
        info.pfnUserCallback = onMessage;
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
        check(create(instance, &info, nullptr, &messenger), "vkCreateDebugUtilsMessengerEXT");
    }

    std::uint32_t count = 0;
    vkEnumeratePhysicalDevices(instance, &count, nullptr);
    if (count == 0) {
        std::fprintf(stderr, "consumer: no Vulkan device\n");
        return 2;
    }
    std::vector<VkPhysicalDevice> physicals(count);
    vkEnumeratePhysicalDevices(instance, &count, physicals.data());
    glint::vk::Device device;
    device.physical = physicals.front();
    vkGetPhysicalDeviceProperties(device.physical, &device.properties);
    vkGetPhysicalDeviceMemoryProperties(device.physical, &device.memory);
    std::uint32_t families = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device.physical, &families, nullptr);
    std::vector<VkQueueFamilyProperties> familyProperties(families);
    vkGetPhysicalDeviceQueueFamilyProperties(device.physical, &families, familyProperties.data());
    for (std::uint32_t i = 0; i < families; ++i)
        if (familyProperties[i].queueFlags & VK_QUEUE_COMPUTE_BIT) {
            device.queueFamily = i;
            break;
        }
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = device.queueFamily;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    deviceInfo.queueCreateInfoCount = 1;
    deviceInfo.pQueueCreateInfos = &queueInfo;
    check(vkCreateDevice(device.physical, &deviceInfo, nullptr, &device.device), "vkCreateDevice");
    vkGetDeviceQueue(device.device, device.queueFamily, 0, &device.queue);
    VkPhysicalDeviceSubgroupProperties subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
    VkPhysicalDeviceProperties2 properties2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    properties2.pNext = &subgroup;
    vkGetPhysicalDeviceProperties2(device.physical, &properties2);
    device.subgroupSize = subgroup.subgroupSize;

    // The effect, planned by glint::core.
    const std::uint32_t width = 37, height = 23;
    glint::DepthPyramidDesc desc;
    desc.size = {width, height};
    glint::EffectPlan plan;
    std::string error;
    if (glint::planDepthPyramid(desc, plan, &error) != glint::Result::Ok) {
        std::fprintf(stderr, "consumer: %s\n", error.c_str());
        return 1;
    }
    std::vector<float> depth(std::size_t{width} * height);
    for (std::size_t i = 0; i < depth.size(); ++i)
        depth[i] = 0.25f + 0.5f * std::fabs(std::sin(0.37f * static_cast<float>(i)));

    // Run by glint::vulkan on the engine's device.
    glint::vk::Image depthImage = glint::vk::createImage2D(device, width, height, VK_FORMAT_R32_SFLOAT);
    glint::vk::Buffer upload = glint::vk::createBuffer(
        device, depth.size() * 4, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, glint::vk::MemoryUse::Upload);
    std::memcpy(upload.mapped, depth.data(), depth.size() * 4);
    glint::vk::flushBuffer(device, upload);
    glint::vk::EffectInstance effect;
    if (glint::vk::createEffect(device, plan, effect, &error) != glint::Result::Ok) {
        std::fprintf(stderr, "consumer: %s\n", error.c_str());
        return 1;
    }
    const glint::vk::Image& pyramid = effect.images.at("depth_pyramid");
    const std::uint32_t w1 = std::max(1u, pyramid.width >> 1), h1 = std::max(1u, pyramid.height >> 1);
    glint::vk::Buffer readback = glint::vk::createBuffer(
        device, std::size_t{w1} * h1 * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT, glint::vk::MemoryUse::Readback);
    glint::vk::Executor executor = glint::vk::createExecutor(device);

    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.queueFamilyIndex = device.queueFamily;
    VkCommandPool pool = VK_NULL_HANDLE;
    check(vkCreateCommandPool(device.device, &poolInfo, nullptr, &pool), "vkCreateCommandPool");
    VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocate.commandPool = pool;
    allocate.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    check(vkAllocateCommandBuffers(device.device, &allocate, &cmd), "vkAllocateCommandBuffers");
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    vkBeginCommandBuffer(cmd, &begin);
    VkImageMemoryBarrier toGeneral{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    toGeneral.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toGeneral.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    toGeneral.newLayout = VK_IMAGE_LAYOUT_GENERAL;
    toGeneral.srcQueueFamilyIndex = toGeneral.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toGeneral.image = depthImage.image;
    toGeneral.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0,
                         nullptr, 0, nullptr, 1, &toGeneral);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {width, height, 1};
    vkCmdCopyBufferToImage(cmd, upload.buffer, depthImage.image, VK_IMAGE_LAYOUT_GENERAL, 1, &region);
    barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
            VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT);
    glint::vk::ResourceTable inputs;
    inputs.images["depth"] = &depthImage;
    if (glint::vk::dispatchEffect(effect, executor, cmd, plan, inputs, {}, &error) != glint::Result::Ok) {
        std::fprintf(stderr, "consumer: %s\n", error.c_str());
        return 1;
    }
    barrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
            VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
    VkBufferImageCopy level1{};
    level1.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 1, 0, 1};
    level1.imageExtent = {w1, h1, 1};
    vkCmdCopyImageToBuffer(cmd, pyramid.image, VK_IMAGE_LAYOUT_GENERAL, readback.buffer, 1, &level1);
    barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
            VK_ACCESS_HOST_READ_BIT);
    vkEndCommandBuffer(cmd);
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    check(vkQueueSubmit(device.queue, 1, &submit, VK_NULL_HANDLE), "vkQueueSubmit");
    check(vkQueueWaitIdle(device.queue), "vkQueueWaitIdle");
    glint::vk::invalidateBuffer(device, readback);

    // Level 1 texel (i, j) bounds pixels [2i, 2i + 2) x [2j, 2j + 2); outside the image the far value 1.
    const auto* texels = static_cast<const float*>(readback.mapped);
    int mismatches = 0;
    for (std::uint32_t j = 0; j < h1; ++j)
        for (std::uint32_t i = 0; i < w1; ++i) {
            float expected = 1.0f;
            for (std::uint32_t y = 2 * j; y < 2 * j + 2; ++y)
                for (std::uint32_t x = 2 * i; x < 2 * i + 2; ++x)
                    if (x < width && y < height)
                        expected = std::min(expected, depth[std::size_t{y} * width + x]);
            if (texels[std::size_t{j} * w1 + i] != expected) ++mismatches;
        }

    vkDestroyCommandPool(device.device, pool, nullptr);
    glint::vk::destroyExecutor(executor);
    glint::vk::destroyEffect(effect);
    glint::vk::destroyBuffer(device, readback);
    glint::vk::destroyBuffer(device, upload);
    glint::vk::destroyImage(device, depthImage);
    vkDestroyDevice(device.device, nullptr);
    if (messenger) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
        destroy(instance, messenger, nullptr);
    }
    vkDestroyInstance(instance, nullptr);
    std::printf(
        "consumer: depth pyramid of %ux%u on %s: level 1 %ux%u, %d mismatches, %d validation errors\n", width,
        height, device.properties.deviceName, w1, h1, mismatches, validationErrors);
    return mismatches == 0 && validationErrors == 0 ? 0 : 1;
}
