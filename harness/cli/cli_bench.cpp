// glint bench <effects|captures...>: per-pass GPU times, replayed through replay::Session with
// readback off: warm-up runs, then --runs measured runs of the last frame, sustained; median,
// min and max per pass, with the device, driver and subgroup size, as a table and (--json) as
// JSON. A target is a registered effect's name (the effect alone on the scene its descriptor's
// evaluation names for benchmarks, or on --scene), a frame .exr, a sequence folder or a scene
// .toml (its declared effects, or --effects). Scenes are simulated in memory at --size without
// references.
#include "cli_bench.h"
#include "cli_capture.h"
#include "cli_commands.h"

#include "capture/enum_names.h"
#include "capture/sequence_io.h"
#include "scene/scene_file.h"
#include "scene/scene_simulate.h"

#include <gpu/gpu_sustained.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <stdexcept>

namespace glint::cli {
namespace {

// Frames held in memory for the round-robin: re-reading EXRs between runs would make a long
// benchmark slow without changing what the GPU does.
constexpr std::size_t kMaxFrames = 32;

PassStats statsOf(const std::string& pass, std::vector<double> microseconds) {
    std::sort(microseconds.begin(), microseconds.end());
    return {pass, microseconds[microseconds.size() / 2], microseconds.front(), microseconds.back()};
}

std::string sizeText(std::uint32_t width, std::uint32_t height) {
    return std::to_string(width) + "x" + std::to_string(height);
}

struct Target {
    std::string path;
    std::string kind;                 // "effect", "frame", "sequence" or "scene"
    std::vector<std::string> effects; // an effect target's one effect; empty: --effects or declared
    std::vector<capture::Frame> frames;
    capture::Environment environment;
    std::optional<scene::Scene> scene; // simulated once the device is up
    std::string sceneFile;             // the geometry for effects that ray trace
};

// A scene file at the bench's size, without references (only the inputs are timed).
scene::Scene benchScene(const std::string& path, const BenchOptions& options) {
    scene::Scene scene = scene::loadScene(path);
    scene.width = options.width;
    scene.height = options.height;
    scene.reference = {};
    if (!options.depth.empty()) scene.camera.depth = *capture::parseDepthConvention(options.depth);
    return scene;
}

// A registered effect alone, on the scene its descriptor names for benchmarks (or --scene),
// rendered with the inputs of the scene effect the descriptor names.
Target effectTarget(const EffectDescriptor& effect, const BenchOptions& options) {
    if (!options.effects.empty())
        throw std::invalid_argument(
            "bench: --effects applies to captures and scene files, not to the effect '" + effect.name + "'");
    if (!effect.evaluation.bench)
        throw std::invalid_argument("bench: the effect '" + effect.name +
                                    "' names no bench scene; time it on a capture or scene file with "
                                    "--effects " +
                                    effect.name);
    const EffectBench& bench = *effect.evaluation.bench;
    Target target;
    target.path = options.scene.empty() ? bench.scene : options.scene;
    if (!std::filesystem::exists(target.path))
        throw std::invalid_argument("bench: " + target.path + ": no such scene file (the effect '" +
                                    effect.name +
                                    "' is timed on it; run from the repository root or "
                                    "give --scene FILE)");
    target.kind = "effect";
    target.effects = {effect.name};
    target.sceneFile = target.path;
    target.scene = benchScene(target.path, options);
    target.scene->effects = {scene::effectNamed(bench.simulateAs)};
    return target;
}

// Everything that can be wrong with a target is found here, before a device is created.
Target openTarget(const std::string& path, const BenchOptions& options) {
    if (const EffectDescriptor* effect = findEffect(path)) return effectTarget(*effect, options);
    Target target;
    target.path = path;
    target.effects = options.effects;
    const std::filesystem::path file(path);
    if (!std::filesystem::exists(file)) {
        // A bare word is more likely a mistyped effect than a missing capture.
        if (path.find_first_of("/.") == std::string::npos)
            throw std::invalid_argument("bench: unknown effect '" + path + "' (" + effectNames() +
                                        ") and no capture of that name");
        throw std::invalid_argument("bench: " + path + ": no such file or folder");
    }
    if (file.extension() == ".toml") {
        target.kind = "scene";
        target.sceneFile = path;
        target.scene = benchScene(path, options);
        return target;
    }
    if (std::filesystem::is_directory(file) && !std::filesystem::exists(file / capture::kManifestName))
        throw std::invalid_argument("bench: " + path + ": no " + capture::kManifestName +
                                    " (bench times glint captures and scenes; a foreign capture replays "
                                    "with glint run --map FILE)");
    const CaptureSource source(path);
    target.kind = source.frameCount() > 1 || std::filesystem::is_directory(file) ? "sequence" : "frame";
    target.environment = source.environment();
    target.sceneFile = source.sceneFile();
    for (std::size_t index = 0; index < std::min(source.frameCount(), kMaxFrames); ++index)
        target.frames.push_back(source.frame(index));
    const capture::Frame& first = target.frames.front();
    if (options.sizeGiven && (first.width != options.width || first.height != options.height))
        throw std::invalid_argument("bench: " + path + " is " + sizeText(first.width, first.height) +
                                    ", not the --resolution " + sizeText(options.width, options.height) +
                                    " asked for (captures are timed at their own size)");
    try {
        replay::effectsToRun(first, target.effects);
    } catch (const std::invalid_argument& error) {
        throw std::invalid_argument("bench: " + path + ": " + error.what());
    }
    return target;
}

// The target's own scene for the effects that ray trace (options.geometry, from --geometry, wins).
replay::SessionOptions withScene(replay::SessionOptions options, const Target& target) {
    options.scene = target.sceneFile;
    return options;
}

void printCounters(std::FILE* out, const std::vector<replay::Counter>& counters) {
    for (const replay::Counter& counter : counters)
        std::fprintf(out, "  %-34s %12.4g\n", counter.name.c_str(), counter.value);
}

} // namespace

Measurement measureFrames(const gpu::Context& context, const std::vector<capture::Frame>& frames,
                          const capture::Environment& environment, replay::SessionOptions options,
                          std::uint32_t runs) {
    if (frames.empty() || runs == 0) throw std::invalid_argument("nothing to time: no frames or no runs");
    options.readback = false;
    replay::Session session(context, frames.front(), environment, options);
    Measurement measurement;
    measurement.runs = runs;
    measurement.warmup = std::min(runs, 10u);
    std::vector<std::string> order;
    std::map<std::string, std::vector<double>> times;
    std::vector<double> totals;
    // Every frame once (uploads, histories), then the warm-up and the measured runs repeat the
    // last frame, submitted so that the GPU never waits for the host: the clocks follow the
    // load, and a GPU left idle between frames runs them several times slower
    // (docs/performance.md).
    for (const capture::Frame& frame : frames) session.run(frame);
    const std::uint32_t all = measurement.warmup + runs;
    const replay::SustainedResult sustained =
        session.repeatSustained(gpu::kSustainedFramesPerBuffer, gpu::sustainedSubmissions(all));
    const std::vector<replay::FrameResult>& results = sustained.frames;
    measurement.wallPerRunUs = 1000.0 * sustained.wallMilliseconds / static_cast<double>(results.size());
    measurement.counters = results.back().counters;
    for (std::uint32_t run = measurement.warmup; run < all; ++run) {
        const replay::FrameResult& result = results[run];
        if (result.timings.empty()) continue;
        double total = 0.0;
        for (const replay::PassTime& time : result.timings) {
            if (!times.contains(time.pass)) order.push_back(time.pass);
            times[time.pass].push_back(1000.0 * time.milliseconds);
            total += 1000.0 * time.milliseconds;
        }
        totals.push_back(total);
    }
    for (const std::string& pass : order) measurement.passes.push_back(statsOf(pass, times[pass]));
    if (!totals.empty()) measurement.total = statsOf("total", totals);
    measurement.memory = gpu::deviceMemoryUse(context);
    return measurement;
}

nlohmann::json deviceJson(const gpu::Context& context) {
    return {{"name", context.info.name},
            {"driver", context.info.driverName + " " + context.info.driverInfo},
            {"subgroupSize", context.device.subgroupSize}};
}

nlohmann::json measurementJson(const Measurement& measurement) {
    auto stats = [](const PassStats& s) {
        return nlohmann::json{
            {"pass", s.pass}, {"medianUs", s.medianUs}, {"minUs", s.minUs}, {"maxUs", s.maxUs}};
    };
    nlohmann::json json{{"warmup", measurement.warmup},
                        {"runs", measurement.runs},
                        {"passes", nlohmann::json::array()},
                        {"total", stats(measurement.total)},
                        {"wallPerRunUs", measurement.wallPerRunUs},
                        {"counters", nlohmann::json::object()}};
    if (measurement.memory.known)
        json["deviceMemoryMiB"] = static_cast<double>(measurement.memory.usedBytes) / 1048576.0;
    for (const PassStats& pass : measurement.passes) json["passes"].push_back(stats(pass));
    for (const replay::Counter& counter : measurement.counters)
        json["counters"][counter.name] = counter.value;
    return json;
}

void printMeasurement(std::FILE* out, const Measurement& measurement) {
    if (measurement.passes.empty()) {
        std::fprintf(out, "  (no timestamps on this queue)\n");
        return;
    }
    std::fprintf(out, "  %-34s %12s %12s %12s\n", "pass", "median us", "min us", "max us");
    for (const PassStats& pass : measurement.passes)
        std::fprintf(out, "  %-34s %12.2f %12.2f %12.2f\n", pass.pass.c_str(), pass.medianUs, pass.minUs,
                     pass.maxUs);
    const PassStats& total = measurement.total;
    std::fprintf(out, "  %-34s %12.2f %12.2f %12.2f\n", "total (sum of a run's passes)", total.medianUs,
                 total.minUs, total.maxUs);
    std::fprintf(out, "  %-34s %12.2f\n", "wall time a run (sustained)", measurement.wallPerRunUs);
    if (measurement.memory.known)
        std::fprintf(out, "  device-local memory in use: %.1f MiB of a %.1f MiB budget\n",
                     static_cast<double>(measurement.memory.usedBytes) / 1048576.0,
                     static_cast<double>(measurement.memory.budgetBytes) / 1048576.0);
}

void addBenchOptions(CLI::App& command, BenchOptions& options) {
    command
        .add_option("targets", options.targets,
                    "effects (" + effectNames() +
                        ": each alone on its bench scene), or captures: frame .exr, sequence folders, "
                        "scene .toml")
        ->required();
    command.add_option("--size,--resolution", options.size, "render size WxH")
        ->capture_default_str()
        ->each([&options](const std::string&) { options.sizeGiven = true; });
    command.add_option("--runs", options.runs, "measured runs")->capture_default_str();
    command.add_option("--scene", options.scene,
                       "an effect named: the scene file to time it on (default: its bench scene, "
                       "relative to the repository root)");
    command.add_option("--depth", options.depth,
                       "standard | reversed | reversed_infinite: the depth convention simulated "
                       "scenes render (default: the scene file's)");
    command.add_option("--set", options.settings, "a setting, name=value (repeatable; glint settings)");
    addPresetOptions(command, options.preset);
    command.footer(settingsHelp());
    command
        .add_option("--effects", options.effects,
                    "captures and scene files: " + effectNames() + " (default: declared)")
        ->delimiter(',');
    command.add_option("--json", options.json, "also write the results as JSON to FILE ('-': stdout)");
    command.add_option("--geometry", options.geometry,
                       "a glTF (.gltf/.glb, or anything assimp reads) of the targets' scene in their world "
                       "space, for the effects that ray trace (hybrid); wins over a manifest's or scene "
                       "file's own scene (docs/replay.md)");
}

int runBench(BenchOptions options, bool validate) {
    // An unknown preset or an unreadable preset file fails before any capture is read.
    checkPresetChoice(options.preset);
    if (std::sscanf(options.size.c_str(), "%ux%u", &options.width, &options.height) != 2)
        throw std::invalid_argument("bench: --size must read WxH, e.g. 1920x1080");
    options.validate = validate;
    if (options.width == 0 || options.height == 0 || options.runs == 0)
        throw std::invalid_argument("bench: size and runs must be positive");
    if (!options.depth.empty() && !capture::parseDepthConvention(options.depth))
        throw std::invalid_argument("bench: --depth must be standard, reversed or reversed_infinite, not '" +
                                    options.depth + "'");
    replay::SessionOptions sessionOptions;
    sessionOptions.settings = replay::parseSettings(options.settings);
    setGeometry(sessionOptions, {}, options.geometry); // withScene keeps it: it wins over the targets' scenes
    std::vector<Target> targets;
    for (const std::string& path : options.targets) targets.push_back(openTarget(path, options));
    if (!options.scene.empty() &&
        std::none_of(targets.begin(), targets.end(), [](const Target& t) { return t.kind == "effect"; }))
        throw std::invalid_argument(
            "bench: --scene applies to an effect named, not to captures and scene files");
    // With the JSON on stdout, the table goes to stderr so that stdout parses.
    std::FILE* out = options.json == "-" ? stderr : stdout;

    return withContext(options.validate, [&](const gpu::Context& context) {
        nlohmann::json report{{"device", deviceJson(context)},
                              {"settings", options.settings},
                              {"captures", nlohmann::json::array()}};
        if (!options.preset.name.empty()) report["preset"] = options.preset.name;
        std::fprintf(out, "device: %s, driver %s %s, subgroup %u\n", context.info.name.c_str(),
                     context.info.driverName.c_str(), context.info.driverInfo.c_str(),
                     context.device.subgroupSize);
        if (options.preset.name.empty())
            for (const std::string& setting : options.settings)
                std::fprintf(out, "  set %s\n", setting.c_str());
        for (Target& target : targets) {
            if (target.scene) {
                target.scene->frameCount =
                    std::min<std::uint32_t>(target.scene->frameCount, static_cast<std::uint32_t>(kMaxFrames));
                scene::Simulation simulation = scene::simulate(context, *target.scene);
                target.frames = std::move(simulation.frames);
                target.environment = simulation.environment.value_or(blackEnvironment());
            }
            const capture::Frame& first = target.frames.front();
            const std::vector<std::string> effects = replay::effectsToRun(first, target.effects);
            // --preset's bundles follow each target's own effects.
            replay::SessionOptions targetOptions = withScene(sessionOptions, target);
            targetOptions.effects = target.effects;
            const std::vector<std::string> settings =
                presetThenSettings(options.preset, effects, options.settings);
            targetOptions.settings = replay::parseSettings(settings);
            if (!options.preset.name.empty())
                for (const std::string& setting : settings)
                    std::fprintf(out, "  %s: set %s\n", target.path.c_str(), setting.c_str());
            const Measurement measurement =
                measureFrames(context, target.frames, target.environment, targetOptions, options.runs);
            if (target.kind == "effect")
                std::fprintf(out, "effect %s on %s: %ux%u, %zu frame(s), effects:", effects.front().c_str(),
                             target.path.c_str(), first.width, first.height, target.frames.size());
            else
                std::fprintf(out, "%s %s: %ux%u, %zu frame(s), effects:", target.kind.c_str(),
                             target.path.c_str(), first.width, first.height, target.frames.size());
            for (const std::string& effect : effects) std::fprintf(out, " %s", effect.c_str());
            std::fprintf(out, "; %u warm-up + %u measured runs\n", measurement.warmup, measurement.runs);
            printMeasurement(out, measurement);
            printCounters(out, measurement.counters);
            nlohmann::json entry = measurementJson(measurement);
            entry["capture"] = target.path;
            entry["kind"] = target.kind;
            entry["width"] = first.width;
            entry["height"] = first.height;
            entry["frames"] = target.frames.size();
            entry["effects"] = effects;
            entry["settings"] = settings;
            report["captures"].push_back(entry);
        }
        if (options.json == "-") {
            std::printf("%s\n", report.dump(2).c_str());
        } else if (!options.json.empty()) {
            std::ofstream file(options.json);
            if (!(file << report.dump(2) << "\n"))
                throw std::runtime_error("bench: " + options.json + ": cannot write");
            std::fprintf(out, "wrote %s\n", options.json.c_str());
        }
        return kExitOk;
    });
}

} // namespace glint::cli
