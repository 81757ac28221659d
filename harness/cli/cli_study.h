// What glint study's settings sweeps (cli_study.cpp) and its scaling runs
// (cli_study_scaling.cpp) share: the resolved options, simulated scenes and table output.
#pragma once

#include "cli_bench.h"
#include "cli_commands.h"
#include "cli_presets.h"

#include "capture/capture_frame.h"
#include "capture/environment_io.h"

#include <gpu/gpu_context.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace glint::cli::study {

// StudyOptions with every default filled in.
struct Plan {
    std::filesystem::path out;
    std::vector<std::string> effects; // "reflections", "shadows", "hybrid"
    std::vector<std::string> scenes;  // --scenes; empty: the bundled ones per effect
    std::uint32_t width = 0, height = 0, frames = 0, runs = 0;
    std::uint32_t spp = 0; // 0: per-effect default
    bool quick = false;
    bool floors = true;             // a second, independent reference per scene: the reference noise floor
    std::optional<double> budgetUs; // --budget-us: name the most accurate point that fits
};

// The second reference's seed is the scene's plus this (the demo's seed 2 for a scene at seed 1).
inline constexpr std::uint32_t kSecondReferenceSeedOffset = 1;

struct SimulatedScene {
    std::string name; // the file's stem, "glossy_room"
    std::string file; // the scene file, absolute (the hybrid's geometry)
    std::vector<capture::Frame> frames;
    capture::Environment environment;
};

// The scene at `path` with `effect` as its only effect (so that a reflections scene can serve
// the shadow study too), at width x height for `frames` frames; with referenceSpp > 0 the
// effect's reference at that many samples per pixel. A `seedOffset` other than 0 moves the
// scene's seed, which gives an independent reference of the same frames (the noise floor).
SimulatedScene simulateFor(const gpu::Context& context, const std::string& path, const std::string& effect,
                           std::uint32_t width, std::uint32_t height, std::uint32_t frames,
                           std::uint32_t referenceSpp, std::uint32_t seedOffset = 0);

// The settings every point of an effect starts from: the effect as an engine runs it.
std::vector<std::string> baseSettings(const std::string& effect);

// "a;b;c": lists inside one CSV field.
std::string joined(const std::vector<std::string>& items, const char* separator = ";");
std::string passesField(const Measurement& measurement); // "reflections/classify:12.3;..."
std::optional<double> counterNumber(const Measurement& measurement, const std::string& name);
std::string formatNumber(double value);                                            // "%.6g"
std::string counterValue(const Measurement& measurement, const std::string& name); // "" when absent
// Quotes a CSV field that holds a comma or a quote.
std::string csvField(const std::string& text);

void writeText(const std::filesystem::path& file, const std::string& text);

int runScaling(const Plan& plan, const gpu::Context& context);

// One measured row of the sweep, as the presets and the budget choice read it.
struct Measured {
    std::string effect, scene, label;
    std::vector<std::string> settings; // as --set would give them (the base's included)
    double timeUs = 0.0;               // median GPU time
    double error = 0.0;                // mean error against the reference
};
// The sweep's points of `effect` with their scenes combined (cli_study_presets.cpp): a point's
// time is its largest time over the scenes (a budget it fits holds on every scene), its error
// the mean over the scenes of its error divided by the `defaults` point's on that scene (1: as
// accurate as the effect as shipped; every scene weighs the same). A scene where the defaults
// point's error is not positive and finite cannot weigh in and is left out; a point without a
// finite error on a scene that counts gets a NaN error (on no front).
std::vector<StudyPoint> combineScenes(const std::vector<Measured>& rows, const std::string& effect);
// Per effect studied: the four presets from the combined points' front, written to
// plan.out/presets.toml, and with plan.budgetUs the most accurate point that fits it, printed.
// Returns both for study.json ("presets", "front", "budget").
nlohmann::json choosePresetsAndBudget(const Plan& plan, const std::string& device,
                                      const std::vector<Measured>& rows);

} // namespace glint::cli::study
