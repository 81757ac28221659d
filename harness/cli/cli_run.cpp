// glint run: a capture or sequence through the effects it declares (or --effects), histories
// carried across frames. Writes per frame the outputs as EXR with PNG previews and, where the
// capture has references, an error heat map; prints a progress bar, then a summary table of
// per-pass GPU times and errors; writes summary.json (docs/replay.md).
#include "cli_capture.h"
#include "cli_commands.h"
#include "cli_images.h"

#include "replay/replay_error.h"
#include "replay/replay_session.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <limits>
#include <map>
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

double median(std::vector<double> values) {
    if (values.empty()) return -1.0;
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

} // namespace

int runRun(const ReplayOptions& options) {
    if (options.outDir.empty()) throw std::invalid_argument("run: --out DIR is required");
    const CaptureSource source(options.capture, options.mapPath);
    const FrameRange range = parseFrames(options.frames, source.frameCount());
    replay::SessionOptions sessionOptions;
    sessionOptions.effects = options.effects;
    setGeometry(sessionOptions, source.sceneFile(), options.geometry);
    sessionOptions.settings = replay::parseSettings(options.settings);
    const std::filesystem::path out(options.outDir);

    // Every frame's header, camera and layers before anything is written.
    source.checkFrames(range.first, range.last, sessionOptions);
    const capture::Frame first = source.frame(range.first);
    source.checkEffects(first, range.first, sessionOptions);

    return withContext(options.validate, [&](const gpu::Context& context) {
        replay::Session session(context, first, source.environment(), sessionOptions);
        nlohmann::json summary;
        summary["capture"] = source.description();
        summary["device"] = {{"name", context.info.name},
                             {"driver", context.info.driverName + " " + context.info.driverInfo},
                             {"subgroupSize", context.device.subgroupSize}};
        summary["effects"] = session.effects();
        summary["settings"] = options.settings;
        summary["frames"] = nlohmann::json::array();
        std::vector<std::string> passOrder;
        std::map<std::string, std::vector<double>> passTimes;
        // effect -> mean error per frame; NaN where the frame's mask held no pixel (nothing scored)
        std::map<std::string, std::vector<double>> errors;
        std::map<std::string, double> noisyErrors; // effect -> its noisy input's, last frame
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
            const capture::Frame frame = index == range.first ? first : source.frame(index);
            const replay::FrameResult result = session.run(frame);
            // Named by the input's own frame number (Blender's 0001.exr -> frame_0001).
            const std::string folder = frameFolderName(source.frameNumber(index));
            const std::filesystem::path dir = out / folder;
            nlohmann::json record{{"frame", index},
                                  {"number", source.frameNumber(index)},
                                  {"folder", folder},
                                  {"input", source.framePath(index)},
                                  {"images", nlohmann::json::array()}};
            for (const replay::NamedImage& image : result.images) {
                writeImageFiles(dir, fileStem(image.name), image.name, image.image, true);
                record["images"].push_back(image.name);
            }
            for (const replay::PassTime& time : result.timings) {
                if (!passTimes.contains(time.pass)) passOrder.push_back(time.pass);
                passTimes[time.pass].push_back(time.milliseconds);
                record["timings"][time.pass] = time.milliseconds;
            }
            for (const replay::Counter& counter : result.counters)
                record["counters"][counter.name] = counter.value;
            for (const replay::ReferenceError& error :
                 replay::referenceErrors(frame, result, sessionOptions.settings.real("roughnessThreshold"))) {
                writeImageFiles(dir, error.effect + "_error", error.effect + "/error", error.map, true);
                errors[error.effect].push_back(error.pixels > 0 ? error.mean
                                                                : std::numeric_limits<double>::quiet_NaN());
                noisyErrors[error.effect] = error.noisyMean;
                record["errors"][error.effect] = {
                    {"image", error.image}, {"pixels", error.pixels},     {"mean", error.mean},
                    {"rmse", error.rmse},   {"penumbra", error.penumbra}, {"nonFinite", error.nonFinite}};
                if (error.nonFinite > 0.0) ++nonFiniteFrames;
            }
            summary["frames"].push_back(record);
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
        for (const std::string& setting : options.settings) std::printf("  set %s\n", setting.c_str());
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
        const auto scoredJson = [](double value) {
            return std::isnan(value) ? nlohmann::json(nullptr) : nlohmann::json(value);
        };
        for (const auto& [effect, values] : errors) {
            const double noisy = std::isnan(values.back()) ? -1.0 : noisyErrors[effect];
            std::printf("error of %s against the reference: first frame %s, last frame %s", effect.c_str(),
                        scored(values.front()).c_str(), scored(values.back()).c_str());
            if (noisy >= 0.0) std::printf(" (its noisy input %.4f)", noisy);
            if (std::isnan(values.back())) std::printf(" (no pixel of the last frame is in its error mask)");
            std::printf("\n");
            summary["error"][effect] = {{"first", scoredJson(values.front())},
                                        {"last", scoredJson(values.back())},
                                        {"noisyLast", noisy}};
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
