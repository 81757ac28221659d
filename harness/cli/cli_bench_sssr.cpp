// glint bench sssr: the reflections effect on a simulated scene (default: the glossy room)
// at the requested size, per-pass GPU times with the traced-pixel fraction next to them.
// Settings come from --set name=value, so the same runs can sweep options.
#include "cli_bench_sssr.h"

#include "core/camera.h"
#include "replay/replay_settings.h"
#include "replay/replay_sssr.h"
#include "scene/scene_file.h"
#include "scene/scene_simulate.h"

#include <gpu/gpu_sssr_runner.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace glint::cli {
namespace {

// With debugOutput: how the traced rays ended and how many iterations they took.
void printRayClasses(const gpu::SssrFrameOutputs& out) {
    static const char* const kNames[] = {"hit",    "escaped",  "budget",    "occupancy",
                                         "behind", "rejected", "degenerate"};
    std::size_t classes[7] = {};
    std::vector<double> iterations;
    for (std::uint32_t entry : out.rayList) {
        const std::size_t x = entry & 0x7FFFu, y = (entry >> 15) & 0x3FFFu;
        const float* info = &out.rayInfo[4 * (y * out.width + x)];
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

    SssrDesc desc;
    gpu::SssrFrameInputs inputs;
    replay::sssrFromFrame(simulation.frames.at(0), simulation.environment.value(), desc, inputs);
    const replay::EffectSettings settings = replay::parseSettings(options.settings);
    replay::copySssrTunables(settings.sssr, desc);
    desc.storeRays = replay::needsSssrRays(settings);
    if (desc.materialChannel != 0)
        throw std::invalid_argument("bench: roughness must come from material channel 0");
    gpu::SssrRunner runner(context, desc, /*compactInputs=*/true);
    runner.upload(inputs);
    const std::vector<std::string> passes =
        runner.passNames(desc, desc.denoise, settings.denoiser.spatialPath);
    // With denoise: a static camera, so last frame's view-projection is this frame's.
    ReflectionsDenoiserDesc denoiser;
    denoiser.size = desc.size;
    denoiser.projection = desc.projection;
    denoiser.viewFromWorld = desc.viewFromWorld;
    denoiser.depth = desc.depth;
    denoiser.nearPlane = desc.nearPlane;
    denoiser.farPlane = desc.farPlane;
    denoiser.vulkanNdc = desc.vulkanNdc;
    denoiser.normalUnpackMul = desc.normalUnpackMul;
    denoiser.normalUnpackAdd = desc.normalUnpackAdd;
    denoiser.roughnessThreshold = desc.roughnessThreshold;
    denoiser.mirrorThreshold = desc.mirrorThreshold;
    denoiser.halfPrecisionStorage = desc.halfPrecisionStorage;
    denoiser.previousClipFromWorld = core::multiply(desc.projection, desc.viewFromWorld);
    replay::copyDenoiserTunables(settings.denoiser, denoiser);
    std::vector<std::vector<double>> times(passes.size());
    for (std::uint32_t run = 0; run < std::min(options.runs, 10u) + options.runs; ++run) {
        desc.frameIndex = run;
        denoiser.frameIndex = run;
        denoiser.resetHistory = run == 0;
        std::vector<double> timing;
        runner.run(desc, &timing, desc.denoise ? &denoiser : nullptr);
        if (run < std::min(options.runs, 10u)) continue; // warm-up
        for (std::size_t pass = 0; pass < std::min(timing.size(), passes.size()); ++pass)
            times[pass].push_back(timing[pass]);
    }
    const gpu::SssrFrameOutputs out = runner.readback();
    const double pixels = static_cast<double>(options.width) * options.height;

    std::printf("device: %s, driver %s %s, subgroup %u\n", context.info.name.c_str(),
                context.info.driverName.c_str(), context.info.driverInfo.c_str(),
                context.device.subgroupSize);
    std::printf("effect sssr on %s at %ux%u, %u runs\n", scene.file.filename().string().c_str(),
                options.width, options.height, options.runs);
    for (const std::string& setting : options.settings) std::printf("  set %s\n", setting.c_str());
    std::printf("inputs: R32F depth, RGBA16F normals and colour, R16F roughness, RG16F motion\n");
    std::printf("traced pixels %.1f %% (%u rays), tiles with glossy pixels %u\n",
                100.0 * out.counters[1] / pixels, out.counters[1], out.counters[3]);
    if (!out.rayInfo.empty()) printRayClasses(out);
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
