// Sustained timing (gpu::timeSustained): two command buffers recorded once, resubmitted
// alternately, with a warm-up whose frames are discarded.
#include "support/gpu_test_context.h"

#include <gpu/gpu_sustained.h>

#include "glint/vulkan/vk_resources.h"

#include <catch2/catch.hpp>

#include <chrono>

using namespace glint;

namespace {

// One frame: two timed fills of `buffer`, each ordered after every earlier transfer write
// (earlier frames and earlier submissions included).
void recordFills(VkCommandBuffer cmd, gpu::TimestampPool& timestamps, const vk::Buffer& buffer,
                 uint32_t value) {
    for (uint32_t fill = 0; fill < 2; ++fill) {
        VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        barrier.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1,
                             &barrier, 0, nullptr, 0, nullptr);
        gpu::writeTimestamp(cmd, timestamps, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT);
        vkCmdFillBuffer(cmd, buffer.buffer, 0, VK_WHOLE_SIZE, value + fill);
        gpu::writeTimestamp(cmd, timestamps, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);
    }
}

} // namespace

TEST_CASE("sustained timing records two buffers once and measures every submitted frame", "[gpu]") {
    const gpu::Context& context = test::testContext();
    if (!context.device.timestamps) GLINT_SKIP("the queue cannot write timestamps");
    vk::Buffer buffer = vk::createBuffer(context.device, 1 << 20, 0, vk::MemoryUse::DeviceLocal);
    std::vector<uint32_t> recorded;
    const auto start = std::chrono::steady_clock::now();
    const gpu::SustainedTimes times = gpu::timeSustained(
        context, 3, 5, 4,
        [&](VkCommandBuffer cmd, gpu::TimestampPool& timestamps, uint32_t frame) {
            recorded.push_back(frame);
            recordFills(cmd, timestamps, buffer, frame);
        },
        50.0);
    const std::chrono::duration<double, std::milli> elapsed = std::chrono::steady_clock::now() - start;

    CHECK(recorded == std::vector<uint32_t>{0, 1, 2, 3, 4, 5}); // each buffer's frames, recorded once
    REQUIRE(times.frames.size() == 15);                         // 3 frames x 5 measured submissions
    for (const std::vector<double>& frame : times.frames) {
        REQUIRE(frame.size() == 2);
        for (double ms : frame) {
            CHECK(ms >= 0.0);
            CHECK(ms < 60e3);
        }
    }
    CHECK(elapsed.count() >= 50.0); // the warm-up ran before anything was measured
    CHECK(times.wallMilliseconds > 0.0);
    CHECK(times.wallMilliseconds <= elapsed.count() - 50.0 + 1e-3);

    vk::destroyBuffer(context.device, buffer);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("sustained timing refuses what it cannot measure", "[gpu]") {
    const gpu::Context& context = test::testContext();
    if (!context.device.timestamps) GLINT_SKIP("the queue cannot write timestamps");
    vk::Buffer buffer = vk::createBuffer(context.device, 4096, 0, vk::MemoryUse::DeviceLocal);
    const auto fills = [&](VkCommandBuffer cmd, gpu::TimestampPool& timestamps, uint32_t frame) {
        recordFills(cmd, timestamps, buffer, frame);
    };
    CHECK_THROWS_AS(gpu::timeSustained(context, 2, 1, 4, fills, 0.0), std::invalid_argument);
    CHECK_THROWS_AS(gpu::timeSustained(context, 0, 2, 4, fills, 0.0), std::invalid_argument);
    CHECK_THROWS_AS(gpu::timeSustained(context, 2, 2, 3, fills, 0.0), std::invalid_argument);
    // A frame that writes other than the declared timestamps is a caller's bug, found before submitting.
    CHECK_THROWS_AS(gpu::timeSustained(context, 2, 2, 2, fills, 0.0), std::out_of_range);
    CHECK_THROWS_AS(gpu::timeSustained(context, 2, 2, 8, fills, 0.0), std::logic_error);
    vk::destroyBuffer(context.device, buffer);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
