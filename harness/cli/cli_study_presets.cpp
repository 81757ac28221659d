// glint study's presets and budget choice (docs/accuracy-vs-time.md, "Presets"): the sweep's
// points of each effect combined over the scenes, the presets chosen from them by the rule in
// cli_presets.h, written as presets.toml (the built-in presets' format), and with --budget-us
// the most accurate point that fits the budget.
#include "cli_study.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

namespace glint::cli::study {
namespace {

constexpr const char* kBaseLabel = "defaults"; // the effect as shipped (pointsFor, cli_study.cpp)

nlohmann::json pointJson(const StudyPoint& point) {
    nlohmann::json json{{"point", point.label}, {"settings", point.settings}, {"time_us", point.timeUs}};
    json["error"] = std::isfinite(point.error) ? nlohmann::json(point.error) : nlohmann::json(nullptr);
    return json;
}

std::string settingsText(const std::vector<std::string>& settings) {
    return settings.empty() ? "no --set" : joined(settings, " ");
}

} // namespace

std::vector<StudyPoint> combineScenes(const std::vector<Measured>& rows, const std::string& effect) {
    std::map<std::string, double> baseError; // scene -> the defaults point's error
    for (const Measured& row : rows)
        if (row.effect == effect && row.label == kBaseLabel) baseError[row.scene] = row.error;
    std::vector<StudyPoint> points;
    std::map<std::string, std::size_t> scenesOf; // label -> scenes that counted
    for (const Measured& row : rows) {
        if (row.effect != effect) continue;
        auto found = std::find_if(points.begin(), points.end(),
                                  [&](const StudyPoint& p) { return p.label == row.label; });
        if (found == points.end()) {
            points.push_back({row.label, row.settings, row.timeUs, 0.0});
            found = points.end() - 1;
        }
        found->timeUs = std::max(found->timeUs, row.timeUs);
        const auto base = baseError.find(row.scene);
        if (base == baseError.end() || !(base->second > 0.0) || !std::isfinite(base->second)) continue;
        found->error +=
            std::isfinite(row.error) ? row.error / base->second : std::numeric_limits<double>::quiet_NaN();
        ++scenesOf[row.label];
    }
    for (StudyPoint& point : points)
        point.error = scenesOf[point.label] > 0 ? point.error / static_cast<double>(scenesOf[point.label])
                                                : std::numeric_limits<double>::quiet_NaN();
    return points;
}

nlohmann::json choosePresetsAndBudget(const Plan& plan, const std::string& device,
                                      const std::vector<Measured>& rows) {
    nlohmann::json json{{"presets", nlohmann::json::object()}, {"front", nlohmann::json::object()}};
    if (plan.budgetUs)
        json["budget"] = {{"budget_us", *plan.budgetUs}, {"choices", nlohmann::json::object()}};
    PresetTable table;
    table.names = {"low", "medium", "high", "ultra"};
    for (const std::string& effect : plan.effects) {
        const std::vector<StudyPoint> points = combineScenes(rows, effect);
        json["front"][effect] = nlohmann::json::array();
        for (const std::size_t i : paretoFront(points)) json["front"][effect].push_back(pointJson(points[i]));
        const auto chosen = choosePresets(points, kBaseLabel);
        if (chosen.empty())
            std::printf("presets: %s: no point has a finite time and error; no presets\n", effect.c_str());
        for (const auto& [name, index] : chosen) {
            const StudyPoint& point = points[index];
            table.presets[name][effect] = {point.settings, point.label, point.timeUs, point.error};
            json["presets"][effect][name] = pointJson(point);
            std::printf("preset %-6s %-12s %-22s %10.1f us   error %.4f x the defaults'\n", name.c_str(),
                        effect.c_str(), point.label.c_str(), point.timeUs, point.error);
        }
        if (!plan.budgetUs) continue;
        if (const std::optional<std::size_t> best = bestWithin(points, *plan.budgetUs)) {
            json["budget"]["choices"][effect] = pointJson(points[*best]);
            std::printf(
                "budget %.1f us: %s: %s (%s), %.1f us on its slowest scene, error %.4f x the defaults'\n",
                *plan.budgetUs, effect.c_str(), points[*best].label.c_str(),
                settingsText(points[*best].settings).c_str(), points[*best].timeUs, points[*best].error);
        } else {
            json["budget"]["choices"][effect] = nullptr;
            double fastest = std::numeric_limits<double>::infinity();
            for (const StudyPoint& point : points) fastest = std::min(fastest, point.timeUs);
            std::printf("budget %.1f us: %s: no measured point fits (the fastest takes %.1f us)\n",
                        *plan.budgetUs, effect.c_str(), fastest);
        }
    }
    char size[64];
    std::snprintf(size, sizeof size, "%ux%u, %u frames", plan.width, plan.height, plan.frames);
    writeText(
        plan.out / "presets.toml",
        formatPresets(table, "Written by glint study: " + device + ", " + size +
                                 ".\nPer effect, points of the run's Pareto front, each point's scenes "
                                 "combined:\ntime_us is its largest median over the scenes, error its "
                                 "mean error relative to\nthe defaults point's (docs/accuracy-vs-time.md, "
                                 "\"Presets\"). Use with\nglint run --preset-file presets.toml --preset "
                                 "NAME ..."));
    return json;
}

} // namespace glint::cli::study
