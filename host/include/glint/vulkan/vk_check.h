// Error handling for the Vulkan backend. Internal code throws VulkanError carrying the
// failing expression, file, line and VkResult name; the public API turns it into a result
// code and tools print it and exit non-zero.
#pragma once

#include <vulkan/vulkan.h>

#include <source_location>
#include <stdexcept>
#include <string>

namespace glint::vk {

struct VulkanError : std::runtime_error {
    VkResult result;
    VulkanError(VkResult r, const std::string& message) : std::runtime_error(message), result(r) {}
};

const char* resultName(VkResult result);

// Throws VulkanError("<file>:<line>: <expr> failed: VK_ERROR_...") unless result is VK_SUCCESS.
void check(VkResult result, const char* expression,
           std::source_location where = std::source_location::current());

} // namespace glint::vk

#define GLINT_VK_CHECK(expr) ::glint::vk::check((expr), #expr)
