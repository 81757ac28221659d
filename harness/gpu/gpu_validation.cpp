// The debug-utils callback. It may run on any thread the application or driver calls Vulkan
// from, concurrently, hence the atomics and the mutex.
#include <gpu/gpu_validation.h>

#include "glint/vulkan/vk_check.h"

#include <cstdio>

namespace glint::gpu {

namespace {

VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                         VkDebugUtilsMessageTypeFlagsEXT /*types*/,
                                         const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    auto& stats = *static_cast<ValidationStats*>(user);
    const bool isError = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) != 0;
    (isError ? stats.errors : stats.warnings).fetch_add(1, std::memory_order_relaxed);

    const char* id = data->pMessageIdName ? data->pMessageIdName : "(no message id)";
    const char* text = data->pMessage ? data->pMessage : "";
    std::string line = std::string(isError ? "error: " : "warning: ") + id + ": " + text;
    if (isError ? stats.printErrors : stats.printWarnings) {
        std::fprintf(stderr, "glint: validation %s\n", line.c_str());
    }
    {
        std::lock_guard<std::mutex> lock(stats.mutex);
        if (stats.messages.size() < ValidationStats::kMaxKeptMessages) {
            stats.messages.push_back(std::move(line));
        } else {
            ++stats.droppedMessages;
        }
    }
    // The spec asks applications to return VK_FALSE: the reported call then proceeds as it
    // would without the layer.
    return VK_FALSE;
}

} // namespace

VkDebugUtilsMessengerCreateInfoEXT messengerCreateInfo(ValidationStats& stats) {
    VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    // Info and verbose messages are the loader and layer narrating themselves; not problems.
    info.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    info.pfnUserCallback = onMessage;
    info.pUserData = &stats;
    return info;
}

VkDebugUtilsMessengerEXT createMessenger(VkInstance instance, ValidationStats& stats) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
    if (!create) {
        throw vk::VulkanError(
            VK_ERROR_EXTENSION_NOT_PRESENT,
            "glint: vkCreateDebugUtilsMessengerEXT is missing (VK_EXT_debug_utils not enabled)");
    }
    VkDebugUtilsMessengerCreateInfoEXT info = messengerCreateInfo(stats);
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    GLINT_VK_CHECK(create(instance, &info, nullptr, &messenger));
    return messenger;
}

void destroyMessenger(VkInstance instance, VkDebugUtilsMessengerEXT& messenger) {
    if (!messenger) return;
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance, messenger, nullptr);
    messenger = VK_NULL_HANDLE;
}

std::vector<std::string> validationMessages(ValidationStats& stats, size_t first) {
    std::lock_guard<std::mutex> lock(stats.mutex);
    if (first >= stats.messages.size()) return {};
    return {stats.messages.begin() + static_cast<std::ptrdiff_t>(first), stats.messages.end()};
}

size_t validationMessageCount(ValidationStats& stats) {
    std::lock_guard<std::mutex> lock(stats.mutex);
    return stats.messages.size();
}

} // namespace glint::gpu
