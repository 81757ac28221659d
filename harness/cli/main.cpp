// glint: frame-capture and device tool. main() builds the command from the table of verbs
// below; each verb's options and run live in its cli_<verb>.cpp (cli_commands.h).
#include "cli_commands.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <functional>
#include <vector>

namespace {

using namespace glint::cli;

// In the order `glint --help` lists them.
constexpr Verb kVerbs[] = {
    makeVerb<DevicesOptions, addDevicesOptions, runDevices>(
        "devices", "List Vulkan devices: driver, subgroup size, float16 support"),
    makeVerb<SettingsOptions, addSettingsOptions, runSettings>(
        "settings", "List every effect's settings (--set name=value): type, default, range, help"),
    makeVerb<InfoOptions, addInfoOptions, runInfo>("info",
                                                   "Describe a frame capture (.exr) or a sequence folder"),
    makeVerb<BenchOptions, addBenchOptions, runBench>(
        "bench", "Per-pass GPU times of effects (median of sustained timestamped runs)"),
    makeVerb<StudyOptions, addStudyOptions, runStudy>(
        "study", "Sweep effect settings on scenes with references: GPU time and error per setting"),
    makeVerb<SimulateOptions, addSimulateOptions, runSimulate>(
        "simulate", "Render a scene file (TOML) into a capture sequence"),
    makeVerb<ReplayOptions, addRunOptions, runRun>(
        "run", "Replay a capture through its effects; write outputs and a summary"),
    makeVerb<ReplayOptions, addDumpOptions, runDump>(
        "dump", "Write every intermediate of the named passes of one frame"),
    makeVerb<ReplayOptions, addCheckOptions, runCheck>(
        "check", "Compare each pass's outputs with expected ones laid out like glint dump's"),
    makeVerb<ViewOptions, addViewOptions, runView>(
        "view",
        "A window replaying a capture live: effects, settings and every pass's images (docs/viewer.md)"),
    makeVerb<ReportOptions, addReportOptions, runReport>(
        "report", "Write one HTML page from folders written by glint run"),
};

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"glint: reflections and shadow-denoising passes on frame captures"};
    app.require_subcommand(1);
    bool validate = false;
    app.add_flag(
        "--validate", validate,
        "Run under VK_LAYER_KHRONOS_validation (with synchronization validation); any error exits 1");

    struct Bound {
        CLI::App* command;
        std::function<int(bool validate)> run;
    };
    std::vector<Bound> verbs;
    for (const Verb& verb : kVerbs) {
        CLI::App* command = app.add_subcommand(std::string(verb.name), std::string(verb.help));
        verbs.push_back({command, verb.bind(*command)});
    }

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        // CLI11 exits 0 for --help and non-zero for real usage errors; map the latter to 2.
        const int code = app.exit(error);
        return code == 0 ? kExitOk : kExitUsage;
    }

    try {
        for (const Bound& verb : verbs)
            if (*verb.command) return verb.run(validate);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "glint: %s\n", error.what());
        return kExitUsage;
    }
    return kExitUsage;
}
