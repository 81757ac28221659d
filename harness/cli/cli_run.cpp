// glint run: a capture or sequence through the effects it declares (or --effects), histories
// carried across frames. Writes per frame the outputs as EXR with PNG previews and, where the
// capture has references, an error heat map and the error mask (EXR); prints a progress bar,
// then a summary table of per-pass GPU times and errors; writes summary.json (docs/replay.md).
// With --second-reference, each frame's reference noise floor: the capture's references
// against another seed's, and that seed's reference images (EXR).
#include "cli_capture.h"
#include "cli_commands.h"
#include "cli_images.h"

#include "replay/replay_error.h"
#include "replay/replay_session.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <unistd.h>

namespace glint::cli {
namespace {

void progress(std::size_t done, std::size_t total) {
    if (total < 2) return;
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(kWidth * done / total);
    std::fprintf(stderr, "\r[%.*s%*s] %zu/%zu frames", filled, "##############################",
                 kWidth - filled, "", done, total);
    if (done == total) std::fprintf(stderr, "\n");
    std::fflush(stderr);
}

// The previews a scored output's evaluation names (ScoredOutput::outsideMaskShownAs: the
// shadows' noisy, denoised and reference) show every pixel outside its error mask as the value
// the effect gives them there (the shadows' non-receivers lit, 1: docs/shadow_denoiser.md,
// "Non-receivers"), so the images differ only inside the mask. The EXR files keep the values
// as written.
void writeMaskedPreview(const std::filesystem::path& dir, const replay::NamedImage& image,
                        const std::vector<std::uint8_t>& mask, float outside) {
    report::Image preview = image.image;
    for (std::size_t i = 0; i < mask.size(); ++i)
        if (!mask[i])
            for (std::uint32_t c = 0; c < preview.channels; ++c)
                preview.pixels[i * preview.channels + c] = outside;
    report::writePng((dir / (fileStem(image.name) + ".png")).string(), preview,
                     previewMapping(image.name, preview));
}

// The simulation.json glint simulate wrote next to a sequence's manifest (the capture folder or
// its manifest.json), or null when there is none (a capture not simulated by glint, a single
// frame). A file that is there but unreadable is an error naming it.
nlohmann::json simulationOf(const std::string& capture) {
    std::filesystem::path dir(capture);
    if (!std::filesystem::is_directory(dir)) dir = dir.parent_path();
    const std::filesystem::path path = dir / "simulation.json";
    if (!std::filesystem::is_regular_file(path)) return nullptr;
    std::ifstream file(path);
    const std::string text{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
    nlohmann::json simulation = nlohmann::json::parse(text, nullptr, false);
    if (!file || simulation.is_discarded() || !simulation.is_object())
        throw std::invalid_argument("run: " + path.string() + ": not a JSON object");
    return simulation;
}

// The scored output whose previews show `name` ("<effect>/<output>") masked, or none.
const ScoredOutput* maskedPreview(const std::string& name) {
    const std::size_t slash = name.find('/');
    if (slash == std::string::npos) return nullptr;
    const ScoredOutput* scored = replay::scoredOutput(name.substr(0, slash));
    if (!scored) return nullptr;
    const std::vector<std::string>& shown = scored->outsideMaskShownAs;
    return std::find(shown.begin(), shown.end(), name.substr(slash + 1)) != shown.end() ? scored : nullptr;
}

// A score where the frame's mask held pixels to score, null where it held none (docs/replay.md:
// never a 0 that reads as a perfect result, nor a -1 that reads as a number).
nlohmann::json scoredOrNull(bool scored, double value) {
    return scored ? nlohmann::json(value) : nlohmann::json(nullptr);
}

double median(std::vector<double> values) {
    if (values.empty()) return -1.0;
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

} // namespace

void addRunOptions(CLI::App& command, ReplayOptions& options) {
    addReplayOptions(command, options);
    command.add_option("--out", options.outDir, "output folder")->required();
    command.add_option("--frames", options.frames, "frames a..b (inclusive), a.. or a");
    command.add_flag("--json", options.json, "also print the summary as JSON");
    command.add_option("--second-reference", options.secondReference,
                       "the same capture simulated with another --seed: its references against the "
                       "capture's give each frame's reference noise floor (docs/replay.md)");
}

int runRun(ReplayOptions options, bool validate) {
    // An unknown preset or an unreadable preset file fails before any capture is read.
    checkPresetChoice(options.preset);
    options.validate = validate;
    if (options.outDir.empty()) throw std::invalid_argument("run: --out DIR is required");
    const CaptureSource source(options.capture, options.mapPath);
    const FrameRange range = parseFrames(options.frames, source.frameCount());
    replay::SessionOptions sessionOptions;
    sessionOptions.effects = options.effects;
    setGeometry(sessionOptions, source.sceneFile(), options.geometry);
    const std::vector<std::string> settings = settingsWithPreset(options, source);
    sessionOptions.settings = replay::parseSettings(settings);
    const std::filesystem::path out(options.outDir);

    // Every frame's header, camera and layers before anything is written.
    source.checkFrames(range.first, range.last, sessionOptions);
    const capture::Frame first = source.frame(range.first);
    source.checkEffects(first, range.first, sessionOptions);
    // The frame before each replayed one, whose reference gives the moving edges
    // (replay::referenceErrors): before the first, the capture's frame before the range, if any.
    std::optional<capture::Frame> previous;
    if (range.first > 0) previous = source.frame(range.first - 1);
    std::unique_ptr<CaptureSource> second;
    if (!options.secondReference.empty()) {
        second = std::make_unique<CaptureSource>(options.secondReference);
        if (second->frameCount() < range.last + 1)
            throw std::invalid_argument("run: --second-reference " + options.secondReference + " has " +
                                        std::to_string(second->frameCount()) + " frame(s), the capture " +
                                        std::to_string(source.frameCount()));
    }

    return withContext(options.validate, [&](const gpu::Context& context) {
        replay::Session session(context, first, source.environment(), sessionOptions);
        nlohmann::json summary;
        summary["capture"] = source.description();
        summary["device"] = {{"name", context.info.name},
                             {"driver", context.info.driverName + " " + context.info.driverInfo},
                             {"subgroupSize", context.device.subgroupSize}};
        summary["effects"] = session.effects();
        summary["width"] = first.width;
        summary["height"] = first.height;
        if (nlohmann::json simulation = simulationOf(options.capture); !simulation.is_null())
            summary["simulation"] = simulation;
        if (second)
            if (nlohmann::json simulation = simulationOf(options.secondReference); !simulation.is_null())
                summary["secondReference"] = simulation;
        summary["settings"] = settings;
        if (!options.preset.name.empty()) summary["preset"] = options.preset.name;
        summary["frames"] = nlohmann::json::array();
        std::vector<std::string> passOrder;
        std::map<std::string, std::vector<double>> passTimes;
        // effect -> mean error per frame; NaN where the frame's mask held no pixel (nothing scored)
        std::map<std::string, std::vector<double>> errors;
        std::map<std::string, double> noisyErrors;    // effect -> its noisy input's, last frame
        std::map<std::string, double> noiseFloors;    // effect -> reference noise floor, last frame
        std::map<std::string, double> maskThresholds; // effect -> its error mask's threshold
        std::size_t nonFiniteFrames = 0;

        const std::size_t total = range.last - range.first + 1;
        // An error after the progress bar has started goes on a line of its own.
        struct EndProgressLine {
            bool shown;
            ~EndProgressLine() {
                if (shown && std::uncaught_exceptions() > 0) std::fprintf(stderr, "\n");
            }
        } endProgressLine{false};
        for (std::size_t index = range.first; index <= range.last; ++index) {
            capture::Frame frame = index == range.first ? first : source.frame(index);
            const replay::FrameResult result = session.run(frame);
            // Named by the input's own frame number (Blender's 0001.exr -> frame_0001).
            const std::string folder = frameFolderName(source.frameNumber(index));
            const std::filesystem::path dir = out / folder;
            nlohmann::json record{{"frame", index},
                                  {"number", source.frameNumber(index)},
                                  {"folder", folder},
                                  {"input", source.framePath(index)},
                                  {"images", nlohmann::json::array()}};
            const SettingValues& values = sessionOptions.settings;
            std::map<const ScoredOutput*, std::vector<std::uint8_t>> masks; // of the masked previews
            for (const replay::NamedImage& image : result.images) {
                const ScoredOutput* masked = maskedPreview(image.name);
                writeImageFiles(dir, fileStem(image.name), image.name, image.image, !masked);
                if (masked) {
                    if (!masks.contains(masked))
                        masks[masked] = replay::errorMask(frame, masked->mask, values);
                    writeMaskedPreview(dir, image, masks[masked], masked->outsideMaskValue);
                }
                record["images"].push_back(image.name);
            }
            for (const replay::PassTime& time : result.timings) {
                if (!passTimes.contains(time.pass)) passOrder.push_back(time.pass);
                passTimes[time.pass].push_back(time.milliseconds);
                record["timings"][time.pass] = time.milliseconds;
            }
            for (const replay::Counter& counter : result.counters)
                record["counters"][counter.name] = counter.value;
            if (second) {
                const capture::Frame secondFrame = second->frame(index);
                for (const replay::ReferenceError& noise :
                     replay::referenceNoise(frame, result, secondFrame, values)) {
                    const bool any = noise.pixels > 0;
                    record["referenceNoise"][noise.effect] = {
                        {"mean", scoredOrNull(any, noise.mean)},
                        {"rmse", scoredOrNull(any, noise.rmse)},
                        {"maeClamped", scoredOrNull(any, noise.maeClamped)},
                        {"rmseClamped", scoredOrNull(any, noise.rmseClamped)}};
                    if (!std::isnan(noise.differenceAgainstSecond))
                        record["referenceNoise"][noise.effect]["differenceAgainstSecond"] =
                            noise.differenceAgainstSecond;
                    noiseFloors[noise.effect] = any ? noise.mean : std::numeric_limits<double>::quiet_NaN();
                    // The second reference itself, for scores computed outside glint
                    // (scripts/run_flip.py's FLIP floor): EXR only.
                    writeImageFiles(dir, noise.effect + "_reference2", noise.effect + "/reference2",
                                    referenceImage(secondFrame, noise.effect), false);
                }
            }
            for (const replay::ReferenceError& error :
                 replay::referenceErrors(frame, result, values, previous ? &*previous : nullptr)) {
                const ScoredOutput& scored = *replay::scoredOutput(error.effect);
                writeImageFiles(dir, error.effect + "_error", error.effect + "/error", error.map, true);
                // The pixels the error was measured over, for scripts/run_flip.py: EXR only.
                writeImageFiles(dir, error.effect + "_mask", error.effect + "/mask",
                                maskImage(frame, replay::errorMask(frame, scored.mask, values)), false);
                if (error.maskThreshold >= 0.0) maskThresholds[error.effect] = error.maskThreshold;
                errors[error.effect].push_back(error.pixels > 0 ? error.mean
                                                                : std::numeric_limits<double>::quiet_NaN());
                const bool any = error.pixels > 0;
                noisyErrors[error.effect] = any && error.noisyMean >= 0.0 ? error.noisyMean : -1.0;
                record["errors"][error.effect] = {
                    {"image", error.image},
                    {"pixels", error.pixels},
                    {"mean", scoredOrNull(any, error.mean)},
                    {"rmse", scoredOrNull(any, error.rmse)},
                    {"penumbra", scoredOrNull(error.penumbra >= 0.0, error.penumbra)},
                    {"nonFinite", error.nonFinite},
                    {"maeClamped", scoredOrNull(any, error.maeClamped)},
                    {"rmseClamped", scoredOrNull(any, error.rmseClamped)}};
                if (error.noisyMean >= 0.0)
                    record["errors"][error.effect]["noisyMean"] = scoredOrNull(any, error.noisyMean);
                if (error.noisyRmse >= 0.0)
                    record["errors"][error.effect]["noisyRmse"] = scoredOrNull(any, error.noisyRmse);
                if (error.visibility) {
                    // null where no receiver is a moving edge (the first frame, or nothing moved).
                    const auto orNull = [](const std::optional<double>& value) {
                        return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
                    };
                    record["errors"][error.effect]["movingEdgePixels"] = error.movingEdgePixels;
                    record["errors"][error.effect]["movingEdge"] = orNull(error.movingEdge);
                    if (!scored.noisy.empty() && result.find(error.effect + "/" + scored.noisy))
                        record["errors"][error.effect]["noisyMovingEdge"] = orNull(error.noisyMovingEdge);
                }
                if (error.nonFinite > 0.0) ++nonFiniteFrames;
            }
            summary["frames"].push_back(record);
            previous = std::move(frame);
            progress(index - range.first + 1, total);
            endProgressLine.shown = total >= 2 && index < range.last; // the last one ends its line
        }

        std::printf("device: %s, driver %s %s, subgroup %u\n", context.info.name.c_str(),
                    context.info.driverName.c_str(), context.info.driverInfo.c_str(),
                    context.device.subgroupSize);
        std::printf("capture %s: %ux%u, frames %zu..%zu, effects:", source.description().c_str(), first.width,
                    first.height, range.first, range.last);
        for (const std::string& effect : session.effects()) std::printf(" %s", effect.c_str());
        std::printf("\n");
        for (const std::string& setting : settings) std::printf("  set %s\n", setting.c_str());
        std::printf("%-28s %12s %12s %12s\n", "pass", "median us", "min us", "max us");
        double sum = 0.0;
        for (const std::string& pass : passOrder) {
            const std::vector<double>& values = passTimes[pass];
            const double m = median(values);
            sum += m;
            std::printf("%-28s %12.2f %12.2f %12.2f\n", pass.c_str(), 1000.0 * m,
                        1000.0 * *std::min_element(values.begin(), values.end()),
                        1000.0 * *std::max_element(values.begin(), values.end()));
            summary["passes"][pass] = {{"medianMs", m}};
        }
        if (passOrder.empty())
            std::printf("(no timestamps on this queue)\n");
        else
            std::printf("%-28s %12.2f\n", "all passes (sum of medians)", 1000.0 * sum);
        // A frame whose mask held no pixel scored nothing: said so, and null in summary.json,
        // rather than an error of 0 that reads as a perfect result.
        const auto scored = [](double value) {
            char text[32];
            std::snprintf(text, sizeof text, "%.4f", value);
            return std::isnan(value) ? std::string("no pixels scored") : std::string(text);
        };
        for (const auto& [effect, values] : errors) {
            const double noisy = noisyErrors[effect]; // -1: none (not denoised, or nothing scored)
            std::printf("error of %s against the reference: first frame %s, last frame %s", effect.c_str(),
                        scored(values.front()).c_str(), scored(values.back()).c_str());
            if (noisy >= 0.0) std::printf(" (its noisy input %.4f)", noisy);
            if (noiseFloors.contains(effect) && !std::isnan(noiseFloors[effect]))
                std::printf(" (reference noise floor %.4f)", noiseFloors[effect]);
            if (std::isnan(values.back())) std::printf(" (no pixel of the last frame is in its error mask)");
            std::printf("\n");
            summary["error"][effect] = {{"first", scoredOrNull(!std::isnan(values.front()), values.front())},
                                        {"last", scoredOrNull(!std::isnan(values.back()), values.back())},
                                        {"noisyLast", scoredOrNull(noisy >= 0.0, noisy)}};
            if (noiseFloors.contains(effect))
                summary["error"][effect]["referenceNoiseLast"] =
                    scoredOrNull(!std::isnan(noiseFloors[effect]), noiseFloors[effect]);
            // The threshold of the error mask (a setting's value, ErrorMask in glint_effect.h).
            if (maskThresholds.contains(effect))
                summary["error"][effect]["maskThreshold"] = maskThresholds[effect];
        }
        if (nonFiniteFrames > 0) std::printf("non-finite output pixels in %zu frame(s)\n", nonFiniteFrames);
        std::filesystem::create_directories(out);
        std::ofstream(out / "summary.json") << summary.dump(2) << "\n";
        std::printf("wrote %s\n", (out / "summary.json").string().c_str());
        if (options.json) std::printf("%s\n", summary.dump().c_str());
        return nonFiniteFrames > 0 ? kExitCheckFailed : kExitOk;
    });
}

} // namespace glint::cli
