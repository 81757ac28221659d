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

    // --preset on every verb that takes --set (cli_presets.h): the preset's settings for each
    // effect being run, before --set.
    auto presetOptions = [](CLI::App* command, glint::cli::PresetChoice& preset) {
        command->add_option("--preset", preset.name,
                            "low | medium | high | ultra: settings per effect, applied before --set "
                            "(docs/accuracy-vs-time.md, Presets)");
        command->add_option("--preset-file", preset.file,
                            "read --preset from this file (presets.toml written by glint study)");
    };

    CLI::App* devices =
        app.add_subcommand("devices", "List Vulkan devices: driver, subgroup size, float16 support");

    std::string settingsEffect;
    CLI::App* settings = app.add_subcommand(
        "settings", "List every effect's settings (--set name=value): type, default, range, help");
    settings->add_option("effect", settingsEffect, glint::cli::effectNames());
    bool settingsMarkdown = false;
    settings->add_flag("--markdown", settingsMarkdown, "as the Markdown tables of docs/settings.md");

    std::string infoPath, infoMap;
    bool headerOnly = false;
    CLI::App* info = app.add_subcommand("info", "Describe a frame capture (.exr) or a sequence folder");
    info->add_option("capture", infoPath,
                     "frame file, sequence folder, or with --map one foreign EXR or a folder of them")
        ->required();
    info->add_option("--map", infoMap, "channel map of a foreign capture (docs/replay.md)");
    info->add_flag("--header-only", headerOnly, "read headers only; skip pixels and non-finite counts");

    glint::cli::BenchOptions bench;
    std::string benchSize = "1920x1080";
    CLI::App* benchCommand =
        app.add_subcommand("bench", "Per-pass GPU times of effects (median of sustained timestamped runs)");
    benchCommand
        ->add_option("targets", bench.targets,
                     "effects (" + glint::cli::effectNames() +
                         ": each alone on its bench scene), or captures: frame .exr, sequence folders, "
                         "scene .toml")
        ->required();
    CLI::Option* benchSizeOption =
        benchCommand->add_option("--size,--resolution", benchSize, "render size WxH")->capture_default_str();
    benchCommand->add_option("--runs", bench.runs, "measured runs")->capture_default_str();
    benchCommand->add_option("--scene", bench.scene,
                             "an effect named: the scene file to time it on (default: its bench scene, "
                             "relative to the repository root)");
    benchCommand->add_option("--depth", bench.depth,
                             "standard | reversed | reversed_infinite: the depth convention simulated "
                             "scenes render (default: the scene file's)");
    benchCommand->add_option("--set", bench.settings, "a setting, name=value (repeatable; glint settings)");
    presetOptions(benchCommand, bench.preset);
    benchCommand->footer(glint::cli::settingsHelp());
    benchCommand
        ->add_option("--effects", bench.effects,
                     "captures and scene files: " + glint::cli::effectNames() + " (default: declared)")
        ->delimiter(',');
    benchCommand->add_option("--json", bench.json, "also write the results as JSON to FILE ('-': stdout)");
    benchCommand->add_option(
        "--geometry", bench.geometry,
        "a glTF (.gltf/.glb, or anything assimp reads) of the targets' scene in their world "
        "space, for the effects that ray trace (hybrid); wins over a manifest's or scene "
        "file's own scene (docs/replay.md)");

    glint::cli::StudyOptions study;
    std::string studySize;
    CLI::App* studyCommand = app.add_subcommand(
        "study", "Sweep effect settings on scenes with references: GPU time and error per setting");
    studyCommand
        ->add_option("--out", study.outDir, "output folder (study.csv, study.json, presets.toml, images/)")
        ->required();
    studyCommand->add_option("--effect", study.effect, "reflections | shadows | hybrid | all")
        ->capture_default_str();
    studyCommand
        ->add_option("--scenes", study.scenes, "scene files (default: three bundled scenes per effect)")
        ->delimiter(',');
    studyCommand->add_option("--size", studySize, "resolution WxH (default 1920x1080)");
    studyCommand->add_option("--frame-count", study.frames,
                             "frames per point; the last is measured (default 16)");
    studyCommand->add_option("--spp", study.spp, "reference samples per pixel");
    studyCommand->add_option("--runs", study.runs, "timed runs per point (default 50)");
    studyCommand->add_flag("--quick", study.quick, "tiny sizes, few frames and points (smoke test)");
    studyCommand->add_flag("--no-floor", study.noFloor,
                           "skip the second, independent reference (no reference noise floor)");
    double studyBudget = 0.0;
    CLI::Option* studyBudgetOption = studyCommand->add_option(
        "--budget-us", studyBudget, "name the most accurate measured point whose GPU time fits this budget");
    studyCommand->add_flag("--scaling", study.scaling,
                           "time against resolution and against the fraction of affected pixels");

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
    simulateCommand->add_option("--frame-count", simulate.frames, "override the frame count");
    simulateCommand->add_option("--spp", simulate.spp, "override the reference samples per pixel");
    CLI::Option* seedOption =
        simulateCommand->add_option("--seed", simulateSeed, "override the scene's seed");

    // run, dump and check share the capture, map, effect and setting options.
    glint::cli::ReplayOptions run, dump, check;
    auto replayOptions = [&presetOptions](CLI::App* command, glint::cli::ReplayOptions& options) {
        command
            ->add_option("capture", options.capture,
                         "frame .exr, sequence folder, or with --map one foreign EXR or a folder of them "
                         "(one path)")
            ->required();
        command->add_option("--map", options.mapPath, "channel map of a foreign capture (docs/replay.md)");
        command->add_option(
            "--geometry", options.geometry,
            "a glTF (.gltf/.glb, or anything assimp reads) of the capture's scene in its world "
            "space, for the effects that ray trace (hybrid): its meshes with their materials "
            "and its punctual lights; wins over the scene a manifest records (docs/replay.md)");
        command->add_option("--effects", options.effects, glint::cli::effectNames() + " (default: declared)")
            ->delimiter(',');
        command->add_option("--set", options.settings, "a setting, name=value (repeatable; glint settings)");
        presetOptions(command, options.preset);
        command->footer(glint::cli::settingsHelp());
    };
    CLI::App* runCommand =
        app.add_subcommand("run", "Replay a capture through its effects; write outputs and a summary");
    replayOptions(runCommand, run);
    runCommand->add_option("--out", run.outDir, "output folder")->required();
    runCommand->add_option("--frames", run.frames, "frames a..b (inclusive), a.. or a");
    runCommand->add_flag("--json", run.json, "also print the summary as JSON");
    runCommand->add_option("--second-reference", run.secondReference,
                           "the same capture simulated with another --seed: its references against the "
                           "capture's give each frame's reference noise floor (docs/replay.md)");
    CLI::App* dumpCommand =
        app.add_subcommand("dump", "Write every intermediate of the named passes of one frame");
    replayOptions(dumpCommand, dump);
    dumpCommand->add_option("--out", dump.outDir, "output folder")->required();
    dumpCommand->add_option("--pass", dump.pass, "pass name, effect/pass, input or all")
        ->capture_default_str();
    dumpCommand->add_option("--frame", dump.frames, "the frame to dump (default: the last)");
    CLI::App* checkCommand = app.add_subcommand(
        "check", "Compare each pass's outputs with expected ones laid out like glint dump's");
    replayOptions(checkCommand, check);
    checkCommand->add_option("--expected", check.expectedDir, "folder laid out as glint dump writes")
        ->required();
    checkCommand->add_option("--pass", check.pass, "pass name, effect/pass or all")->capture_default_str();
    checkCommand->add_option("--frame", check.frames, "the frame to compare (default: the last)");
    checkCommand->add_option("--tolerance", check.tolerances, "effect/pass=abs,rel[,fraction] (repeatable)");

    glint::cli::ViewOptions view;
    CLI::App* viewCommand = app.add_subcommand(
        "view",
        "A window replaying a capture live: effects, settings and every pass's images (docs/viewer.md)");
    viewCommand
        ->add_option(
            "capture", view.capture,
            "frame .exr, sequence folder, with --map one foreign EXR or a folder of them, or scene .toml")
        ->required();
    viewCommand->add_option("--map", view.mapPath, "channel map of a foreign capture (docs/replay.md)");
    viewCommand->add_option("--geometry", view.geometry,
                            "a glTF of the capture's scene, for the effects that ray trace");
    viewCommand->add_option("--effects", view.effects, glint::cli::effectNames() + " (default: declared)")
        ->delimiter(',');
    viewCommand->add_option("--set", view.settings, "a setting, name=value (repeatable; glint settings)");
    presetOptions(viewCommand, view.preset);
    viewCommand->add_option("--script", view.script, "commands to run, one a line (docs/viewer.md)");
    viewCommand->add_option("--screenshot", view.screenshot,
                            "write the window's image as PNG after frame --after, then exit");
    viewCommand->add_option("--after", view.after, "the frame (0-based) --screenshot waits for");
    viewCommand->add_flag("--ui", view.ui, "show the controls in scripted runs and screenshots too");
    viewCommand->footer(glint::cli::settingsHelp());

    glint::cli::ReportOptions report;
    CLI::App* reportCommand =
        app.add_subcommand("report", "Write one HTML page from folders written by glint run");
    reportCommand->add_option("runs", report.runs, "folders written by glint run")->required();
    reportCommand->add_option("--out", report.outPath, "the HTML file")->required();
    reportCommand->add_option("--title", report.title, "page title")->capture_default_str();
    reportCommand->add_option("--anchors", report.anchorsPath,
                              "anchor points measured elsewhere (docs/anchors/*.json), listed with their "
                              "conditions beside the plot of the scene they were measured on");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        // CLI11 exits 0 for --help and non-zero for real usage errors; map the latter to 2.
        const int code = app.exit(error);
        return code == 0 ? glint::cli::kExitOk : glint::cli::kExitUsage;
    }

    try {
        if (*devices) return glint::cli::runDevices(validate);
        if (*settings) return glint::cli::runSettings(settingsEffect, settingsMarkdown);
        if (*info) return glint::cli::runInfo(infoPath, !headerOnly, infoMap);
        if (*simulateCommand) {
            if (!simulateSize.empty() &&
                std::sscanf(simulateSize.c_str(), "%ux%u", &simulate.width, &simulate.height) != 2)
                throw std::invalid_argument("simulate: --size must read WxH, e.g. 1920x1080");
            if (*seedOption) simulate.seed = simulateSeed;
            simulate.validate = validate;
            return glint::cli::runSimulate(simulate);
        }
        if (*reportCommand) return glint::cli::runReport(report);
        // An unknown preset or an unreadable preset file fails before any capture is read.
        for (const glint::cli::PresetChoice* preset :
             {&bench.preset, &run.preset, &dump.preset, &check.preset, &view.preset})
            glint::cli::checkPresetChoice(*preset);
        if (*viewCommand) {
            view.validate = validate;
            return glint::cli::runView(view);
        }
        if (*runCommand) {
            run.validate = validate;
            return glint::cli::runRun(run);
        }
        if (*dumpCommand) {
            dump.validate = validate;
            return glint::cli::runDump(dump);
        }
        if (*checkCommand) {
            check.validate = validate;
            return glint::cli::runCheck(check);
        }
        if (*benchCommand) {
            if (std::sscanf(benchSize.c_str(), "%ux%u", &bench.width, &bench.height) != 2)
                throw std::invalid_argument("bench: --size must read WxH, e.g. 1920x1080");
            bench.validate = validate;
            bench.sizeGiven = benchSizeOption->count() > 0;
            return glint::cli::runBench(bench);
        }
        if (*studyCommand) {
            if (!studySize.empty() &&
                std::sscanf(studySize.c_str(), "%ux%u", &study.width, &study.height) != 2)
                throw std::invalid_argument("study: --size must read WxH, e.g. 1920x1080");
            study.validate = validate;
            if (*studyBudgetOption) study.budgetUs = studyBudget;
            return glint::cli::runStudy(study);
        }
    } catch (const std::exception& error) {
        std::fprintf(stderr, "glint: %s\n", error.what());
        return glint::cli::kExitUsage;
    }
    return glint::cli::kExitUsage;
}
