// glint study --scaling: does the work follow what the frame calls for? Per effect, GPU time
// against resolution (the scene simulated at 720p, 1080p, 1440p and 4K) and against the
// fraction of pixels the effect works on (0, 25, 50, 100 %), made exact by rewriting the input
// its study names (EffectStudy::scalingInput) in memory: a material's top rows are glossy and
// the rest fully rough, a shadow visibility's top rows hold 1-sample penumbra noise and the rest
// is fully lit. An effect whose study names no scaling scene is not scaled. Writes scaling.csv
// and scaling.json.
#include "cli_study.h"

#include "replay/replay_settings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace glint::cli::study {
namespace {

struct Size {
    std::uint32_t width, height;
};

const EffectStudy& studyOf(const std::string& effect) {
    return *findEffect(effect)->evaluation.study; // resolve() admits only effects with a study
}

std::string sceneFor(const Plan& plan, const std::string& effect) {
    if (!plan.scenes.empty()) return plan.scenes.front();
    return studyOf(effect).scalingScene;
}

std::uint32_t glossyRows(const capture::Frame& frame, double fraction) {
    return static_cast<std::uint32_t>(std::lround(fraction * frame.height));
}

// Perceptual roughness 0.3 (alpha 0.09: glossy, traced, not a mirror) in the first rows, 1 below.
void setGlossyRows(capture::Frame& frame, double fraction) {
    capture::Layer* layer = capture::findLayer(frame, frame.roughness.layer);
    const int channel = layer ? capture::channelIndex(layer->channels, frame.roughness.channel) : -1;
    if (channel < 0) throw std::runtime_error("study: the scene's frames have no roughness channel");
    const float glossy = frame.roughness.perceptual ? 0.3f : 0.09f;
    const std::size_t stride = layer->channels.size();
    for (std::uint32_t y = 0; y < frame.height; ++y)
        for (std::uint32_t x = 0; x < frame.width; ++x)
            layer->pixels[(std::size_t{y} * frame.width + x) * stride + static_cast<std::size_t>(channel)] =
                y < glossyRows(frame, fraction) ? glossy : 1.0f;
}

// Visibility 0 or 1 with even odds, new every frame, in the first rows; lit (1) below.
void setPenumbraRows(capture::Frame& frame, double fraction) {
    capture::Layer* layer = capture::findLayer(frame, "shadow");
    if (!layer) throw std::runtime_error("study: the scene's frames have no shadow layer");
    const std::size_t stride = layer->channels.size();
    for (std::uint32_t y = 0; y < frame.height; ++y)
        for (std::uint32_t x = 0; x < frame.width; ++x) {
            std::uint32_t hash = (x * 73856093u) ^ (y * 19349663u) ^ (frame.frameIndex * 83492791u);
            hash ^= hash >> 13;
            hash *= 0x5bd1e995u;
            hash ^= hash >> 15;
            const float noisy = static_cast<float>(hash & 1u);
            layer->pixels[(std::size_t{y} * frame.width + x) * stride] =
                y < glossyRows(frame, fraction) ? noisy : 1.0f;
        }
}

struct Row {
    std::string effect, sweep, scene;
    std::uint32_t width = 0, height = 0;
    double fraction = -1.0; // -1: the scene as rendered
    Measurement measurement;
};

Row measure(const gpu::Context& context, const Plan& plan, const std::string& effect,
            const SimulatedScene& scene, const std::string& sweep, double fraction) {
    replay::SessionOptions options;
    options.effects = {effect};
    options.settings = replay::parseSettings(baseSettings(effect));
    Row row{effect, sweep, scene.name, scene.frames.front().width, scene.frames.front().height, fraction, {}};
    row.measurement = measureFrames(context, scene.frames, scene.environment, options, plan.runs);
    std::printf("  %-12s %-10s %5ux%-5u %8s %10.1f us", effect.c_str(), sweep.c_str(), row.width, row.height,
                fraction < 0.0 ? "scene" : (std::to_string(std::lround(100.0 * fraction)) + " %").c_str(),
                row.measurement.total.medianUs);
    for (const replay::Counter& counter : row.measurement.counters)
        std::printf("   %s %.4g", counter.name.c_str(), counter.value);
    std::printf("\n");
    std::fflush(stdout);
    return row;
}

void writeScaling(const Plan& plan, const gpu::Context& context, const std::vector<Row>& rows) {
    const nlohmann::json device = deviceJson(context);
    nlohmann::json json{{"device", device}, {"runs", plan.runs}, {"rows", nlohmann::json::array()}};
    std::ostringstream csv;
    csv << "effect,sweep,scene,width,height,fraction,time_us,time_min_us,time_max_us,passes,traced_fraction,"
           "listed_tiles,filtered_tiles,device\n";
    for (const Row& row : rows) {
        const Measurement& m = row.measurement;
        csv << row.effect << "," << row.sweep << "," << row.scene << "," << row.width << "," << row.height
            << "," << row.fraction << "," << m.total.medianUs << "," << m.total.minUs << "," << m.total.maxUs
            << "," << passesField(m) << "," << counterValue(m, "reflections/traced_fraction") << ","
            << counterValue(m, "reflections/listed_tiles") << "," << counterValue(m, "shadows/filtered_tiles")
            << "," << csvField(device["name"].get<std::string>()) << "\n";
        nlohmann::json entry = measurementJson(m);
        entry.update({{"effect", row.effect},
                      {"sweep", row.sweep},
                      {"scene", row.scene},
                      {"width", row.width},
                      {"height", row.height},
                      {"fraction", row.fraction},
                      {"time_us", m.total.medianUs}});
        json["rows"].push_back(entry);
    }
    writeText(plan.out / "scaling.csv", csv.str());
    writeText(plan.out / "scaling.json", json.dump(2) + "\n");
}

} // namespace

int runScaling(const Plan& plan, const gpu::Context& context) {
    const std::vector<Size> sizes =
        plan.quick ? std::vector<Size>{{32, 18}, {64, 36}, {96, 54}, {128, 72}}
                   : std::vector<Size>{{1280, 720}, {1920, 1080}, {2560, 1440}, {3840, 2160}};
    // Two frames: enough for histories to be read; the timed runs cycle through them.
    const std::uint32_t frames = std::min(plan.frames, 2u);
    std::printf("scaling: %u timed runs per point; fractions at %ux%u\n", plan.runs, plan.width, plan.height);
    std::vector<Row> rows;
    for (const std::string& effect : plan.effects) {
        const EffectStudy& study = studyOf(effect);
        if (study.scalingScene.empty()) {
            std::printf("scaling: %s is not scaled (its study names no scaling scene)\n", effect.c_str());
            continue;
        }
        const std::string path = sceneFor(plan, effect);
        for (const Size& size : sizes)
            rows.push_back(measure(context, plan, effect,
                                   simulateFor(context, path, effect, size.width, size.height, frames, 0),
                                   "resolution", -1.0));
        const SimulatedScene scene = simulateFor(context, path, effect, plan.width, plan.height, frames, 0);
        for (const double fraction : {0.0, 0.25, 0.5, 1.0}) {
            SimulatedScene modified = scene;
            for (capture::Frame& frame : modified.frames) {
                if (study.scalingInput == InputKind::Material)
                    setGlossyRows(frame, fraction);
                else if (study.scalingInput == InputKind::ShadowVisibility)
                    setPenumbraRows(frame, fraction);
                else
                    throw std::invalid_argument(
                        "study: --scaling rewrites a Material or ShadowVisibility input, "
                        "not the one " +
                        effect + "'s study names");
            }
            rows.push_back(measure(context, plan, effect, modified, "fraction", fraction));
        }
    }
    writeScaling(plan, context, rows);
    return kExitOk;
}

} // namespace glint::cli::study
