// The verbs of the glint command: per verb, its options struct, the function that adds those
// options to its CLI11 subcommand (add<Verb>Options, in cli_<verb>.cpp) and the function that
// runs it (run<Verb>, returning the process exit code); Verb is the entry of main's table.
#pragma once

#include "cli_presets.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace CLI {
class App;
}

namespace glint::cli {

// Exit codes shared by every verb.
enum ExitCode : int {
    kExitOk = 0,
    kExitCheckFailed = 1, // the command ran and a check it makes failed
    kExitUsage = 2,       // bad arguments or unreadable/malformed input
};

// One verb of glint as main() builds it: the subcommand's name and one-line help, and `bind`,
// which adds the verb's options to that subcommand, bound to an options struct it owns, and
// returns the run of the verb with them once the command line is parsed (`validate`:
// --validate, which comes before the verb).
struct Verb {
    std::string_view name;
    std::string_view help;
    std::function<int(bool validate)> (*bind)(CLI::App& command);
};

// The Verb of a verb's two functions: `addOptions` binds the options of its subcommand to an
// Options; `run` runs the verb with them, completing its copy (--validate, sizes read from
// their text) first.
template <class Options, void (*addOptions)(CLI::App&, Options&), int (*run)(Options, bool validate)>
constexpr Verb makeVerb(std::string_view name, std::string_view help) {
    auto bind = [](CLI::App& command) -> std::function<int(bool)> {
        auto options = std::make_shared<Options>();
        addOptions(command, *options);
        return [options](bool validate) { return run(*options, validate); };
    };
    return {name, help, bind};
}

// --preset and --preset-file on every verb that takes --set (cli_presets.h): the preset's
// settings for each effect being run, before --set (cli_settings.cpp).
void addPresetOptions(CLI::App& command, PresetChoice& preset);

// glint devices (cli_devices.cpp): it has no options of its own.
struct DevicesOptions {};
void addDevicesOptions(CLI::App& command, DevicesOptions& options);
int runDevices(DevicesOptions options, bool validate);

// glint settings [effect] (cli_settings.cpp): the settings tables; settingsHelp() is the same
// listing for --help.
struct SettingsOptions {
    std::string effect;    // empty: every effect
    bool markdown = false; // as the Markdown tables of docs/settings.md
};
void addSettingsOptions(CLI::App& command, SettingsOptions& options);
int runSettings(SettingsOptions options, bool validate);
std::string settingsHelp();
// The registered effects' names, "a, b, c".
std::string effectNames();

// glint info (cli_info.cpp): a glint capture, or with `mapPath` the frames of a foreign one as
// read through that channel map.
struct InfoOptions {
    std::string path;
    std::string mapPath;
    bool headerOnly = false; // headers only: no pixels, no non-finite counts
};
void addInfoOptions(CLI::App& command, InfoOptions& options);
int runInfo(InfoOptions options, bool validate);

// glint bench (cli_bench.cpp).
struct BenchOptions {
    std::string size = "1920x1080"; // --size/--resolution as given, WxH; run reads it into width, height
    bool sizeGiven = false;         // --size/--resolution named: captures must match it
    uint32_t width = 1920, height = 1080;
    uint32_t runs = 200;
    std::vector<std::string> settings; // "name=value"
    PresetChoice preset;               // --preset, --preset-file: applied before `settings`
    bool validate = false;
    // What is timed: registered effects' names (each alone on its descriptor's bench scene, or
    // on `scene`), frame .exr files, sequence folders and scene .toml files.
    std::vector<std::string> targets;
    std::string scene;                // --scene FILE: the scene an effect named is timed on
    std::string depth;                // --depth: the depth convention simulated scenes render
    std::vector<std::string> effects; // --effects; empty: the capture's declared effects
    std::string json;                 // --json FILE, "-" for stdout (the table then goes to stderr)
    std::string geometry;             // --geometry FILE: the scene the effects that ray trace see
};
void addBenchOptions(CLI::App& command, BenchOptions& options);
int runBench(BenchOptions options, bool validate);

// glint simulate (cli_simulate.cpp).
struct SimulateOptions {
    std::string scenePath;
    std::string outDir;
    std::string size;                           // --size as given, WxH; run reads it into width, height
    uint32_t width = 0, height = 0;             // 0: the scene's resolution
    uint32_t frames = 0;                        // 0: the scene's frame count
    uint32_t spp = 0;                           // 0: the scene's reference samples per pixel
    std::optional<float> noiseTarget;           // the scene's reference noise_target when absent
    std::optional<uint32_t> maxSpp;             // the scene's reference max_spp when absent
    std::optional<float> noiseTargetAlphaBelow; // the scene's reference noise_target_alpha_below when absent
    std::optional<uint32_t> seed;
    bool validate = false;
};
void addSimulateOptions(CLI::App& command, SimulateOptions& options);
int runSimulate(SimulateOptions options, bool validate);

// glint run / dump / check: a capture replayed through its effects (docs/replay.md).
struct ReplayOptions {
    std::string capture;               // frame .exr, sequence folder, or with mapPath a foreign EXR or folder
    std::string mapPath;               // --map: channel map of a foreign capture
    std::string geometry;              // --geometry: a glTF of the capture's scene (docs/replay.md)
    std::string outDir;                // run, dump
    std::string expectedDir;           // check
    std::vector<std::string> effects;  // empty: the capture's declared effects
    std::vector<std::string> settings; // "name=value"
    PresetChoice preset;               // --preset, --preset-file: applied before `settings`
    std::string frames;                // run: "a..b"; dump/check: the frame to look at ("" = last)
    std::string pass = "all";          // dump/check: a pass name, "effect/pass" or "all"
    std::vector<std::string> tolerances; // check: "pass=abs,rel[,fraction]"
    bool json = false;                   // run: also print the summary as JSON on stdout
    std::string secondReference;         // run: the same capture rendered with another seed (noise floor)
    bool validate = false;
};
// The options run, dump and check share: the capture, --map, --geometry, --effects, --set and
// the preset's (cli_capture.cpp).
void addReplayOptions(CLI::App& command, ReplayOptions& options);
void addRunOptions(CLI::App& command, ReplayOptions& options);
int runRun(ReplayOptions options, bool validate);
void addDumpOptions(CLI::App& command, ReplayOptions& options);
int runDump(ReplayOptions options, bool validate);
void addCheckOptions(CLI::App& command, ReplayOptions& options);
int runCheck(ReplayOptions options, bool validate);

// glint study (cli_study.cpp): settings swept per effect on simulated scenes with references,
// GPU time and error of each point; with `scaling`, time against resolution and against the
// fraction of pixels the effect works on (docs/accuracy-vs-time.md).
struct StudyOptions {
    std::string outDir;
    std::string effect = "all";      // reflections | shadows | all
    std::vector<std::string> scenes; // empty: three bundled scenes per effect
    std::string size;                // --size as given, WxH; run reads it into width, height
    uint32_t width = 0, height = 0;  // 0: 1920x1080 (--quick: tiny)
    uint32_t frames = 0;             // 0: 16 (--quick: 3)
    uint32_t spp = 0;                // 0: per-effect default reference samples per pixel
    uint32_t runs = 0;               // 0: 50 timed runs per point (--quick: 2)
    std::optional<double> budgetUs;  // --budget-us: name the most accurate point that fits
    bool quick = false;
    bool scaling = false;
    bool noFloor = false; // no second reference, so no reference noise floor
    bool validate = false;
};
void addStudyOptions(CLI::App& command, StudyOptions& options);
int runStudy(StudyOptions options, bool validate);

// glint report: an HTML page from folders written by glint run.
struct ReportOptions {
    std::vector<std::string> runs;
    std::string outPath;
    std::string title = "glint report";
    std::string anchorsPath; // --anchors: measured points of other implementations (docs/anchors)
};
void addReportOptions(CLI::App& command, ReportOptions& options);
int runReport(ReportOptions options, bool validate);

// glint view (cli_view.cpp, docs/viewer.md): a window replaying a capture live.
struct ViewOptions {
    std::string capture;  // frame .exr, sequence folder, a foreign EXR or folder with mapPath, or scene .toml
    std::string mapPath;  // --map
    std::string geometry; // --geometry
    std::vector<std::string> effects;  // empty: the capture's declared effects
    std::vector<std::string> settings; // "name=value"
    PresetChoice preset;               // --preset, --preset-file: applied before `settings`
    std::string script;                // --script FILE (view_script.h)
    std::string screenshot;            // --screenshot FILE: after frame `after`, then exit
    std::uint32_t after = 0;           // --after N
    bool ui = false;                   // --ui: the controls in scripted screenshots too
    bool validate = false;
};
void addViewOptions(CLI::App& command, ViewOptions& options);
int runView(ViewOptions options, bool validate);

} // namespace glint::cli
