// glint report: one self-contained HTML page from the folders `glint run` wrote: per run, the
// metric in words, a plot of the error against frame per effect (noisy input, output and the
// reference noise floor where the run measured one), for visibility effects one of the error
// over moving edges, and, where scripts/run_flip.py added it, one of LDR-FLIP, the last frame's
// images side by side (input, noisy, denoised, composite, reference, error), the errors with
// their moving edges and FLIP, per-pass GPU times; the device on top; with --anchors, other
// implementations' points listed beside the scene they were measured on, with their
// conditions. The demo's report.
#include "cli_capture.h"
#include "cli_commands.h"
#include "cli_report_summary.h"

#include "capture/json_text.h"
#include "replay/replay_error.h"
#include "report/report_html.h"

#include <CLI/CLI.hpp>
#include <glint/glint_effect.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iterator>

namespace glint::cli {
namespace {

nlohmann::json readSummary(const std::filesystem::path& dir) {
    std::ifstream file(dir / "summary.json");
    if (!file)
        throw std::invalid_argument("report: " + (dir / "summary.json").string() +
                                    " is missing (run glint run first)");
    const std::string text{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& error) {
        throw std::invalid_argument("report: " + (dir / "summary.json").string() +
                                    ": malformed JSON: " + capture::jsonProblem(error, text));
    }
}

std::string today() {
    const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%d", std::gmtime(&now));
    return text;
}

nlohmann::json readAnchors(const std::string& path) {
    if (path.empty()) return nlohmann::json::array();
    std::ifstream file(path);
    if (!file) throw std::invalid_argument("report: " + path + ": cannot open the anchors file");
    const std::string text{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
    nlohmann::json anchors;
    try {
        anchors = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& error) {
        throw std::invalid_argument("report: " + path +
                                    ": malformed JSON: " + capture::jsonProblem(error, text));
    }
    if (!anchors.is_object() || !anchors.contains("points") || !anchors.at("points").is_array())
        throw std::invalid_argument("report: " + path + ": no \"points\" array");
    for (const auto& point : anchors.at("points"))
        if (!point.is_object() || !point.contains("scene") || !point.at("scene").is_string() ||
            !point.contains("effect") || !point.at("effect").is_string())
            throw std::invalid_argument("report: " + path +
                                        ": a point without a \"scene\" or \"effect\" string");
    return anchors.at("points");
}

// The pixels `scored`'s error is measured over, in words: the descriptor's, or from its kind;
// `threshold` is the value of the mask's setting summary.json recorded (NaN: not recorded, a
// summary written before maskThreshold).
std::string maskWords(const ScoredOutput& scored, double threshold) {
    if (!scored.maskInWords.empty()) return scored.maskInWords;
    if (scored.mask.pixels == ErrorMask::Pixels::Surface) return "every pixel with a surface";
    return "the glossy pixels (a surface with GGX alpha below " + scored.mask.setting +
           (std::isnan(threshold) ? ", its value not recorded)" : " = " + fixedDecimals(threshold, 2) + ")");
}

// What "error" means for `effect`, in words (replay/replay_error.h is the definition), from its
// scored output's metric and mask; `values` is summary.json's error.<effect>.
std::string metricSentence(const std::string& effect, const nlohmann::json& values) {
    const ScoredOutput* scored = replay::scoredOutput(effect);
    if (!scored)
        return "Error of " + effect + ": not scored by this glint (its descriptor names no scored output).";
    const std::string mask = maskWords(*scored, valueOr(values, "maskThreshold"));
    switch (scored->metric) {
    case ErrorMetric::Visibility:
        return "Error of " + effect +
               ": the mean of |visibility - reference visibility| (both in [0, 1], so no clamp is needed) "
               "over " +
               mask + ". The error over moving edges is the same mean over the " +
               (scored->mask.pixels == ErrorMask::Pixels::Surface ? "pixels with a surface"
                                                                  : "glossy pixels") +
               " whose reference changed by more than " + fixedDecimals(replay::kMovingEdgeChange, 2) +
               " since the previous frame at the same pixel (none on the first frame).";
    case ErrorMetric::Absolute:
        return "Error of " + effect +
               ": per pixel, the luminance of |output - reference| (per channel, not clamped), averaged "
               "over " +
               mask + ". The table adds the mean absolute error of values clamped to [0, " +
               fixedDecimals(replay::kMaeClamp, 0) + "] and the unclamped RMSE, on the same mask.";
    case ErrorMetric::RelativeLuminance:
        break;
    }
    return "Error of " + effect +
           ": per pixel, the luminance of |output - reference| (per RGB channel, radiance not "
           "clamped) divided by max(luminance(reference), 0.05), averaged over " +
           mask +
           ". The table adds the mean absolute error of "
           "radiance clamped to [0, " +
           fixedDecimals(replay::kMaeClamp, 0) + "] and the unclamped RMSE, on the same mask.";
}

std::string referenceSentence(const nlohmann::json& summary) {
    if (!summary.contains("simulation"))
        return "The reference's sample count is not recorded (not a glint simulate capture).";
    const nlohmann::json& simulation = summary.at("simulation");
    std::string text = "Reference: " + std::to_string(simulation.value("referenceSpp", 0)) +
                       " samples per pixel (seed " + std::to_string(simulation.value("seed", 0)) + ")";
    if (summary.contains("secondReference"))
        text += "; its noise floor is its difference from a second reference of " +
                std::to_string(summary.at("secondReference").value("referenceSpp", 0)) +
                " samples per pixel with the independent seed " +
                std::to_string(summary.at("secondReference").value("seed", 0)) +
                ", in the same metric: an error at or below the floor cannot be told from zero";
    else
        text += "; no second reference was rendered, so its noise floor is not known";
    return text + ".";
}

// What the FLIP columns and plot are, in words: scripts/run_flip.py's metric (scripts/study.py's
// LDR-FLIP), or that it was not computed for this run.
std::string flipSentence(const nlohmann::json& summary) {
    if (!summary.contains("flip") || !summary.at("flip").is_object())
        return "FLIP was not computed for this run (\"-\"): scripts/run_flip.py adds it to summary.json.";
    const nlohmann::json& flip = summary.at("flip");
    const double clamp = flip.contains("clamp") && flip.at("clamp").is_number()
                             ? flip.at("clamp").get<double>()
                             : replay::kMaeClamp;
    return "FLIP (scripts/run_flip.py) is LDR-FLIP as scripts/study.py defines it: NVIDIA's "
           "flip-evaluator at 67 pixels per degree, given linear values, of radiance clamped to [0, " +
           fixedDecimals(clamp, 0) +
           "] and tone-mapped per channel with Reinhard x/(1+x), and of shadow visibility clamped to "
           "[0, 1]; both images are zeroed outside the error mask above and FLIP is averaged over the "
           "mask's pixels. 0 is identical; a frame whose mask is empty shows \"no pixels scored\".";
}

// The series of one per-frame value of errors.<effect> (and referenceNoise.<effect>): the noisy
// input's, the output's and the reference noise floor's, each left out where no frame has it.
report::Plot framePlot(const std::string& effect, const nlohmann::json& frames, const std::string& title,
                       const std::string& yLabel, const char* outputKey, const char* noisyKey,
                       const char* floorKey) {
    // floorKey null: the value has no reference noise floor.
    report::Plot plot;
    plot.title = effect + ": " + title;
    plot.xLabel = "frame";
    plot.yLabel = yLabel;
    report::PlotSeries noisy{"noisy input", {}, "#d62728"};
    report::PlotSeries output{"output (denoised)", {}, "#1f77b4"};
    report::PlotSeries floor{"reference noise floor", {}, "#555", true};
    bool anyNoisy = false, anyFloor = false, denoised = false;
    for (const auto& frame : frames) {
        const nlohmann::json errors = frame.value("errors", nlohmann::json::object());
        const nlohmann::json error = errors.value(effect, nlohmann::json::object());
        output.values.push_back(valueOr(error, outputKey));
        noisy.values.push_back(valueOr(error, noisyKey));
        anyNoisy = anyNoisy || error.contains(noisyKey);
        denoised = denoised || error.value("image", std::string{}).ends_with("/denoised");
        const nlohmann::json noise = frame.value("referenceNoise", nlohmann::json::object());
        const nlohmann::json effectNoise = noise.value(effect, nlohmann::json::object());
        floor.values.push_back(floorKey ? valueOr(effectNoise, floorKey) : std::nan(""));
        anyFloor = anyFloor || (floorKey && effectNoise.contains(floorKey));
    }
    if (!denoised) output.label = "output (not denoised)";
    if (anyNoisy) plot.series.push_back(std::move(noisy));
    plot.series.push_back(std::move(output));
    if (anyFloor) plot.series.push_back(std::move(floor));
    return plot;
}

report::Plot errorPlot(const std::string& effect, const nlohmann::json& frames) {
    return framePlot(effect, frames, "error against the reference", "mean error", "mean", "noisyMean",
                     "mean");
}

// Whether any frame holds errors.<effect>.<key> (a number, or null where nothing was scored).
bool anyFrameHas(const std::string& effect, const nlohmann::json& frames, const char* key) {
    for (const auto& frame : frames) {
        const nlohmann::json errors = frame.value("errors", nlohmann::json::object());
        if (errors.value(effect, nlohmann::json::object()).contains(key)) return true;
    }
    return false;
}

report::Plot flipPlot(const std::string& effect, const nlohmann::json& frames) {
    return framePlot(effect, frames, "LDR-FLIP against the reference", "mean LDR-FLIP", "flip", "noisyFlip",
                     "flip");
}

// Moving edges come and go from frame to frame, so each value is marked: a frame alone between
// frames without moving edges has no line to sit on.
report::Plot movingEdgePlot(const std::string& effect, const nlohmann::json& frames) {
    report::Plot plot = framePlot(effect, frames, "error over moving edges", "mean error over moving edges",
                                  "movingEdge", "noisyMovingEdge", nullptr);
    for (report::PlotSeries& series : plot.series) series.markers = true;
    return plot;
}

report::Section runSection(const std::filesystem::path& dir, const nlohmann::json& summary,
                           const nlohmann::json& anchors) {
    report::Section section;
    section.heading = dir.filename().string();
    std::string effects;
    for (const auto& effect : summary.at("effects"))
        effects += (effects.empty() ? "" : ", ") + effect.get<std::string>();
    section.lead = "Capture " + summary.value("capture", std::string{}) + "; effects: " + effects + ".";
    const nlohmann::json settings = summary.value("settings", nlohmann::json::array());
    for (const auto& setting : settings)
        section.text += (section.text.empty() ? "" : "\n") + ("set " + setting.get<std::string>());
    if (summary.contains("width") && summary.contains("height"))
        section.lead += " " + std::to_string(summary.at("width").get<unsigned>()) + "x" +
                        std::to_string(summary.at("height").get<unsigned>()) + ", " +
                        std::to_string(summary.at("frames").size()) + " frame(s).";
    const nlohmann::json& frames = summary.at("frames");
    if (summary.contains("error")) {
        section.text += "\n\n" + referenceSentence(summary);
        for (const auto& [effect, values] : summary.at("error").items()) {
            section.text += "\n" + metricSentence(effect, values);
            section.plots.push_back(errorPlot(effect, frames));
            if (anyFrameHas(effect, frames, "movingEdge"))
                section.plots.push_back(movingEdgePlot(effect, frames));
            if (anyFrameHas(effect, frames, "flip")) section.plots.push_back(flipPlot(effect, frames));
        }
        section.text += "\n" + flipSentence(summary);
    }
    // The scene the run was simulated from names the anchors that belong here.
    std::string scene = dir.filename().string();
    if (summary.contains("simulation"))
        scene = std::filesystem::path(summary.at("simulation").value("scene", scene)).stem().string();
    report::Table anchorTable{{"anchor (measured elsewhere; not on the plot, whose conditions differ)",
                               "effect", "FLIP", "MAE", "error measured", "time (us)", "time measured"},
                              {}};
    for (const auto& point : anchors) {
        if (point.at("scene").get<std::string>() != scene) continue;
        const auto number = [&](const char* key, int decimals) {
            return point.contains(key) && point.at(key).is_number()
                       ? fixedDecimals(point.at(key).get<double>(), decimals)
                       : std::string("-");
        };
        anchorTable.rows.push_back({point.value("label", std::string{}),
                                    point.at("effect").get<std::string>(), number("flip", 3),
                                    number("mae", 3), point.value("error_measured", std::string{}),
                                    number("time_us", 1), point.value("time_measured", std::string{})});
    }
    if (frames.empty()) {
        if (!anchorTable.rows.empty()) section.tables.push_back(std::move(anchorTable));
        return section;
    }
    const nlohmann::json& last = frames.back();
    // "folder" names the frame's output folder; summaries written before it had only "frame".
    const std::string frameName = last.contains("folder")
                                      ? last.at("folder").get<std::string>()
                                      : frameFolderName(last.at("frame").get<std::size_t>());
    if (frameName.empty() || frameName == ".." || frameName.find_first_of("/\\") != std::string::npos)
        throw std::invalid_argument("report: " + (dir / "summary.json").string() + ": frame folder '" +
                                    frameName + "' is not a folder name");
    const std::filesystem::path frameDir = dir / frameName;
    section.lead += "\nImages of the last frame (" + frameName +
                    "): first, where the output's error is largest, its noisy input, the output and the "
                    "reference side by side, enlarged; then the whole frame.";
    const nlohmann::json lastErrorsOfFrame = last.value("errors", nlohmann::json::object());
    for (const auto& effect : summary.at("effects")) {
        const std::string name = effect.get<std::string>();
        const ScoredOutput* scored = replay::scoredOutput(name); // null for an unknown effect
        const nlohmann::json error = lastErrorsOfFrame.value(name, nlohmann::json::object());
        if (scored && !scored->noisy.empty() && error.contains("image") && error.at("image").is_string())
            for (report::Figure& figure : zoomFigures(frameDir, name, error.at("image").get<std::string>(),
                                                      name + "/" + scored->noisy))
                section.figures.push_back(std::move(figure));
    }
    for (const auto& effect : summary.at("effects")) {
        const std::string name = effect.get<std::string>();
        const EffectDescriptor* descriptor = findEffect(name);
        if (!descriptor) continue;
        for (const std::string& image : descriptor->evaluation.reportImages) {
            const std::filesystem::path png = frameDir / (name + "_" + image + ".png");
            if (!std::filesystem::exists(png)) continue;
            report::Figure figure{name + " " + image, png.string()};
            figure.minWidth = 400; // a frame of 320 px and less is shown at twice its size or more
            section.figures.push_back(std::move(figure));
        }
    }
    if (summary.contains("error")) {
        report::Table errors{
            {"effect", "error, first frame", "error, last frame", "its noisy input, last frame",
             "error over moving edges, last frame", "its noisy input's, over the same moving edges",
             "reference noise floor, last frame", "converged (floor below a quarter of |output - noisy|)",
             "clamped MAE, last frame", "clamped RMSE, last frame", "FLIP, last frame",
             "its noisy input's FLIP, last frame"},
            {}};
        const nlohmann::json lastErrors = frames.back().value("errors", nlohmann::json::object());
        const nlohmann::json lastNoise = frames.back().value("referenceNoise", nlohmann::json::object());
        for (const auto& [effect, values] : summary.at("error").items()) {
            const double noisyValue = valueOr(values, "noisyLast"); // null: none, or nothing scored
            const double noisy = std::isnan(noisyValue) ? -1.0 : noisyValue;
            // null: that frame's error mask held no pixel (glint run wrote nothing to score).
            const auto scored = [](const nlohmann::json& value) {
                return value.is_number() ? fixedDecimals(value.get<double>(), 4)
                                         : std::string("no pixels scored");
            };
            const auto shown = [](double value) {
                return std::isnan(value) ? std::string("-") : fixedDecimals(value, 4);
            };
            const nlohmann::json lastError = lastErrors.value(effect, nlohmann::json::object());
            const nlohmann::json noise = lastNoise.value(effect, nlohmann::json::object());
            // FLIP (scripts/run_flip.py): "-" where it was not computed, "no pixels scored" where
            // it is null (an empty mask).
            const auto flip = [&](const nlohmann::json& object, const char* key) {
                return object.is_object() && object.contains(key) ? scored(object.at(key)) : std::string("-");
            };
            // "-" for an effect without moving edges; "no pixels scored" where none moved.
            const auto movingEdge = [&](const char* key) {
                if (!lastError.is_object() || !lastError.contains(key)) return std::string("-");
                std::string text = scored(lastError.at(key));
                if (lastError.at(key).is_number() && lastError.contains("movingEdgePixels"))
                    text += " (" + std::to_string(lastError.at("movingEdgePixels").get<std::size_t>()) +
                            " pixels)";
                return text;
            };
            std::string floor = shown(valueOr(noise, "mean"));
            if (floor != "-") {
                floor += " (clamped MAE " + shown(valueOr(noise, "maeClamped"));
                if (noise.contains("flip")) floor += ", FLIP " + flip(noise, "flip");
                floor += ")";
            }
            errors.rows.push_back(
                {effect, scored(values.at("first")), scored(values.at("last")),
                 noisy >= 0.0 ? fixedDecimals(noisy, 4) : "-", movingEdge("movingEdge"),
                 movingEdge("noisyMovingEdge"), floor,
                 convergence(valueOr(noise, "mean"), valueOr(values, "last"), noisy).withReason(),
                 shown(valueOr(lastError, "maeClamped")), shown(valueOr(lastError, "rmseClamped")),
                 flip(lastError, "flip"), flip(lastError, "noisyFlip")});
        }
        section.tables.push_back(std::move(errors));
        if (!anchorTable.rows.empty()) section.tables.push_back(std::move(anchorTable)); // beside the errors
    }
    report::Table times{{"pass", "median GPU time (us)"}, {}};
    double total = 0.0;
    const nlohmann::json passes = summary.value("passes", nlohmann::json::object());
    for (const auto& [pass, values] : passes.items()) {
        const double ms = values.at("medianMs").get<double>();
        total += ms;
        times.rows.push_back({pass, fixedDecimals(1000.0 * ms, 1)});
    }
    if (!times.rows.empty()) {
        times.rows.push_back({"all passes", fixedDecimals(1000.0 * total, 1)});
        section.tables.push_back(std::move(times));
    }
    if (!summary.contains("error") && !anchorTable.rows.empty())
        section.tables.push_back(std::move(anchorTable));
    return section;
}

} // namespace

void addReportOptions(CLI::App& command, ReportOptions& options) {
    command.add_option("runs", options.runs, "folders written by glint run")->required();
    command.add_option("--out", options.outPath, "the HTML file")->required();
    command.add_option("--title", options.title, "page title")->capture_default_str();
    command.add_option("--anchors", options.anchorsPath,
                       "anchor points measured elsewhere (docs/anchors/*.json), listed with their "
                       "conditions beside the plot of the scene they were measured on");
}

int runReport(ReportOptions options, bool) {
    if (options.runs.empty())
        throw std::invalid_argument("report: name at least one folder written by glint run");
    const nlohmann::json anchors = readAnchors(options.anchorsPath);
    report::Report page;
    page.title = options.title;
    bool first = true;
    std::vector<std::pair<std::filesystem::path, nlohmann::json>> runs;
    for (const std::string& run : options.runs) runs.emplace_back(run, readSummary(run));
    if (runs.size() > 1) {
        report::Section overview;
        overview.heading = "Summary: the last frame of every run";
        overview.lead =
            "The last frame of each run: the error of the noisy input and of the output against the run's "
            "reference, in its effect's metric (the run's section says which); the reference floor (the "
            "reference against a second one of another seed, same metric); converged: the floor is below a "
            "quarter of |output error - noisy input's error| (where the two are equal, below a quarter of "
            "the error); output - noisy: that difference measured against the reference and against the "
            "second one, and whether they agree (same sign, apart by less than a quarter); LDR-FLIP (\"-\" "
            "where not computed); the error over moving edges (visibility effects); the effect's GPU time "
            "per frame on this device; the reference's samples per pixel behind the frame.";
        overview.tables.push_back(summaryTable(runs));
        page.sections.push_back(std::move(overview));
    }
    for (const auto& [dir, summary] : runs) {
        if (first) {
            const nlohmann::json& device = summary.at("device");
            page.facts.push_back({"device", device.value("name", std::string{})});
            page.facts.push_back({"driver", device.value("driver", std::string{})});
            page.facts.push_back({"subgroup size", std::to_string(device.value("subgroupSize", 0))});
            page.facts.push_back({"date", today()});
            first = false;
        }
        page.sections.push_back(runSection(dir, summary, anchors));
    }
    report::writeHtml(options.outPath, page);
    std::printf("wrote %s (%zu run(s))\n", options.outPath.c_str(), options.runs.size());
    return kExitOk;
}

} // namespace glint::cli
