// The harness's Vulkan instance, device and queue: created once per tool run or test process,
// then borrowed by glint as a glint::vk::Device.
#pragma once

#include <gpu/gpu_devices.h>
#include <gpu/gpu_validation.h>

#include "glint/vulkan/vk_device.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace glint::gpu {

// GLINT_DEVICE's value, or "" when unset (see chooseDevice for the syntax).
std::string deviceSelectorFromEnvironment();

struct ContextOptions {
    // VK_LAYER_KHRONOS_validation with a counting messenger; createContext fails with a clear
    // error if the layer is not installed.
    bool validation = false;
    // The layer's synchronization validation (hazards between dispatches, copies and host
    // access). Only with validation. Best-practices checks stay off: they flag style, not bugs.
    bool synchronizationValidation = false;
    // Off for tests that provoke validation errors on purpose and only count them.
    bool printValidationErrors = true;
    std::string deviceSelector = deviceSelectorFromEnvironment();
    // Presentation (glint view): the instance extensions the window system needs, and a
    // callback that makes the window's surface once the instance exists. The device then gets
    // VK_KHR_swapchain and a queue family with graphics, compute and presentation to it.
    std::vector<std::string> surfaceExtensions;
    std::function<VkSurfaceKHR(VkInstance)> createSurface;
};

struct RecordedCommands;

struct Context {
    VkInstance instance = VK_NULL_HANDLE;
    uint32_t instanceApiVersion = 0;
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    vk::Device device;
    DeviceInfo info; // the features it reports (float16, int16, storage16) are enabled
    VkCommandPool commandPool = VK_NULL_HANDLE; // for submitAndWait; resettable buffers
    // submitAndWait's command buffer and fence, re-recorded on every call: allocating a pair per
    // call made the validation layer's and lavapipe's bookkeeping grow with every submission.
    std::unique_ptr<RecordedCommands> immediate;
    // Non-null when validation is on. Heap-allocated because the messenger holds its address.
    std::unique_ptr<ValidationStats> validation;
    bool memoryBudget = false;             // VK_EXT_memory_budget is enabled
    VkSurfaceKHR surface = VK_NULL_HANDLE; // with ContextOptions::createSurface; the queue presents to it
};

// Device-local memory the process holds and may hold, summed over the device-local heaps
// (VK_EXT_memory_budget); `known` is false where the device lacks the extension.
struct DeviceMemoryUse {
    bool known = false;
    uint64_t usedBytes = 0;
    uint64_t budgetBytes = 0;
};
DeviceMemoryUse deviceMemoryUse(const Context& context);

// Throws glint::vk::VulkanError or std::runtime_error with a one-line message on failure,
// having destroyed whatever it had created.
Context createContext(const ContextOptions& options);
// Waits for the device to go idle, then destroys everything but `validation`, which stays
// readable: vkDestroyDevice is where the layer reports objects the caller never destroyed.
void destroyContext(Context& context);

// Records one command buffer with `record`, submits it to the context's queue and waits for
// it to finish. Not thread-safe: the harness drives the queue from one thread.
void submitAndWait(const Context& context, const std::function<void(VkCommandBuffer)>& record);

// A command buffer recorded once and submitted any number of times (sustained benchmarks),
// with the fence of its latest submission.
struct RecordedCommands {
    VkCommandBuffer commands = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;
    bool pending = false; // submitted and not yet waited for
};
RecordedCommands recordCommands(const Context& context, const std::function<void(VkCommandBuffer)>& record);
// Submits without waiting; the previous submission must have been waited for.
void submitRecorded(const Context& context, RecordedCommands& recorded);
void waitRecorded(const Context& context, RecordedCommands& recorded);
// Idles the device first when a submission is still pending (after an error).
void destroyRecorded(const Context& context, RecordedCommands& recorded);

} // namespace glint::gpu
