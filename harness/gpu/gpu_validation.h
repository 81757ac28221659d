// The Khronos validation layer's reports, counted and kept. A VK_EXT_debug_utils messenger
// feeds ValidationStats from whichever thread the driver or layer reports on; tests assert
// the counts stay at zero, tools print a summary.
#pragma once

#include <vulkan/vulkan.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

namespace glint::gpu {

struct ValidationStats {
    std::atomic<uint32_t> errors{0};
    std::atomic<uint32_t> warnings{0};
    // Read by the callback; set them before the messenger exists.
    bool printErrors = true;    // each error to stderr as it arrives, with its message id name
    bool printWarnings = false; // warnings are kept but not printed: the layer is chatty

    std::mutex mutex; // guards the two members below
    // "error: <message id name>: <message>" or "warning: ...", in arrival order. Capped at
    // kMaxKeptMessages so a flood cannot exhaust memory; the counters keep counting.
    std::vector<std::string> messages;
    size_t droppedMessages = 0;

    static constexpr size_t kMaxKeptMessages = 1000;
};

// For chaining into VkInstanceCreateInfo::pNext so that vkCreateInstance/vkDestroyInstance
// are validated too. stats must outlive the instance.
VkDebugUtilsMessengerCreateInfoEXT messengerCreateInfo(ValidationStats& stats);

// Requires VK_EXT_debug_utils to be enabled on the instance.
VkDebugUtilsMessengerEXT createMessenger(VkInstance instance, ValidationStats& stats);
void destroyMessenger(VkInstance instance, VkDebugUtilsMessengerEXT& messenger);

// Copies of the kept messages from position `first` on (a count taken earlier), so a caller
// can show just what arrived since its last look.
std::vector<std::string> validationMessages(ValidationStats& stats, size_t first = 0);
size_t validationMessageCount(ValidationStats& stats);

} // namespace glint::gpu
