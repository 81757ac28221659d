// GPU timestamps around real work. On a queue without timestamps the tests are skips, not passes.
#include "support/gpu_test_context.h"

#include <gpu/gpu_timestamps.h>

#include "glint/vulkan/vk_resources.h"

#include <catch2/catch.hpp>

using namespace glint;

TEST_CASE("timestamps written in order never decrease", "[gpu]") {
    const gpu::Context& context = test::testContext();
    if (!context.device.timestamps) GLINT_SKIP("the queue cannot write timestamps");
    gpu::TimestampPool pool = gpu::createTimestampPool(context.device, 8);
    vk::Buffer buffer = vk::createBuffer(context.device, 1 << 20, 0, vk::MemoryUse::DeviceLocal);

    gpu::submitAndWait(context, [&](VkCommandBuffer cmd) {
        gpu::resetTimestamps(cmd, pool);
        gpu::writeTimestamp(cmd, pool, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT);
        for (uint32_t round = 0; round < 3; ++round) {
            // Real work between the stamps; the barrier orders the fills (no write-after-write hazard).
            vkCmdFillBuffer(cmd, buffer.buffer, 0, VK_WHOLE_SIZE, round);
            VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
            barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
            barrier.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
            vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1,
                                 &barrier, 0, nullptr, 0, nullptr);
            gpu::writeTimestamp(cmd, pool, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);
        }
    });
    const std::vector<uint64_t> ticks = gpu::readTimestamps(context.device, pool);
    REQUIRE(ticks.size() == 4);
    for (size_t i = 1; i < ticks.size(); ++i) {
        INFO("timestamp " << i);
        CHECK(ticks[i] >= ticks[i - 1]);
    }
    const double total = gpu::timestampMilliseconds(pool, ticks.front(), ticks.back());
    CHECK(total >= 0.0);
    CHECK(total < 60e3); // a minute would mean garbage bits, not a slow fill

    vk::destroyBuffer(context.device, buffer);
    gpu::destroyTimestampPool(context.device, pool);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("a full timestamp pool refuses further writes", "[gpu]") {
    const gpu::Context& context = test::testContext();
    if (!context.device.timestamps) GLINT_SKIP("the queue cannot write timestamps");
    gpu::TimestampPool pool = gpu::createTimestampPool(context.device, 1);
    gpu::submitAndWait(context, [&](VkCommandBuffer cmd) {
        gpu::resetTimestamps(cmd, pool);
        gpu::writeTimestamp(cmd, pool, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);
        CHECK_THROWS_AS(gpu::writeTimestamp(cmd, pool, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT),
                        std::out_of_range);
    });
    CHECK(gpu::readTimestamps(context.device, pool).size() == 1);
    gpu::destroyTimestampPool(context.device, pool);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
