// glint bench: GPU time of one effect at one setting, from timestamps around each dispatch,
// median of many runs, with the device and driver it ran on. Never asserts a speed.
#include "cli_commands.h"

#include "glint/glint_depth_pyramid.h"
#include "glint/glint_gbuffer.h"

#include <gpu/gpu_context.h>
#include <gpu/gpu_plan_runner.h>
#include <gpu/gpu_transfer.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace glint::cli {
namespace {

// Smooth depth with some structure: a ramp plus ripples, all inside (0, 1).
std::vector<float> syntheticDepth(uint32_t width, uint32_t height) {
    std::vector<float> depth(std::size_t{width} * height);
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x)
            depth[std::size_t{y} * width + x] = 0.5f + 0.3f * std::sin(0.05f * static_cast<float>(x)) *
                                                           std::cos(0.07f * static_cast<float>(y));
    return depth;
}

struct Setup {
    EffectPlan plan;
    std::string inputName;
    VkFormat inputFormat = VK_FORMAT_UNDEFINED;
    uint32_t inputChannels = 1;
    std::vector<float> input;
};

Setup setupEffect(const BenchOptions& options) {
    Setup setup;
    std::string error;
    const Extent2D size{options.width, options.height};
    if (options.effect == "depth_pyramid") {
        DepthPyramidDesc desc;
        desc.size = size;
        desc.depth = options.reversed ? DepthConvention::Reversed : DepthConvention::Standard;
        desc.channels =
            options.farthest ? DepthPyramidChannels::ClosestAndFarthest : DepthPyramidChannels::Closest;
        desc.levelCount = options.levels;
        desc.copyLevel0 = !options.skipLevel0;
        if (planDepthPyramid(desc, setup.plan, &error) != Result::Ok) throw std::invalid_argument(error);
        setup.inputName = "depth";
        setup.inputFormat = VK_FORMAT_R32_SFLOAT;
        setup.input = syntheticDepth(size.width, size.height);
    } else if (options.effect == "roughness") {
        RoughnessExtractionDesc desc;
        desc.size = size;
        desc.materialChannel = 1;
        if (planRoughnessExtraction(desc, setup.plan, &error) != Result::Ok)
            throw std::invalid_argument(error);
        setup.inputName = "material";
        setup.inputFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
        setup.inputChannels = 4;
        const std::vector<float> ramp = syntheticDepth(size.width, size.height);
        for (float value : ramp) setup.input.insert(setup.input.end(), {value, value, value, 1.0f});
    } else {
        throw std::invalid_argument("bench: unknown effect '" + options.effect +
                                    "' (depth_pyramid, roughness)");
    }
    return setup;
}

} // namespace

int runBench(const BenchOptions& options) {
    if (options.width == 0 || options.height == 0 || options.runs == 0)
        throw std::invalid_argument("bench: size and runs must be positive");
    gpu::ContextOptions contextOptions;
    contextOptions.validation = options.validate;
    contextOptions.synchronizationValidation = options.validate;
    gpu::Context context = gpu::createContext(contextOptions);
    Setup setup = setupEffect(options);

    vk::Image input = vk::createImage2D(context.device, options.width, options.height, setup.inputFormat);
    gpu::uploadImage(context, input, setup.input, setup.inputChannels);
    gpu::PlanResources owned = gpu::createPlanResources(context, setup.plan);
    vk::Executor executor = vk::createExecutor(context.device);
    const vk::ResourceTable table = gpu::resourceTable(owned, {{setup.inputName, &input}});

    // Warm-up runs settle clocks and pipeline creation before anything is measured.
    gpu::executePlan(context, executor, setup.plan, table, std::min(options.runs, 10u));
    const gpu::PlanTimings timings = gpu::executePlan(context, executor, setup.plan, table, options.runs);

    std::printf("device: %s, driver %s %s\n", context.info.name.c_str(), context.info.driverName.c_str(),
                context.info.driverInfo.c_str());
    std::printf("effect %s at %ux%u, %u runs%s%s\n", options.effect.c_str(), options.width, options.height,
                options.runs, options.reversed ? ", reversed depth" : "",
                options.farthest ? ", closest+farthest" : "");
    if (options.effect == "depth_pyramid")
        std::printf("levels %s%s\n", options.levels ? std::to_string(options.levels).c_str() : "full chain",
                    options.skipLevel0 ? ", level 0 not copied" : "");
    for (std::size_t pass = 0; pass < timings.passes.size(); ++pass) {
        std::vector<double> values;
        for (const auto& run : timings.times) values.push_back(run.at(pass));
        std::sort(values.begin(), values.end());
        if (values.empty()) {
            std::printf("  %-20s no timestamps on this queue\n", timings.passes[pass].c_str());
            continue;
        }
        std::printf("  %-20s median %9.2f us   min %9.2f us   p90 %9.2f us\n", timings.passes[pass].c_str(),
                    1000.0 * gpu::medianMilliseconds(timings, pass), 1000.0 * values.front(),
                    1000.0 * values[values.size() * 9 / 10]);
    }

    vk::destroyExecutor(executor);
    gpu::destroyPlanResources(context, owned);
    vk::destroyImage(context.device, input);
    gpu::destroyContext(context);
    const uint32_t errors = context.validation ? context.validation->errors.load() : 0u;
    if (errors > 0) std::fprintf(stderr, "glint: %u validation errors\n", errors);
    return errors > 0 ? kExitCheckFailed : kExitOk;
}

} // namespace glint::cli
