// glint bench: GPU time of one effect at one setting, from timestamps around each dispatch,
// median of many runs, with the device and driver it ran on. Never asserts a speed.
#include "cli_bench_sssr.h"
#include "cli_commands.h"

#include "glint/glint_depth_pyramid.h"
#include "glint/glint_gbuffer.h"
#include "glint/glint_shadow_denoiser.h"

#include <gpu/gpu_context.h>
#include <gpu/gpu_effect_runner.h>
#include <gpu/gpu_sustained.h>
#include <gpu/gpu_transfer.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
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

// An application-side image the effect reads.
struct Input {
    std::string name;
    VkFormat format = VK_FORMAT_UNDEFINED;
    uint32_t channels = 1;
    std::vector<float> texels;
};

struct Setup {
    EffectPlan plan;
    std::vector<Input> inputs;
};

// 1-sample visibility: a soft-edged band of shadow with per-pixel noise, so the denoiser's
// tiles are a realistic mix of lit, shadowed and penumbra.
std::vector<float> noisyVisibility(uint32_t width, uint32_t height) {
    std::vector<float> visibility(std::size_t{width} * height);
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) {
            const float u = static_cast<float>(x) / static_cast<float>(width);
            const float lit = std::clamp((u - 0.3f) * 4.0f, 0.0f, 1.0f);
            uint32_t hash = (x * 73856093u) ^ (y * 19349663u);
            hash ^= hash >> 13;
            hash *= 0x5bd1e995u;
            hash ^= hash >> 15;
            const float random = static_cast<float>(hash & 0xFFFFu) / 65535.0f;
            visibility[std::size_t{y} * width + x] = random < lit ? 1.0f : 0.0f;
        }
    return visibility;
}

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
        setup.inputs.push_back({"depth", VK_FORMAT_R32_SFLOAT, 1, syntheticDepth(size.width, size.height)});
    } else if (options.effect == "roughness") {
        RoughnessExtractionDesc desc;
        desc.size = size;
        desc.materialChannel = 1;
        if (planRoughnessExtraction(desc, setup.plan, &error) != Result::Ok)
            throw std::invalid_argument(error);
        Input material{"material", VK_FORMAT_R32G32B32A32_SFLOAT, 4, {}};
        for (float value : syntheticDepth(size.width, size.height))
            material.texels.insert(material.texels.end(), {value, value, value, 1.0f});
        setup.inputs.push_back(std::move(material));
    } else if (options.effect == "shadow_denoiser") {
        ShadowDenoiserDesc desc;
        desc.size = size;
        desc.frameIndex = 1;
        if (planShadowDenoiser(desc, setup.plan, &error) != Result::Ok) throw std::invalid_argument(error);
        const std::vector<float> depth = syntheticDepth(size.width, size.height);
        Input normals{"shadow_normals", VK_FORMAT_R32G32B32A32_SFLOAT, 4, {}};
        for (std::size_t i = 0; i < depth.size(); ++i)
            normals.texels.insert(normals.texels.end(), {0.0f, 1.0f, 0.0f, 0.0f});
        setup.inputs.push_back(
            {"shadow_visibility", VK_FORMAT_R32_SFLOAT, 1, noisyVisibility(size.width, size.height)});
        setup.inputs.push_back({"shadow_depth", VK_FORMAT_R32_SFLOAT, 1, depth});
        setup.inputs.push_back({"shadow_previous_depth", VK_FORMAT_R32_SFLOAT, 1, depth});
        setup.inputs.push_back(std::move(normals));
        setup.inputs.push_back(
            {"shadow_motion", VK_FORMAT_R32G32_SFLOAT, 2, std::vector<float>(depth.size() * 2, 0.0f)});
    } else {
        throw std::invalid_argument("bench: unknown effect '" + options.effect +
                                    "' (depth_pyramid, roughness, shadow_denoiser, sssr)");
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
    if (options.effect == "sssr") {
        int code = kExitUsage;
        try {
            code = runBenchSssr(options, context);
        } catch (...) {
            gpu::destroyContext(context);
            throw;
        }
        gpu::destroyContext(context);
        const uint32_t errors = context.validation ? context.validation->errors.load() : 0u;
        if (errors > 0) std::fprintf(stderr, "glint: %u validation errors\n", errors);
        return errors > 0 ? kExitCheckFailed : code;
    }
    Setup setup = setupEffect(options);

    std::vector<vk::Image> inputs;
    std::map<std::string, const vk::Image*> external;
    inputs.reserve(setup.inputs.size());
    for (const Input& input : setup.inputs) {
        inputs.push_back(vk::createImage2D(context.device, options.width, options.height, input.format));
        gpu::uploadImage(context, inputs.back(), input.texels, input.channels);
        external[input.name] = &inputs.back();
    }
    std::vector<std::string> passes;
    std::vector<std::vector<double>> times; // times[run][pass]
    {
        // Owned resources start at zero: histories hold finite values when the timed frames
        // do not reset them.
        gpu::EffectRunner runner(context, setup.plan);
        vk::ResourceTable table;
        table.images = external;
        // Warm-up runs settle pipeline creation; the measured runs are sustained
        // (gpu::timeSustained) so that the clocks follow the load.
        for (uint32_t run = 0; run < std::min(options.runs, 10u); ++run) runner.run(setup.plan, table);
        passes = gpu::passNames(setup.plan);
        if (context.device.timestamps) {
            runner.beginFrames();
            times = gpu::timeSustained(context, gpu::kSustainedFramesPerBuffer,
                                       gpu::sustainedSubmissions(options.runs),
                                       static_cast<uint32_t>(2 * passes.size()),
                                       [&](VkCommandBuffer cmd, gpu::TimestampPool& timestamps, uint32_t) {
                                           runner.record(cmd, setup.plan, table, &timestamps);
                                       })
                        .frames;
            times.resize(options.runs);
        }
    }
    const auto median = [&](std::size_t pass) {
        std::vector<double> values;
        for (const auto& run : times) values.push_back(run.at(pass));
        std::sort(values.begin(), values.end());
        return values.empty() ? -1.0 : values[values.size() / 2];
    };

    std::printf("device: %s, driver %s %s\n", context.info.name.c_str(), context.info.driverName.c_str(),
                context.info.driverInfo.c_str());
    std::printf("effect %s at %ux%u, %u runs%s%s\n", options.effect.c_str(), options.width, options.height,
                options.runs, options.reversed ? ", reversed depth" : "",
                options.farthest ? ", closest+farthest" : "");
    if (options.effect == "depth_pyramid")
        std::printf("levels %s%s\n", options.levels ? std::to_string(options.levels).c_str() : "full chain",
                    options.skipLevel0 ? ", level 0 not copied" : "");
    for (std::size_t pass = 0; pass < passes.size(); ++pass) {
        std::vector<double> values;
        for (const auto& run : times) values.push_back(run.at(pass));
        std::sort(values.begin(), values.end());
        if (values.empty()) {
            std::printf("  %-20s no timestamps on this queue\n", passes[pass].c_str());
            continue;
        }
        std::printf("  %-20s median %9.2f us   min %9.2f us   p90 %9.2f us\n", passes[pass].c_str(),
                    1000.0 * median(pass), 1000.0 * values.front(), 1000.0 * values[values.size() * 9 / 10]);
    }

    if (passes.size() > 1 && !times.empty()) {
        double total = 0.0;
        for (std::size_t pass = 0; pass < passes.size(); ++pass) total += median(pass);
        std::printf("  %-20s %9.2f us (sum of the medians)\n", "all passes", 1000.0 * total);
    }

    for (vk::Image& input : inputs) vk::destroyImage(context.device, input);
    gpu::destroyContext(context);
    const uint32_t errors = context.validation ? context.validation->errors.load() : 0u;
    if (errors > 0) std::fprintf(stderr, "glint: %u validation errors\n", errors);
    return errors > 0 ? kExitCheckFailed : kExitOk;
}

} // namespace glint::cli
