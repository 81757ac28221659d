// glint report: one self-contained HTML page from the folders `glint run` wrote: per run, the
// last frame's images side by side (input, noisy, denoised, composite, reference, error), the
// error against the reference, per-pass GPU times; the device on top. The demo's report.
#include "cli_capture.h"
#include "cli_commands.h"

#include "capture/json_text.h"
#include "report/report_html.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iterator>

namespace glint::cli {
namespace {

// Four decimals for errors, one for microseconds.
std::string fixed(double value, int decimals) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

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

report::Section runSection(const std::filesystem::path& dir, const nlohmann::json& summary) {
    report::Section section;
    section.heading = dir.filename().string();
    std::string effects;
    for (const auto& effect : summary.at("effects"))
        effects += (effects.empty() ? "" : ", ") + effect.get<std::string>();
    section.text = "Capture " + summary.value("capture", std::string{}) + "; effects: " + effects + ".";
    const nlohmann::json settings = summary.value("settings", nlohmann::json::array());
    for (const auto& setting : settings) section.text += "\nset " + setting.get<std::string>();
    const nlohmann::json& frames = summary.at("frames");
    if (frames.empty()) return section;
    const nlohmann::json& last = frames.back();
    // "folder" names the frame's output folder; summaries written before it had only "frame".
    const std::string frameName = last.contains("folder")
                                      ? last.at("folder").get<std::string>()
                                      : frameFolderName(last.at("frame").get<std::size_t>());
    if (frameName.empty() || frameName == ".." || frameName.find_first_of("/\\") != std::string::npos)
        throw std::invalid_argument("report: " + (dir / "summary.json").string() + ": frame folder '" +
                                    frameName + "' is not a folder name");
    const std::filesystem::path frameDir = dir / frameName;
    section.text += "\nImages of the last frame (" + frameName + ").";
    for (const auto& effect : summary.at("effects")) {
        const std::string name = effect.get<std::string>();
        for (const char* image : {"input", "noisy", "denoised", "composite", "reference", "error", "mip1"}) {
            const std::filesystem::path png = frameDir / (name + "_" + image + ".png");
            if (std::filesystem::exists(png)) section.figures.push_back({name + " " + image, png.string()});
        }
    }
    if (summary.contains("error")) {
        report::Table errors{
            {"effect", "error, first frame", "error, last frame", "its noisy input, last frame"}, {}};
        for (const auto& [effect, values] : summary.at("error").items()) {
            const double noisy = values.value("noisyLast", -1.0);
            // null: that frame's error mask held no pixel (glint run wrote nothing to score).
            const auto scored = [](const nlohmann::json& value) {
                return value.is_number() ? fixed(value.get<double>(), 4) : std::string("no pixels scored");
            };
            errors.rows.push_back({effect, scored(values.at("first")), scored(values.at("last")),
                                   noisy >= 0.0 ? fixed(noisy, 4) : "-"});
        }
        section.tables.push_back(std::move(errors));
    }
    report::Table times{{"pass", "median GPU time (us)"}, {}};
    double total = 0.0;
    const nlohmann::json passes = summary.value("passes", nlohmann::json::object());
    for (const auto& [pass, values] : passes.items()) {
        const double ms = values.at("medianMs").get<double>();
        total += ms;
        times.rows.push_back({pass, fixed(1000.0 * ms, 1)});
    }
    if (!times.rows.empty()) {
        times.rows.push_back({"all passes", fixed(1000.0 * total, 1)});
        section.tables.push_back(std::move(times));
    }
    return section;
}

} // namespace

int runReport(const ReportOptions& options) {
    if (options.runs.empty())
        throw std::invalid_argument("report: name at least one folder written by glint run");
    report::Report page;
    page.title = options.title;
    bool first = true;
    for (const std::string& run : options.runs) {
        const std::filesystem::path dir(run);
        const nlohmann::json summary = readSummary(dir);
        if (first) {
            const nlohmann::json& device = summary.at("device");
            page.facts.push_back({"device", device.value("name", std::string{})});
            page.facts.push_back({"driver", device.value("driver", std::string{})});
            page.facts.push_back({"subgroup size", std::to_string(device.value("subgroupSize", 0))});
            page.facts.push_back({"date", today()});
            first = false;
        }
        page.sections.push_back(runSection(dir, summary));
    }
    report::writeHtml(options.outPath, page);
    std::printf("wrote %s (%zu run(s))\n", options.outPath.c_str(), options.runs.size());
    return kExitOk;
}

} // namespace glint::cli
