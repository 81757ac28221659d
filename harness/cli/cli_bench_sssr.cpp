// glint bench sssr: the reflections effect on a simulated scene (default: the glossy room)
// at the requested size, per-pass GPU times with the traced-pixel fraction next to them.
// Settings come from --set name=value, so the same runs can sweep options.
#include "cli_bench_sssr.h"

#include "replay/replay_frame.h"
#include "replay/replay_settings.h"
#include "scene/scene_file.h"
#include "scene/scene_simulate.h"

#include <gpu/gpu_effect_runner.h>
#include <gpu/gpu_input_images.h>
#include <gpu/gpu_sustained.h>
#include <gpu/gpu_transfer.h>

#include "glint/common/glint_wire_formats.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace glint::cli {
namespace {

// With debugOutput: how the traced rays ended and how many iterations they took.
void printRayClasses(const std::vector<std::uint32_t>& rayList, const std::vector<float>& rayInfo,
                     std::uint32_t width) {
    static const char* const kNames[] = {"hit",    "escaped",  "budget",    "occupancy",
                                         "behind", "rejected", "degenerate"};
    std::size_t classes[7] = {};
    std::vector<double> iterations;
    for (std::uint32_t entry : rayList) {
        const std::size_t x = shared::GLINT_WIRE_RayEntryX(entry), y = shared::GLINT_WIRE_RayEntryY(entry);
        const float* info = &rayInfo[4 * (y * width + x)];
        const auto rayClass = static_cast<std::size_t>(info[2]);
        if (rayClass < 7) ++classes[rayClass];
        iterations.push_back(static_cast<double>(info[3]));
    }
    std::sort(iterations.begin(), iterations.end());
    std::printf("ray classes:");
    for (std::size_t c = 0; c < 7; ++c)
        std::printf(" %s %.1f %%", kNames[c],
                    100.0 * static_cast<double>(classes[c]) /
                        static_cast<double>(std::max<std::size_t>(1, iterations.size())));
    if (!iterations.empty())
        std::printf("\niterations: median %.0f, p90 %.0f, p99 %.0f, max %.0f\n",
                    iterations[iterations.size() / 2], iterations[iterations.size() * 9 / 10],
                    iterations[iterations.size() * 99 / 100], iterations.back());
}

} // namespace

int runBenchSssr(const BenchOptions& options, const gpu::Context& context) {
    scene::Scene scene =
        scene::loadScene(options.scene.empty() ? "harness/scenes/glossy_room.toml" : options.scene);
    if (!scene::needsReflections(scene))
        throw std::invalid_argument("bench: scene '" + scene.file.string() + "' declares no reflections");
    scene.width = options.width;
    scene.height = options.height;
    scene.frameCount = 1;
    scene.reference = {}; // no references: only the inputs are needed
    const scene::Simulation simulation = scene::simulate(context, scene);

    const capture::Frame& frame = simulation.frames.at(0);
    const capture::Environment& environment = simulation.environment.value();
    const EffectDescriptor& effect = *findEffect("reflections");
    const std::vector<std::string> assignments =
        presetThenSettings(options.preset, {"reflections"}, options.settings);
    const SettingValues settings = replay::parseSettings(assignments);
    // A static camera: every run is the first frame again, its histories carried.
    FrameInfo info = replay::frameInfo(frame, environment, 0, true);
    replay::holdCamera(info);
    EffectPlan plan;
    std::string error;
    if (effect.plan(info, settings, plan, &error) != Result::Ok) throw std::invalid_argument(error);
    gpu::InputImages inputs(context, info.size, /*compact=*/true);
    vk::ResourceTable table;
    for (const InputDesc& input : effect.inputs) {
        if (!input.setting.empty() && !settings.flag(input.setting)) continue;
        if (input.kind == InputKind::Environment) {
            inputs.uploadEnvironment(environment.width, environment.height,
                                     replay::environmentTexels(environment));
        } else {
            std::uint32_t channels = 0;
            const std::vector<float> texels = replay::inputTexels(frame, input.kind, channels);
            inputs.upload(input.kind, texels, channels);
        }
        table.images[input.resource] = inputs.find(input.kind);
    }
    gpu::EffectRunner runner(context, plan);
    const std::vector<std::string> passes = gpu::passNames(plan);
    std::vector<std::vector<double>> times(passes.size());
    const std::uint32_t warmup = std::min(options.runs, 10u);
    for (std::uint32_t run = 0; run < warmup; ++run) {
        info.frameIndex = run;
        info.resetHistory = run == 0;
        if (effect.plan(info, settings, plan, &error) != Result::Ok) throw std::invalid_argument(error);
        runner.run(plan, table);
    }
    if (context.device.timestamps) {
        // Sustained, so that the clocks follow the load (gpu::timeSustained).
        runner.beginFrames();
        info.resetHistory = false;
        const gpu::SustainedTimes sustained = gpu::timeSustained(
            context, gpu::kSustainedFramesPerBuffer, gpu::sustainedSubmissions(options.runs),
            static_cast<std::uint32_t>(2 * passes.size()),
            [&](VkCommandBuffer cmd, gpu::TimestampPool& timestamps, std::uint32_t index) {
                info.frameIndex = warmup + index;
                if (effect.plan(info, settings, plan, &error) != Result::Ok)
                    throw std::invalid_argument(error);
                runner.record(cmd, plan, table, &timestamps);
            });
        for (std::size_t run = 0; run < std::min<std::size_t>(sustained.frames.size(), options.runs); ++run)
            for (std::size_t pass = 0; pass < passes.size(); ++pass)
                times[pass].push_back(sustained.frames[run][pass]);
    }
    const std::vector<std::uint32_t> counters = runner.readWords("sssr_counters", 4);
    const double pixels = static_cast<double>(options.width) * options.height;

    std::printf("device: %s, driver %s %s, subgroup %u\n", context.info.name.c_str(),
                context.info.driverName.c_str(), context.info.driverInfo.c_str(),
                context.device.subgroupSize);
    std::printf("effect sssr on %s at %ux%u, %u runs\n", scene.file.filename().string().c_str(),
                options.width, options.height, options.runs);
    for (const std::string& setting : assignments) std::printf("  set %s\n", setting.c_str());
    std::printf("inputs: R32F depth, RGBA16F normals and colour, R16F roughness, RG16F motion\n");
    std::printf("traced pixels %.1f %% (%u rays), tiles with glossy pixels %u\n",
                100.0 * counters[1] / pixels, counters[1], counters[3]);
    if (runner.hasImage("sssr_ray_info"))
        printRayClasses(runner.readWords("sssr_ray_list", counters[1]),
                        gpu::readbackImage(context, runner.image("sssr_ray_info")), options.width);
    double total = 0.0;
    for (std::size_t pass = 0; pass < passes.size(); ++pass) {
        std::vector<double>& values = times[pass];
        if (values.empty()) {
            std::printf("  %-20s no timestamps on this queue\n", passes[pass].c_str());
            continue;
        }
        std::sort(values.begin(), values.end());
        const double median = values[values.size() / 2];
        total += median;
        std::printf("  %-20s median %9.2f us   min %9.2f us   p90 %9.2f us\n", passes[pass].c_str(),
                    1000.0 * median, 1000.0 * values.front(), 1000.0 * values[values.size() * 9 / 10]);
    }
    std::printf("  %-20s %9.2f us (sum of the medians)\n", "all passes", 1000.0 * total);
    return kExitOk;
}

} // namespace glint::cli
