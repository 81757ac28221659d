// glint simulate: a scene file -> a capture sequence (docs/scenes.md). Prints the layers and
// passes it computed and their GPU time. Next to the sequence's manifest it writes
// simulation.json: the scene file, size, frame count, reference samples per pixel and seed the
// capture was simulated with (what `glint run` copies into its summary and the demo keys its
// cache on).
#include "cli_commands.h"

#include "capture/sequence_io.h"
#include "scene/scene_file.h"
#include "scene/scene_simulate.h"

#include <gpu/gpu_context.h>

#include <CLI/CLI.hpp>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace glint::cli {

void addSimulateOptions(CLI::App& command, SimulateOptions& options) {
    command.add_option("scene", options.scenePath, "scene file, e.g. harness/scenes/glossy_room.toml")
        ->required();
    command.add_option("--out", options.outDir, "output sequence folder")->required();
    command.add_option("--size", options.size, "override the resolution, WxH");
    command.add_option("--frame-count", options.frames, "override the frame count");
    command.add_option("--spp", options.spp, "override the reference samples per pixel (per frame)");
    command
        .add_option("--noise-target", options.noiseTarget,
                    "override the reflection reference's noise target: past --spp, a frame samples the "
                    "pixels whose relative standard error is at or above it (0: none)")
        ->check(CLI::Range(0.0, 1.0));
    command.add_option("--max-spp", options.maxSpp,
                       "override the most reflection reference samples a pixel takes in a frame with a "
                       "noise target");
    command
        .add_option("--noise-target-alpha-below", options.noiseTargetAlphaBelow,
                    "override the GGX alpha below which pixels take samples for the noise target")
        ->check(CLI::Range(0.0, 1.0));
    command.add_option("--seed", options.seed, "override the scene's seed");
}

int runSimulate(SimulateOptions options, bool validate) {
    if (!options.size.empty() &&
        std::sscanf(options.size.c_str(), "%ux%u", &options.width, &options.height) != 2)
        throw std::invalid_argument("simulate: --size must read WxH, e.g. 1920x1080");
    options.validate = validate;
    scene::Scene scene = scene::loadScene(options.scenePath);
    if (options.width > 0 && options.height > 0) {
        scene.width = options.width;
        scene.height = options.height;
    }
    if (options.frames > 0) scene.frameCount = options.frames;
    if (options.spp > 0) scene.reference.samplesPerPixel = options.spp;
    if (options.noiseTarget) scene.reference.noiseTarget = *options.noiseTarget;
    if (options.maxSpp) scene.reference.maxSamplesPerPixel = *options.maxSpp;
    if (options.noiseTargetAlphaBelow) scene.reference.noiseTargetAlphaBelow = *options.noiseTargetAlphaBelow;
    if (options.seed) scene.seed = *options.seed;

    gpu::ContextOptions contextOptions;
    contextOptions.validation = options.validate;
    contextOptions.synchronizationValidation = options.validate;
    gpu::Context context = gpu::createContext(contextOptions);
    int exitCode = kExitOk;
    try {
        const scene::Simulation sim = scene::simulate(context, scene);
        for (const std::string& warning : sim.warnings) std::fprintf(stderr, "glint: %s\n", warning.c_str());
        const capture::Environment* environment = sim.environment ? &*sim.environment : nullptr;
        capture::writeSequence(options.outDir, sim.frames, scene.frameRate, environment, options.scenePath);
        const nlohmann::json simulation{
            {"scene", options.scenePath},
            {"width", scene.width},
            {"height", scene.height},
            {"frames", scene.frameCount},
            {"referenceSpp", scene.reference.samplesPerPixel},
            {"referenceSamples", sim.referenceSamples},
            {"referenceNoiseTarget", scene.reference.noiseTarget},
            {"referenceMaxSpp", scene::maxReferenceSamples(scene.reference)},
            {"referenceNoiseTargetAlphaBelow", scene.reference.noiseTargetAlphaBelow},
            {"seed", scene.seed}};
        const std::filesystem::path simulationPath =
            std::filesystem::path(options.outDir) / "simulation.json";
        std::ofstream simulationFile(simulationPath);
        simulationFile << simulation.dump(2) << "\n";
        if (!simulationFile)
            throw std::runtime_error("simulate: " + simulationPath.string() + ": cannot write");

        std::printf("device: %s, driver %s %s\n", context.info.name.c_str(), context.info.driverName.c_str(),
                    context.info.driverInfo.c_str());
        std::printf("scene %s: %ux%u, %u frame(s), %zu primitives, effects:", options.scenePath.c_str(),
                    scene.width, scene.height, scene.frameCount, sim.primitives);
        for (const std::string& effect : scene::captureEffects(scene)) std::printf(" %s", effect.c_str());
        std::printf("\nlayers:");
        for (const std::string& layer : sim.layers) std::printf(" %s", layer.c_str());
        std::printf("%s\npasses (GPU time, all frames):\n", environment ? " (+ environment.exr)" : "");
        double total = 0.0;
        for (const scene::PassTime& pass : sim.passes) {
            if (pass.milliseconds < 0.0) {
                std::printf("  %-22s no timestamps on this queue\n", pass.pass.c_str());
                continue;
            }
            total += pass.milliseconds;
            std::printf("  %-22s %10.3f ms\n", pass.pass.c_str(), pass.milliseconds);
        }
        std::printf("  %-22s %10.3f ms\nwrote %s\n", "total", total, options.outDir.c_str());
    } catch (...) {
        gpu::destroyContext(context);
        throw;
    }
    gpu::destroyContext(context);
    const uint32_t errors = context.validation ? context.validation->errors.load() : 0u;
    if (errors > 0) {
        std::fprintf(stderr, "glint: %u validation errors\n", errors);
        exitCode = kExitCheckFailed;
    }
    return exitCode;
}

} // namespace glint::cli
