#include "gbuffer/roughness_runner.h"

#include "glint/vulkan/vk_executor.h"

#include <gpu/gpu_timestamps.h>
#include <gpu/gpu_transfer.h>

#include <catch2/catch.hpp>

namespace glint::test {

RoughnessRun runRoughnessExtraction(gpu::Context& context, const std::vector<float>& material,
                                    const RoughnessExtractionDesc& desc) {
    const vk::Device& device = context.device;
    EffectPlan plan;
    std::string error;
    REQUIRE(planRoughnessExtraction(desc, plan, &error) == Result::Ok);

    vk::Image materialImage =
        vk::createImage2D(device, desc.size.width, desc.size.height, VK_FORMAT_R32G32B32A32_SFLOAT);
    vk::Image alphaImage =
        vk::createImage2D(device, desc.size.width, desc.size.height,
                          desc.halfPrecisionOutput ? VK_FORMAT_R16_SFLOAT : VK_FORMAT_R32_SFLOAT);
    gpu::uploadImage(context, materialImage, material, 4);
    // The output starts as NaN so that a pixel the pass forgets to write cannot pass a check.
    VkClearColorValue nan{};
    nan.uint32[0] = 0x7FC00000u;
    gpu::clearImage(context, alphaImage, nan);

    vk::Executor executor = vk::createExecutor(device);
    gpu::TimestampPool timestamps;
    if (device.timestamps) timestamps = gpu::createTimestampPool(device, 2);
    vk::ResourceTable resources;
    resources.images = {{"material", &materialImage}, {"roughness", &alphaImage}};
    vk::PassHooks hooks;
    if (device.timestamps) {
        hooks.beforeDispatch = [&](VkCommandBuffer cmd, std::size_t) {
            gpu::writeTimestamp(cmd, timestamps, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT);
        };
        hooks.afterDispatch = [&](VkCommandBuffer cmd, std::size_t) {
            gpu::writeTimestamp(cmd, timestamps, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);
        };
    }
    gpu::submitAndWait(context, [&](VkCommandBuffer cmd) {
        if (device.timestamps) gpu::resetTimestamps(cmd, timestamps);
        vk::recordPlan(executor, cmd, plan, resources, hooks);
    });

    RoughnessRun run;
    if (device.timestamps) {
        const std::vector<uint64_t> ticks = gpu::readTimestamps(device, timestamps);
        REQUIRE(ticks.size() == 2);
        run.dispatchMs = gpu::timestampMilliseconds(timestamps, ticks[0], ticks[1]);
    }
    run.alpha = gpu::readbackImage(context, alphaImage);

    if (device.timestamps) gpu::destroyTimestampPool(device, timestamps);
    vk::destroyExecutor(executor);
    vk::destroyImage(device, alphaImage);
    vk::destroyImage(device, materialImage);
    return run;
}

} // namespace glint::test
