#include "gpu/gpu_plan_runner.h"

#include "gpu/gpu_timestamps.h"
#include "gpu/gpu_transfer.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace glint::gpu {

PlanResources createPlanResources(const Context& context, const EffectPlan& plan, float imageFill) {
    PlanResources resources;
    try {
        for (const ImageDesc& desc : plan.images) {
            vk::Image& image = resources.images[desc.name];
            image = vk::createImage2D(context.device, desc.width, desc.height, vk::toVkFormat(desc.format),
                                      desc.mipLevels);
            VkClearColorValue fill{};
            const float value = imageFill < 0.0f ? std::numeric_limits<float>::quiet_NaN() : imageFill;
            if (desc.format == Format::R32Uint)
                fill.uint32[0] = 0;
            else
                for (float& channel : fill.float32) channel = value;
            clearImage(context, image, fill);
        }
        for (const BufferDesc& desc : plan.buffers) {
            VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
            if (desc.indirectArgs) usage |= VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT;
            vk::Buffer& buffer = resources.buffers[desc.name];
            buffer = vk::createBuffer(context.device, desc.size, usage, vk::MemoryUse::DeviceLocal);
            const std::vector<std::byte> zeros(desc.size);
            uploadBuffer(context, buffer, std::span<const std::byte>(zeros));
        }
    } catch (...) {
        destroyPlanResources(context, resources);
        throw;
    }
    return resources;
}

void destroyPlanResources(const Context& context, PlanResources& resources) {
    for (auto& [name, image] : resources.images) vk::destroyImage(context.device, image);
    for (auto& [name, buffer] : resources.buffers) vk::destroyBuffer(context.device, buffer);
    resources = PlanResources{};
}

vk::ResourceTable resourceTable(const PlanResources& owned,
                                const std::map<std::string, const vk::Image*>& external) {
    vk::ResourceTable table;
    table.images = external;
    for (const auto& [name, image] : owned.images) table.images[name] = &image;
    for (const auto& [name, buffer] : owned.buffers) table.buffers[name] = &buffer;
    return table;
}

PlanTimings executePlan(const Context& context, vk::Executor& executor, const EffectPlan& plan,
                        const vk::ResourceTable& resources, uint32_t runs) {
    PlanTimings timings;
    for (const Pass& pass : plan.passes) timings.passes.push_back(pass.name);
    const bool timed = context.device.timestamps;
    TimestampPool pool;
    if (timed) pool = createTimestampPool(context.device, static_cast<uint32_t>(2 * plan.passes.size()));
    try {
        vk::PassHooks hooks;
        if (timed) {
            // Top of pipe before and bottom of pipe after: the dispatch's own duration, with
            // the barriers before it outside the interval.
            hooks.beforeDispatch = [&](VkCommandBuffer cmd, std::size_t) {
                writeTimestamp(cmd, pool, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT);
            };
            hooks.afterDispatch = [&](VkCommandBuffer cmd, std::size_t) {
                writeTimestamp(cmd, pool, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);
            };
        }
        for (uint32_t run = 0; run < runs; ++run) {
            vk::resetExecutor(executor);
            submitAndWait(context, [&](VkCommandBuffer cmd) {
                if (timed) resetTimestamps(cmd, pool);
                vk::recordPlan(executor, cmd, plan, resources, hooks);
            });
            if (!timed) continue;
            const std::vector<uint64_t> ticks = readTimestamps(context.device, pool);
            std::vector<double> perPass;
            for (std::size_t pass = 0; 2 * pass + 1 < ticks.size(); ++pass)
                perPass.push_back(timestampMilliseconds(pool, ticks[2 * pass], ticks[2 * pass + 1]));
            timings.times.push_back(std::move(perPass));
        }
    } catch (...) {
        if (timed) destroyTimestampPool(context.device, pool);
        throw;
    }
    if (timed) destroyTimestampPool(context.device, pool);
    return timings;
}

double medianMilliseconds(const PlanTimings& timings, std::size_t pass) {
    std::vector<double> values;
    for (const std::vector<double>& run : timings.times)
        if (pass < run.size()) values.push_back(run[pass]);
    if (values.empty()) return -1.0;
    std::sort(values.begin(), values.end());
    const std::size_t middle = values.size() / 2;
    return values.size() % 2 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

} // namespace glint::gpu
