// glint: frame-capture and device tool. Verbs are registered here and implemented one per
// file (cli_<verb>.cpp); later verbs (simulate, run, dump, bench, study, view) join them.
#include "cli_commands.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <stdexcept>

int main(int argc, char** argv) {
    CLI::App app{"glint: reflections and shadow-denoising passes on frame captures"};
    app.require_subcommand(1);
    bool validate = false;
    app.add_flag(
        "--validate", validate,
        "Run under VK_LAYER_KHRONOS_validation (with synchronization validation); any error exits 1");

    CLI::App* devices =
        app.add_subcommand("devices", "List Vulkan devices: driver, subgroup size, float16 support");

    std::string infoPath;
    bool headerOnly = false;
    CLI::App* info = app.add_subcommand("info", "Describe a frame capture (.exr) or a sequence folder");
    info->add_option("capture", infoPath, "frame file or sequence folder")->required();
    info->add_flag("--header-only", headerOnly, "read headers only; skip pixels and non-finite counts");

    glint::cli::BenchOptions bench;
    std::string benchSize = "1920x1080";
    CLI::App* benchCommand =
        app.add_subcommand("bench", "GPU time of one effect (median of timestamped runs)");
    benchCommand->add_option("effect", bench.effect, "depth_pyramid | roughness | shadow_denoiser | sssr")
        ->required();
    benchCommand->add_option("--size", benchSize, "render size WxH")->capture_default_str();
    benchCommand->add_option("--runs", bench.runs, "measured runs")->capture_default_str();
    benchCommand->add_option("--levels", bench.levels, "depth pyramid levels (0 = full chain)");
    benchCommand->add_flag("--reversed", bench.reversed, "reversed depth (closest = max)");
    benchCommand->add_flag("--farthest", bench.farthest, "closest and farthest channels");
    benchCommand->add_flag("--skip-level0", bench.skipLevel0,
                           "depth pyramid: do not copy the input into level 0");
    benchCommand->add_option("--scene", bench.scene,
                             "sssr: scene file to simulate (default: the glossy room)");
    benchCommand->add_option("--set", bench.settings, "sssr: a setting, name=value (repeatable)");

    glint::cli::SimulateOptions simulate;
    std::string simulateSize;
    uint32_t simulateSeed = 0;
    CLI::App* simulateCommand =
        app.add_subcommand("simulate", "Render a scene file (TOML) into a capture sequence");
    simulateCommand
        ->add_option("scene", simulate.scenePath, "scene file, e.g. harness/scenes/glossy_room.toml")
        ->required();
    simulateCommand->add_option("--out", simulate.outDir, "output sequence folder")->required();
    simulateCommand->add_option("--size", simulateSize, "override the resolution, WxH");
    simulateCommand->add_option("--frames", simulate.frames, "override the frame count");
    simulateCommand->add_option("--spp", simulate.spp, "override the reference samples per pixel");
    CLI::Option* seedOption =
        simulateCommand->add_option("--seed", simulateSeed, "override the scene's seed");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        // CLI11 exits 0 for --help and non-zero for real usage errors; map the latter to 2.
        const int code = app.exit(error);
        return code == 0 ? glint::cli::kExitOk : glint::cli::kExitUsage;
    }

    try {
        if (*devices) return glint::cli::runDevices(validate);
        if (*info) return glint::cli::runInfo(infoPath, !headerOnly);
        if (*simulateCommand) {
            if (!simulateSize.empty() &&
                std::sscanf(simulateSize.c_str(), "%ux%u", &simulate.width, &simulate.height) != 2)
                throw std::invalid_argument("simulate: --size must read WxH, e.g. 1920x1080");
            if (*seedOption) simulate.seed = simulateSeed;
            simulate.validate = validate;
            return glint::cli::runSimulate(simulate);
        }
        if (*benchCommand) {
            if (std::sscanf(benchSize.c_str(), "%ux%u", &bench.width, &bench.height) != 2)
                throw std::invalid_argument("bench: --size must read WxH, e.g. 1920x1080");
            bench.validate = validate;
            return glint::cli::runBench(bench);
        }
    } catch (const std::exception& error) {
        std::fprintf(stderr, "glint: %s\n", error.what());
        return glint::cli::kExitUsage;
    }
    return glint::cli::kExitUsage;
}
