// glint study: for each effect, scene and sweep point (one setting changed from the effect's
// defaults at a time), the GPU time of the effect's passes and its error against the scene's
// converged reference after a fixed warm-up of frames. Writes study.csv, study.json and, per
// point, the last frame's output and the reference as EXR (masked to the pixels the error is
// measured over) for scripts/study.py, which adds FLIP, the Pareto front and plots
// (docs/accuracy-vs-time.md), and presets.toml, the presets chosen from this run's points
// (cli_study_presets.cpp). Paths inside study.json are relative to the output folder, so the
// folder can be evaluated on another machine than the one that measured it.
#include "cli_study.h"

#include "cli_capture.h"
#include "cli_images.h"

#include "replay/replay_error.h"
#include "replay/replay_frame.h"
#include "replay/replay_settings.h"
#include "report/report_image.h"
#include "scene/scene_file.h"
#include "scene/scene_simulate.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace glint::cli {
namespace study {
namespace {

using Point = StudyPointDesc;

// The effect's study (its descriptor's; resolve() admits only effects that have one).
const EffectStudy& studyOf(const std::string& effect) {
    const EffectDescriptor* descriptor = findEffect(effect);
    if (!descriptor || !descriptor->evaluation.study)
        throw std::invalid_argument("study: effect '" + effect + "' has no study in its descriptor");
    return *descriptor->evaluation.study;
}

// One setting at a time around the defaults: the descriptor's points (--quick: those marked quick).
std::vector<Point> pointsFor(const std::string& effect, bool quick) {
    std::vector<Point> points;
    for (const Point& point : studyOf(effect).points)
        if (!quick || point.quick) points.push_back(point);
    return points;
}

std::vector<std::string> defaultScenes(const std::string& effect, bool quick) {
    const EffectStudy& study = studyOf(effect);
    std::vector<std::string> scenes = study.scenes;
    if (quick && scenes.size() > study.quickScenes) scenes.resize(study.quickScenes);
    return scenes;
}

// References converge like 1/sqrt(spp); the descriptor says how many samples its reference needs.
std::uint32_t referenceSpp(const Plan& plan, const std::string& effect) {
    if (plan.spp > 0) return plan.spp;
    return plan.quick ? studyOf(effect).quickReferenceSpp : studyOf(effect).referenceSpp;
}

// The base settings with the point's applied over them; a name set twice keeps its last value
// only, so that the list reads as what `glint bench --set` would need.
SettingValues settingsOf(const std::string& effect, const Point& point) {
    std::vector<std::string> all;
    for (const std::string& base : baseSettings(effect)) {
        const std::string name = base.substr(0, base.find('='));
        const bool overridden =
            std::any_of(point.settings.begin(), point.settings.end(),
                        [&](const std::string& s) { return s.substr(0, s.find('=')) == name; });
        if (!overridden) all.push_back(base);
    }
    all.insert(all.end(), point.settings.begin(), point.settings.end());
    return replay::parseSettings(all);
}

// RGB (one channel is repeated: FLIP reads colour) with the pixels outside the mask zeroed in
// output and reference alike, so FLIP only sees differences where the error is measured.
void writeMaskedRgb(const std::filesystem::path& file, const report::Image& image,
                    const std::vector<std::uint8_t>& mask) {
    report::Image rgb{image.width, image.height, 3, std::vector<float>(mask.size() * 3, 0.0f)};
    for (std::size_t i = 0; i < mask.size(); ++i)
        for (std::uint32_t c = 0; c < 3; ++c)
            if (mask[i])
                rgb.pixels[i * 3 + c] = image.pixels[i * image.channels + std::min(c, image.channels - 1)];
    std::filesystem::create_directories(file.parent_path());
    report::writeExr(file.string(), rgb, {"R", "G", "B"});
}

struct Row {
    std::string scene, effect, label;
    std::vector<std::string> settings;
    Measurement measurement;
    replay::ReferenceError error;
    std::string output, reference, mask; // relative to the output folder
    std::uint32_t referenceSpp = 0;
    // The scene's second, independent reference: its image ("" without one) and the floor, the
    // two references' difference in the same metrics over the same mask.
    std::string reference2;
    std::optional<replay::ReferenceError> floor;
};

// Runs every frame with readback and measures the last one against its reference (its moving
// edges against the frame before it).
// `maskSettings` give the mask its threshold. An effect that is not scored gets NaN errors.
replay::ReferenceError lastFrameError(const gpu::Context& context, const SimulatedScene& scene,
                                      const replay::SessionOptions& options,
                                      const SettingValues& maskSettings, replay::FrameResult& result) {
    replay::Session session(context, scene.frames.front(), scene.environment, options);
    for (const capture::Frame& frame : scene.frames) result = session.run(frame);
    if (!replay::scoredOutput(options.effects.front())) {
        replay::ReferenceError unscored;
        unscored.effect = options.effects.front();
        unscored.mean = unscored.rmse = unscored.maeClamped = unscored.rmseClamped = std::nan("");
        return unscored;
    }
    const capture::Frame* previous =
        scene.frames.size() > 1 ? &scene.frames[scene.frames.size() - 2] : nullptr;
    for (replay::ReferenceError& error :
         replay::referenceErrors(scene.frames.back(), result, maskSettings, previous))
        if (error.effect == options.effects.front()) return error;
    throw std::runtime_error("study: scene " + scene.name + " has no " + options.effects.front() +
                             " reference");
}

// `second`: the same scene with an independent reference (none with --no-floor).
std::vector<Row> sweep(const gpu::Context& context, const Plan& plan, const std::string& effect,
                       const SimulatedScene& scene, const SimulatedScene* second) {
    const std::vector<Point> points = pointsFor(effect, plan.quick);
    const ScoredOutput* scored = replay::scoredOutput(effect);
    // One mask for every point: with a threshold, the largest swept, so that a lower threshold
    // is charged for the pixels it hands to the environment instead of dropping them.
    SettingValues maskSettings = settingsOf(effect, points.front());
    if (scored && !scored->mask.setting.empty()) {
        float threshold = 0.0f;
        for (const Point& point : points)
            threshold = std::max(threshold, settingsOf(effect, point).real(scored->mask.setting));
        maskSettings.set(scored->mask.setting, threshold);
    }
    const std::vector<std::uint8_t> mask =
        scored ? replay::errorMask(scene.frames.back(), scored->mask, maskSettings)
               : std::vector<std::uint8_t>{};
    const std::filesystem::path folder = std::filesystem::path("images") / scene.name / effect;
    std::vector<Row> rows;
    for (const Point& point : points) {
        replay::SessionOptions options;
        options.effects = {effect};
        options.settings = settingsOf(effect, point);
        options.scene = scene.file; // the hybrid's ray tracer traces the scene's geometry
        replay::FrameResult result;
        Row row{.scene = scene.name,
                .effect = effect,
                .label = point.label,
                .settings = options.settings.assignments()};
        row.error = lastFrameError(context, scene, options, maskSettings, result);
        row.measurement = measureFrames(context, scene.frames, scene.environment, options, plan.runs);
        row.referenceSpp = scored ? referenceSpp(plan, effect) : 0;
        if (!scored) {
            // Timed only: nothing to score it against.
            std::printf("  %-16s %-22s %10.1f us   (not scored)\n", scene.name.c_str(), point.label.c_str(),
                        row.measurement.total.medianUs);
            std::fflush(stdout);
            rows.push_back(std::move(row));
            continue;
        }
        row.output = (folder / (point.label + ".exr")).string();
        row.reference = (folder / "reference.exr").string();
        row.mask = (folder / "mask.exr").string();
        writeMaskedRgb(plan.out / row.output, result.find(row.error.image)->image, mask);
        if (rows.empty()) {
            writeMaskedRgb(plan.out / row.reference, result.find(effect + "/reference")->image, mask);
            const std::vector<float> ones(mask.size(), 1.0f);
            writeMaskedRgb(plan.out / row.mask,
                           {scene.frames.back().width, scene.frames.back().height, 1, ones}, mask);
            if (second) {
                for (replay::ReferenceError& noise :
                     replay::referenceNoise(scene.frames.back(), result, second->frames.back(), maskSettings))
                    if (noise.effect == effect) row.floor = std::move(noise);
                writeMaskedRgb(plan.out / folder / "reference2.exr",
                               referenceImage(second->frames.back(), effect), mask);
                std::printf("  %-16s reference noise floor at %u spp: mean error %.4f, MAE %.4f, RMSE %.4f "
                            "(clamped to [0, %g])\n",
                            scene.name.c_str(), row.referenceSpp, row.floor ? row.floor->mean : -1.0,
                            row.floor ? row.floor->maeClamped : -1.0,
                            row.floor ? row.floor->rmseClamped : -1.0, replay::kMaeClamp);
            }
        } else {
            row.floor = rows.front().floor;
        }
        if (second) row.reference2 = (folder / "reference2.exr").string();
        std::printf("  %-16s %-22s %10.1f us   error %.4f   MAE %.4f   RMSE %.4f   non-finite %g\n",
                    scene.name.c_str(), point.label.c_str(), row.measurement.total.medianUs, row.error.mean,
                    row.error.maeClamped, row.error.rmseClamped, row.error.nonFinite);
        std::fflush(stdout);
        rows.push_back(std::move(row));
    }
    return rows;
}

// The share of rays traced, as the effect's study names it (EffectStudy::tracedCounter): the
// counter alone, or traced / (traced + answered); "" without its counters.
std::string tracedShare(const std::string& effect, const Measurement& measurement) {
    const EffectStudy& study = studyOf(effect);
    if (study.tracedCounter.empty()) return "";
    if (study.answeredCounter.empty()) return counterValue(measurement, effect + "/" + study.tracedCounter);
    const std::optional<double> traced = counterNumber(measurement, effect + "/" + study.tracedCounter);
    const std::optional<double> answered = counterNumber(measurement, effect + "/" + study.answeredCounter);
    if (!traced || !answered) return "";
    return formatNumber(*traced + *answered > 0.0 ? *traced / (*traced + *answered) : 0.0);
}

// A CSV field of a value that may be missing: "" then.
std::string optionalField(const std::optional<double>& value) {
    return value ? formatNumber(*value) : "";
}

// `choices`: the presets and the budget choice (choosePresetsAndBudget), kept in study.json.
void writeResults(const Plan& plan, const gpu::Context& context, const std::vector<Row>& rows,
                  const nlohmann::json& choices) {
    const nlohmann::json device = deviceJson(context);
    nlohmann::json json{{"device", device},
                        {"width", plan.width},
                        {"height", plan.height},
                        {"frames", plan.frames},
                        {"runs", plan.runs},
                        {"radiance_clamp", replay::kMaeClamp},
                        {"rows", nlohmann::json::array()}};
    json.update(choices);
    std::ostringstream csv;
    csv << "scene,effect,label,settings,time_us,time_min_us,time_max_us,passes,error_mean,rmse,mae,rmse_"
           "clamped,"
           "penumbra,moving_edge,noisy_moving_edge,moving_edge_pixels,non_finite,traced_fraction,reference_"
           "spp,"
           "floor_error_mean,floor_mae,floor_rmse_clamped,"
           "output,"
           "reference,reference2,mask,device\n";
    for (const Row& row : rows) {
        const std::string traced = tracedShare(row.effect, row.measurement);
        csv << row.scene << "," << row.effect << "," << row.label << "," << joined(row.settings) << ","
            << row.measurement.total.medianUs << "," << row.measurement.total.minUs << ","
            << row.measurement.total.maxUs << "," << passesField(row.measurement) << "," << row.error.mean
            << "," << row.error.rmse << "," << row.error.maeClamped << "," << row.error.rmseClamped << ","
            << row.error.penumbra << "," << optionalField(row.error.movingEdge) << ","
            << optionalField(row.error.noisyMovingEdge) << ","
            << (row.error.visibility ? std::to_string(row.error.movingEdgePixels) : "") << ","
            << row.error.nonFinite << "," << traced << "," << row.referenceSpp << ","
            << (row.floor ? formatNumber(row.floor->mean) : "") << ","
            << (row.floor ? formatNumber(row.floor->maeClamped) : "") << ","
            << (row.floor ? formatNumber(row.floor->rmseClamped) : "") << "," << row.output << ","
            << row.reference << "," << row.reference2 << "," << row.mask << ","
            << csvField(device["name"].get<std::string>()) << "\n";
        nlohmann::json entry = measurementJson(row.measurement);
        entry.update({{"scene", row.scene},
                      {"effect", row.effect},
                      {"label", row.label},
                      {"settings", row.settings},
                      {"time_us", row.measurement.total.medianUs},
                      {"error_mean", row.error.mean},
                      {"rmse", row.error.rmse},
                      {"mae", row.error.maeClamped},
                      {"rmse_clamped", row.error.rmseClamped},
                      {"reference_spp", row.referenceSpp},
                      {"penumbra", row.error.penumbra},
                      {"non_finite", row.error.nonFinite},
                      {"pixels", row.error.pixels},
                      {"traced_fraction", traced},
                      {"output", row.output},
                      {"reference", row.reference},
                      {"mask", row.mask}});
        if (row.error.visibility) {
            // null where no receiver of the last frame is a moving edge.
            const auto orNull = [](const std::optional<double>& value) {
                return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
            };
            entry["moving_edge"] = orNull(row.error.movingEdge);
            entry["noisy_moving_edge"] = orNull(row.error.noisyMovingEdge);
            entry["moving_edge_pixels"] = row.error.movingEdgePixels;
        }
        if (row.floor) {
            entry["reference2"] = row.reference2;
            entry["floor"] = {{"error_mean", row.floor->mean},
                              {"mae", row.floor->maeClamped},
                              {"rmse_clamped", row.floor->rmseClamped},
                              {"penumbra", row.floor->penumbra}};
        }
        json["rows"].push_back(entry);
    }
    writeText(plan.out / "study.csv", csv.str());
    writeText(plan.out / "study.json", json.dump(2) + "\n");
}

Plan resolve(const StudyOptions& options) {
    Plan plan;
    plan.out = options.outDir;
    plan.quick = options.quick;
    // "all": every scored effect with a study, in the registry's order.
    std::vector<std::string> studied, all;
    for (const EffectDescriptor* effect : effectRegistry())
        if (effect->evaluation.study) {
            studied.push_back(effect->name);
            if (!effect->evaluation.scored.empty()) all.push_back(effect->name);
        }
    if (options.effect == "all")
        plan.effects = all;
    else if (std::find(studied.begin(), studied.end(), options.effect) != studied.end())
        plan.effects = {options.effect};
    else
        throw std::invalid_argument("study: --effect must be " + joined(studied, ", ") + " or all, got '" +
                                    options.effect + "'");
    plan.scenes = options.scenes;
    for (const std::string& scene : plan.scenes)
        if (!std::filesystem::exists(scene))
            throw std::invalid_argument("study: " + scene + ": no such file");
    plan.width = options.width ? options.width : (options.quick ? 64u : 1920u);
    plan.height = options.height ? options.height : (options.quick ? 36u : 1080u);
    plan.frames = options.frames ? options.frames : (options.quick ? 3u : 16u);
    plan.runs = options.runs ? options.runs : (options.quick ? 2u : 50u);
    plan.spp = options.spp;
    plan.floors = !options.noFloor;
    if (options.budgetUs) {
        if (options.scaling)
            throw std::invalid_argument(
                "study: --budget-us goes with the settings sweep, not with --scaling");
        if (!(*options.budgetUs > 0.0) || !std::isfinite(*options.budgetUs))
            throw std::invalid_argument("study: --budget-us must be a positive number of microseconds, got " +
                                        formatNumber(*options.budgetUs));
        plan.budgetUs = options.budgetUs;
    }
    return plan;
}

} // namespace

SimulatedScene simulateFor(const gpu::Context& context, const std::string& path, const std::string& effect,
                           std::uint32_t width, std::uint32_t height, std::uint32_t frames,
                           std::uint32_t referenceSpp, std::uint32_t seedOffset) {
    scene::Scene scene = scene::loadScene(path);
    scene.seed += seedOffset;
    scene.width = width;
    scene.height = height;
    scene.frameCount = frames;
    const EffectDescriptor& descriptor = *findEffect(effect);
    scene.effects = {scene::effectNamed(studyOf(effect).simulateAs)};
    scene.reference = {};
    if (referenceSpp > 0 && !descriptor.reference.empty()) {
        scene::requestReference(scene.reference, descriptor.reference);
        scene.reference.samplesPerPixel = referenceSpp;
    }
    scene::Simulation simulation = scene::simulate(context, scene);
    return {std::filesystem::path(path).stem().string(), std::filesystem::absolute(path).string(),
            std::move(simulation.frames), simulation.environment.value_or(blackEnvironment())};
}

std::vector<std::string> baseSettings(const std::string& effect) {
    return studyOf(effect).baseSettings;
}

std::string joined(const std::vector<std::string>& items, const char* separator) {
    std::string text;
    for (const std::string& item : items) text += (text.empty() ? "" : separator) + item;
    return text;
}

std::string passesField(const Measurement& measurement) {
    std::vector<std::string> passes;
    char value[32];
    for (const PassStats& pass : measurement.passes) {
        std::snprintf(value, sizeof value, ":%.2f", pass.medianUs);
        passes.push_back(pass.pass + value);
    }
    return joined(passes);
}

std::optional<double> counterNumber(const Measurement& measurement, const std::string& name) {
    for (const replay::Counter& counter : measurement.counters)
        if (counter.name == name) return counter.value;
    return std::nullopt;
}

std::string formatNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

std::string counterValue(const Measurement& measurement, const std::string& name) {
    const std::optional<double> value = counterNumber(measurement, name);
    return value ? formatNumber(*value) : "";
}

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

void writeText(const std::filesystem::path& file, const std::string& text) {
    std::filesystem::create_directories(file.parent_path());
    std::ofstream stream(file);
    if (!(stream << text)) throw std::runtime_error("study: " + file.string() + ": cannot write");
    std::printf("wrote %s\n", file.string().c_str());
}

} // namespace study

void addStudyOptions(CLI::App& command, StudyOptions& options) {
    command
        .add_option("--out", options.outDir, "output folder (study.csv, study.json, presets.toml, images/)")
        ->required();
    command.add_option("--effect", options.effect, "reflections | shadows | hybrid | all")
        ->capture_default_str();
    command.add_option("--scenes", options.scenes, "scene files (default: three bundled scenes per effect)")
        ->delimiter(',');
    command.add_option("--size", options.size, "resolution WxH (default 1920x1080)");
    command.add_option("--frame-count", options.frames,
                       "frames per point; the last is measured (default 16)");
    command.add_option("--spp", options.spp, "reference samples per pixel");
    command.add_option("--runs", options.runs, "timed runs per point (default 50)");
    command.add_flag("--quick", options.quick, "tiny sizes, few frames and points (smoke test)");
    command.add_flag("--no-floor", options.noFloor,
                     "skip the second, independent reference (no reference noise floor)");
    command.add_option("--budget-us", options.budgetUs,
                       "name the most accurate measured point whose GPU time fits this budget");
    command.add_flag("--scaling", options.scaling,
                     "time against resolution and against the fraction of affected pixels");
}

int runStudy(StudyOptions options, bool validate) {
    if (!options.size.empty() &&
        std::sscanf(options.size.c_str(), "%ux%u", &options.width, &options.height) != 2)
        throw std::invalid_argument("study: --size must read WxH, e.g. 1920x1080");
    options.validate = validate;
    const study::Plan plan = study::resolve(options);
    return withContext(options.validate, [&](const gpu::Context& context) -> int {
        std::printf("device: %s, driver %s %s, subgroup %u\n", context.info.name.c_str(),
                    context.info.driverName.c_str(), context.info.driverInfo.c_str(),
                    context.device.subgroupSize);
        if (options.scaling) return study::runScaling(plan, context);
        std::printf("study at %ux%u, %u frames (the last is measured), %u timed runs per point\n", plan.width,
                    plan.height, plan.frames, plan.runs);
        std::vector<study::Row> rows;
        for (const std::string& effect : plan.effects) {
            const std::vector<std::string> scenes =
                plan.scenes.empty() ? study::defaultScenes(effect, plan.quick) : plan.scenes;
            for (const std::string& path : scenes) {
                const bool scored = replay::scoredOutput(effect) != nullptr;
                const std::uint32_t spp = scored ? study::referenceSpp(plan, effect) : 0;
                const study::SimulatedScene scene =
                    study::simulateFor(context, path, effect, plan.width, plan.height, plan.frames, spp);
                std::optional<study::SimulatedScene> second;
                if (plan.floors && scored)
                    second = study::simulateFor(context, path, effect, plan.width, plan.height, plan.frames,
                                                spp, study::kSecondReferenceSeedOffset);
                std::vector<study::Row> more =
                    study::sweep(context, plan, effect, scene, second ? &*second : nullptr);
                rows.insert(rows.end(), std::make_move_iterator(more.begin()),
                            std::make_move_iterator(more.end()));
            }
        }
        std::vector<study::Measured> measured;
        for (const study::Row& row : rows)
            measured.push_back({row.effect, row.scene, row.label, row.settings,
                                row.measurement.total.medianUs, row.error.mean});
        const nlohmann::json choices = study::choosePresetsAndBudget(plan, context.info.name, measured);
        study::writeResults(plan, context, rows, choices);
        bool finite = true;
        for (const study::Row& row : rows) finite = finite && row.error.nonFinite == 0.0;
        if (!finite) std::fprintf(stderr, "glint: study: non-finite output pixels (see study.csv)\n");
        return finite ? kExitOk : kExitCheckFailed;
    });
}

} // namespace glint::cli
