#include "cli_report_summary.h"

#include "report/report_image.h"

#include <cmath>
#include <cstdio>

namespace glint::cli {
namespace {

std::string shown(double value, int decimals = 4) {
    return std::isnan(value) ? std::string("-") : fixedDecimals(value, decimals);
}

// "output / noisy" of two values, "-" for a missing one.
std::string pair(double output, double noisy) {
    if (std::isnan(output) && std::isnan(noisy)) return "-";
    return shown(output) + " / " + shown(noisy);
}

// The sum of the median GPU times of the passes named "<effect>/...", in microseconds.
double effectMicroseconds(const nlohmann::json& summary, const std::string& effect) {
    double total = 0.0;
    bool any = false;
    const nlohmann::json passes = summary.value("passes", nlohmann::json::object());
    for (const auto& [pass, values] : passes.items()) {
        if (pass.rfind(effect + "/", 0) != 0) continue;
        const double ms = valueOr(values, "medianMs");
        if (std::isnan(ms) || ms < 0.0) continue;
        total += 1000.0 * ms;
        any = true;
    }
    return any ? total : std::nan("");
}

// The reference's samples per pixel behind the last frame: glint simulate's referenceSamples
// (accumulated over unchanged frames), else its per-frame count.
std::string lastFrameSamples(const nlohmann::json& summary) {
    const nlohmann::json simulation = summary.value("simulation", nlohmann::json::object());
    const nlohmann::json samples = simulation.value("referenceSamples", nlohmann::json::array());
    if (samples.is_array() && !samples.empty() && samples.back().is_number_unsigned())
        return std::to_string(samples.back().get<unsigned>());
    const double spp = valueOr(simulation, "referenceSpp");
    return std::isnan(spp) ? std::string("-") : fixedDecimals(spp, 0);
}

// Whether an independent reference says the same of the difference: first, the output's error
// minus its noisy input's against the capture's reference; second, against the second
// reference. "yes" when they have the same sign and differ by less than a quarter of the first.
std::string pairedVerdict(double first, double second) {
    if (std::isnan(first) || std::isnan(second)) return "-";
    if (first == 0.0 && second == 0.0) return "yes (no difference)";
    if ((first < 0.0) == (second < 0.0) && std::abs(first - second) < 0.25 * std::abs(first)) return "yes";
    return "no";
}

} // namespace

std::string fixedDecimals(double value, int decimals) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

double valueOr(const nlohmann::json& object, const char* key) {
    if (!object.is_object() || !object.contains(key) || !object.at(key).is_number()) return NAN;
    return object.at(key).get<double>();
}

Convergence convergence(double floor, double output, double noisy) {
    if (std::isnan(floor) || std::isnan(output) || std::isnan(noisy) || noisy < 0.0) return {"-", {}};
    const double difference = std::abs(output - noisy);
    if (difference > 0.0) {
        if (floor < 0.25 * difference) return {"yes", {}};
        return {"no", "floor " + fixedDecimals(floor, 4) + " is not below a quarter of " +
                          fixedDecimals(difference, 4)};
    }
    if (floor == 0.0 || floor < 0.25 * output) return {"yes (output = input)", {}};
    return {"no", "output = noisy input, and floor " + fixedDecimals(floor, 4) +
                      " is not below a quarter of its error " + fixedDecimals(output, 4)};
}

report::Table summaryTable(const std::vector<std::pair<std::filesystem::path, nlohmann::json>>& runs) {
    report::Table table{{"scene", "effect", "noisy input error", "output error", "reference floor",
                         "converged", "output - noisy, ref. 1 / ref. 2", "refs agree", "FLIP output / noisy",
                         "moving edges output / noisy", "GPU us / frame", "ref. spp"},
                        {},
                        true};
    for (const auto& [dir, summary] : runs) {
        if (!summary.contains("error") || !summary.at("error").is_object()) continue;
        const nlohmann::json frames = summary.value("frames", nlohmann::json::array());
        const nlohmann::json last = frames.empty() ? nlohmann::json::object() : frames.back();
        for (const auto& [effect, values] : summary.at("error").items()) {
            const nlohmann::json error =
                last.value("errors", nlohmann::json::object()).value(effect, nlohmann::json::object());
            const double output = valueOr(values, "last");
            const double noisy = valueOr(values, "noisyLast");
            const double floor = valueOr(values, "referenceNoiseLast");
            const double first = valueOr(error, "mean") - valueOr(error, "noisyMean");
            const double second = valueOr(last.value("referenceNoise", nlohmann::json::object())
                                              .value(effect, nlohmann::json::object()),
                                          "differenceAgainstSecond");
            table.rows.push_back({dir.filename().string(), effect, shown(noisy), shown(output), shown(floor),
                                  convergence(floor, output, std::isnan(noisy) ? -1.0 : noisy).verdict,
                                  pair(first, second), pairedVerdict(first, second),
                                  pair(valueOr(values, "flipLast"), valueOr(values, "noisyFlipLast")),
                                  pair(valueOr(error, "movingEdge"), valueOr(error, "noisyMovingEdge")),
                                  shown(effectMicroseconds(summary, effect), 1), lastFrameSamples(summary)});
        }
    }
    return table;
}

std::vector<report::Figure> zoomFigures(const std::filesystem::path& frameDir, const std::string& effect,
                                        const std::string& finalImage, const std::string& noisyImage) {
    const auto png = [&](const std::string& image) {
        std::string name = image;
        for (char& c : name)
            if (c == '/') c = '_';
        return frameDir / (name + ".png");
    };
    const std::filesystem::path errorPath = frameDir / (effect + "_error.exr");
    const std::vector<std::pair<std::string, std::filesystem::path>> shownImages = {
        {"noisy input", png(noisyImage)},
        {"output", png(finalImage)},
        {"reference", png(effect + "/reference")}};
    if (noisyImage.empty() || !std::filesystem::exists(errorPath)) return {};
    for (const auto& [caption, path] : shownImages)
        if (!std::filesystem::exists(path)) return {};
    const report::Image error = report::readExr(errorPath.string());
    const std::uint32_t width = error.width, height = error.height;
    const std::uint32_t windowWidth = std::max(1u, width / 4), windowHeight = std::max(1u, height / 4);
    // Summed-area table of the error (first channel; non-finite values count as 1, as the map
    // itself records them).
    std::vector<double> area(std::size_t{width + 1} * (height + 1), 0.0);
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            const float value = error.pixels[(std::size_t{y} * width + x) * error.channels];
            const double v = std::isfinite(value) ? std::abs(double{value}) : 1.0;
            area[std::size_t{y + 1} * (width + 1) + x + 1] = v + area[std::size_t{y} * (width + 1) + x + 1] +
                                                             area[std::size_t{y + 1} * (width + 1) + x] -
                                                             area[std::size_t{y} * (width + 1) + x];
        }
    double best = 0.0;
    std::uint32_t bestX = 0, bestY = 0;
    for (std::uint32_t y = 0; y + windowHeight <= height; ++y)
        for (std::uint32_t x = 0; x + windowWidth <= width; ++x) {
            const auto at = [&](std::uint32_t ax, std::uint32_t ay) {
                return area[std::size_t{ay} * (width + 1) + ax];
            };
            const double sum = at(x + windowWidth, y + windowHeight) - at(x, y + windowHeight) -
                               at(x + windowWidth, y) + at(x, y);
            if (sum > best) {
                best = sum;
                bestX = x;
                bestY = y;
            }
        }
    if (best <= 0.0) return {};
    // About 320 px wide: three fit beside each other on a page 1400 px wide.
    const std::uint32_t scale = std::max(1u, 320u / windowWidth);
    std::vector<report::Figure> figures;
    for (const auto& [caption, path] : shownImages) {
        const report::RgbImage image = report::readRgbPng(path.string());
        if (image.width != width || image.height != height) return {};
        const report::RgbImage crop =
            report::cropScaled(image, bestX, bestY, windowWidth, windowHeight, scale);
        report::Figure figure;
        figure.caption = effect + " " + caption + ", x " + std::to_string(bestX) + "-" +
                         std::to_string(bestX + windowWidth - 1) + ", y " + std::to_string(bestY) + "-" +
                         std::to_string(bestY + windowHeight - 1) + ", " + std::to_string(scale) + "x";
        figure.pngPath = path.string();
        figure.pngBytes = report::encodeRgbPng(path.string(), crop);
        figures.push_back(std::move(figure));
    }
    return figures;
}

} // namespace glint::cli
