// The verbs of the glint command. Each returns the process exit code.
#pragma once

#include "cli_presets.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace glint::cli {

// Exit codes shared by every verb.
enum ExitCode : int {
    kExitOk = 0,
    kExitCheckFailed = 1, // the command ran and a check it makes failed
    kExitUsage = 2,       // bad arguments or unreadable/malformed input
};

// glint bench (cli_bench.cpp).
struct BenchOptions {
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
    bool sizeGiven = false;           // --size/--resolution named: captures must match it
    std::string geometry;             // --geometry FILE: the scene the effects that ray trace see
};

struct SimulateOptions {
    std::string scenePath;
    std::string outDir;
    uint32_t width = 0, height = 0; // 0: the scene's resolution
    uint32_t frames = 0;            // 0: the scene's frame count
    uint32_t spp = 0;               // 0: the scene's reference samples per pixel
    std::optional<uint32_t> seed;
    bool validate = false;
};

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

// glint study (cli_study.cpp): settings swept per effect on simulated scenes with references,
// GPU time and error of each point; with `scaling`, time against resolution and against the
// fraction of pixels the effect works on (docs/accuracy-vs-time.md).
struct StudyOptions {
    std::string outDir;
    std::string effect = "all";      // reflections | shadows | all
    std::vector<std::string> scenes; // empty: three bundled scenes per effect
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

int runBench(const BenchOptions& options);
int runStudy(const StudyOptions& options);

// glint report: an HTML page from folders written by glint run.
struct ReportOptions {
    std::vector<std::string> runs;
    std::string outPath;
    std::string title = "glint report";
    std::string anchorsPath; // --anchors: measured points of other implementations (docs/anchors)
};

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
int runView(const ViewOptions& options);

int runDevices(bool validate);
// glint settings [effect]: the settings tables; settingsHelp() is the same listing for --help.
int runSettings(const std::string& effect, bool markdown);
std::string settingsHelp();
// The registered effects' names, "a, b, c".
std::string effectNames();
int runReport(const ReportOptions& options);
int runRun(const ReplayOptions& options);
int runDump(const ReplayOptions& options);
int runCheck(const ReplayOptions& options);
int runSimulate(const SimulateOptions& options);
// glint info: a glint capture, or with `mapPath` the frames of a foreign one as read through
// that channel map.
int runInfo(const std::string& path, bool loadPixels, const std::string& mapPath = {});

} // namespace glint::cli
