// The messenger must really catch mistakes, or every "no validation errors" check is hollow.
// Each test provokes errors in a context of its own, never in the shared test context.
#include "support/gpu_test_context.h"

#include <gpu/gpu_context.h>

#include "glint/vulkan/vk_resources.h"

#include <catch2/catch.hpp>

#include <string>

using namespace glint;

namespace {

gpu::Context createProvokedContext() {
    gpu::ContextOptions options;
    options.validation = true;
    options.synchronizationValidation = true;
    options.printValidationErrors = false; // the errors below are expected
    return gpu::createContext(options);
}

bool anyMessageContains(gpu::ValidationStats& stats, const std::string& text) {
    for (const std::string& message : gpu::validationMessages(stats)) {
        if (message.find(text) != std::string::npos) return true;
    }
    return false;
}

} // namespace

TEST_CASE("the validation messenger counts an invalid Vulkan call as an error", "[gpu][validation]") {
    gpu::Context context = createProvokedContext();
    REQUIRE(context.validation->errors == 0);

    // usage 0 violates VUID-VkBufferCreateInfo-usage-requiredbitmask; the driver still creates it.
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = 256;
    info.usage = 0;
    VkBuffer buffer = VK_NULL_HANDLE;
    const VkResult result = vkCreateBuffer(context.device.device, &info, nullptr, &buffer);
    if (result == VK_SUCCESS) vkDestroyBuffer(context.device.device, buffer, nullptr);

    CHECK(context.validation->errors > 0);
    CHECK(anyMessageContains(*context.validation, "VUID-VkBufferCreateInfo-usage"));
    gpu::destroyContext(context);
}

TEST_CASE("synchronization validation reports two unordered writes to one buffer", "[gpu][validation]") {
    gpu::Context context = createProvokedContext();
    vk::Buffer buffer = vk::createBuffer(context.device, 4096, 0, vk::MemoryUse::DeviceLocal);
    gpu::submitAndWait(context, [&](VkCommandBuffer cmd) {
        vkCmdFillBuffer(cmd, buffer.buffer, 0, VK_WHOLE_SIZE, 1);
        vkCmdFillBuffer(cmd, buffer.buffer, 0, VK_WHOLE_SIZE, 2); // no barrier: write-after-write
    });
    vk::destroyBuffer(context.device, buffer);

    CHECK(context.validation->errors > 0);
    CHECK(anyMessageContains(*context.validation, "SYNC-HAZARD-WRITE-AFTER-WRITE"));
    gpu::destroyContext(context);
}

TEST_CASE("a Vulkan object left alive when the context is destroyed is reported", "[gpu][validation]") {
    gpu::Context context = createProvokedContext();
    vk::Buffer leaked = vk::createBuffer(context.device, 64, 0, vk::MemoryUse::DeviceLocal);
    (void)leaked;
    REQUIRE(context.validation->errors == 0);
    gpu::destroyContext(context);
    // destroyContext keeps the statistics precisely so that this report can be read.
    CHECK(context.validation->errors > 0);
}
