// Presets (cli_presets.h): a preset applies exactly its settings for the effects being run and
// --set overrides them; bad preset files and names are one-line errors; and the choice of
// points (the budget rule, the Pareto front and the four presets) on hand-made point sets
// whose answers follow from the definitions written next to each check.
#include "cli_presets.h"

#include "replay/replay_settings.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

using glint::cli::PresetChoice;
using glint::cli::StudyPoint;

namespace {

const char* kFile = R"(presets = ["fast", "slow"]

[fast.reflections]
point = "a"
settings = ["denoise=false", "samplesPerQuad=2"]

[fast.shadows]
settings = ["shadows.filter=false"]

[fast.hybrid]
settings = ["denoise=true"]

[slow.reflections]
settings = ["samplesPerQuad=4"]
)";

std::string writeFile(const std::string& name, const std::string& text) {
    const std::filesystem::path path = std::filesystem::path(GLINT_TEST_OUTPUT_DIR) / "presets" / name;
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path) << text;
    return path.string();
}

std::string refusal(const std::string& text) {
    try {
        glint::cli::parsePresets(text, "p.toml");
    } catch (const std::invalid_argument& error) {
        return error.what();
    }
    return "(accepted)";
}

std::string choiceRefusal(const PresetChoice& choice) {
    try {
        glint::cli::checkPresetChoice(choice);
    } catch (const std::invalid_argument& error) {
        return error.what();
    }
    return "(accepted)";
}

// Every setting of the table that differs between two values: the settings a preset changed.
std::vector<std::string> changed(const glint::SettingValues& a, const glint::SettingValues& b) {
    std::vector<std::string> names;
    for (const glint::SettingDesc* setting : a.table()) {
        const bool differs =
            setting->type == glint::SettingType::Bool     ? a.flag(setting->name) != b.flag(setting->name)
            : setting->type == glint::SettingType::Uint   ? a.count(setting->name) != b.count(setting->name)
            : setting->type == glint::SettingType::Choice ? a.choice(setting->name) != b.choice(setting->name)
                                                          : a.real(setting->name) != b.real(setting->name);
        if (differs) names.push_back(setting->name);
    }
    return names;
}

StudyPoint point(const std::string& label, double timeUs, double error) {
    return {label, {label + "=1"}, timeUs, error};
}

std::vector<std::string> labels(const std::vector<StudyPoint>& points,
                                const std::vector<std::size_t>& indices) {
    std::vector<std::string> out;
    for (const std::size_t i : indices) out.push_back(points[i].label);
    return out;
}

} // namespace

TEST_CASE("a preset applies exactly its bundles for the effects run, before --set") {
    const std::string file = writeFile("two.toml", kFile);
    const PresetChoice fast{"fast", file};
    // Only the effects run contribute, in their order; --set comes last.
    CHECK(glint::cli::presetThenSettings(fast, {"reflections"}, {}) ==
          std::vector<std::string>{"denoise=false", "samplesPerQuad=2"});
    CHECK(glint::cli::presetThenSettings(fast, {"shadows"}, {"shadows.antiLag=false"}) ==
          std::vector<std::string>{"shadows.filter=false", "shadows.antiLag=false"});
    CHECK(glint::cli::presetThenSettings(fast, {"depth_pyramid"}, {}).empty()); // not in the preset
    CHECK(glint::cli::presetThenSettings({}, {"reflections"}, {"denoise=true"}) ==
          std::vector<std::string>{"denoise=true"}); // no preset: --set alone

    // Parsed, the preset changes exactly the settings it names and nothing else.
    const glint::SettingValues defaults = glint::replay::parseSettings({});
    const glint::SettingValues preset =
        glint::replay::parseSettings(glint::cli::presetThenSettings(fast, {"reflections", "shadows"}, {}));
    CHECK(changed(defaults, preset) == std::vector<std::string>{"samplesPerQuad", "shadows.filter"});
    // denoise=false is the default, so it changes nothing; --set wins over the preset.
    const glint::SettingValues overridden = glint::replay::parseSettings(
        glint::cli::presetThenSettings(fast, {"reflections"}, {"samplesPerQuad=4", "denoise=true"}));
    CHECK(overridden.count("samplesPerQuad") == 4);
    CHECK(overridden.flag("denoise"));
}

TEST_CASE("effects that share a setting must agree on it in a preset unless --set chooses") {
    const PresetChoice fast{"fast", writeFile("two.toml", kFile)};
    // reflections and hybrid share "denoise"; the file gives it false and true.
    try {
        glint::cli::presetThenSettings(fast, {"reflections", "hybrid"}, {});
        FAIL("a conflicting shared setting was accepted");
    } catch (const std::invalid_argument& error) {
        CHECK(std::string(error.what()) == "preset 'fast' gives denoise the value false for reflections and "
                                           "true for hybrid, which share it: "
                                           "choose with --set denoise=VALUE");
    }
    const std::vector<std::string> chosen =
        glint::cli::presetThenSettings(fast, {"reflections", "hybrid"}, {"denoise=true"});
    CHECK(glint::replay::parseSettings(chosen).flag("denoise"));
}

TEST_CASE("an unknown preset names the known ones, and a preset file needs a preset") {
    CHECK(choiceRefusal({"extreme", ""}) == "unknown preset 'extreme' (low, medium, high, ultra)");
    const std::string file = writeFile("two.toml", kFile);
    CHECK(choiceRefusal({"high", file}) == "unknown preset 'high' (fast, slow, from " + file + ")");
    CHECK(choiceRefusal({"", file}) == "--preset-file " + file + " needs --preset NAME");
    CHECK(choiceRefusal({"low", "/nonexistent/p.toml"}) ==
          "/nonexistent/p.toml: cannot read the presets file");
    CHECK(choiceRefusal({"", ""}) == "(accepted)");
}

TEST_CASE("the built-in presets parse, and every bundle is a set of its effect's settings") {
    const glint::cli::PresetTable table = glint::cli::loadPresets("");
    CHECK(table.names == std::vector<std::string>{"low", "medium", "high", "ultra"});
    for (const std::string& name : table.names) {
        REQUIRE(table.presets.contains(name));
        CHECK(table.presets.at(name).contains("reflections"));
        CHECK(table.presets.at(name).contains("shadows"));
    }
    // high is the study's defaults point: the denoised reflections, the shadows as shipped.
    CHECK(table.presets.at("high").at("reflections").settings == std::vector<std::string>{"denoise=true"});
    CHECK(table.presets.at("high").at("shadows").settings.empty());
}

TEST_CASE("a presets file that is wrong is refused in one line naming the key") {
    CHECK(refusal("presets = [\"a\"]\n[a.reflections]\nsettings = [\"nosuch=1\"]\n") ==
          "p.toml: a.reflections.settings: 'nosuch' is not a setting of reflections");
    CHECK(refusal("presets = [\"a\"]\n[a.shadows]\nsettings = [\"denoise=true\"]\n") ==
          "p.toml: a.shadows.settings: 'denoise' is not a setting of shadows");
    CHECK(refusal("presets = [\"a\"]\n[a.reflections]\nsettings = [\"samplesPerQuad=9\"]\n") ==
          "p.toml: a.reflections.settings: --set samplesPerQuad needs a value in 1..4, got '9'");
    CHECK(refusal("presets = [\"a\"]\n[a.nosuch]\nsettings = []\n")
              .starts_with("p.toml: a.nosuch: unknown effect (depth_pyramid, "));
    CHECK(refusal("presets = [\"a\"]\n[b.reflections]\nsettings = []\n") ==
          "p.toml: b: is not listed in 'presets'");
    CHECK(refusal("presets = [\"a\", \"b\"]\n[a]\n") == "p.toml: b: is listed in 'presets' but has no table");
    CHECK(refusal("presets = [\"a\"]\n[a.reflections]\npoint = \"x\"\n") ==
          "p.toml: a.reflections: has no 'settings'");
    CHECK(refusal("presets = [\"a\"]\n[a.reflections]\nsettings = [1]\n") ==
          "p.toml: a.reflections.settings: must be an array of \"name=value\" strings");
    CHECK(refusal("[a.reflections]\nsettings = []\n") ==
          "p.toml: presets: must list the preset names, e.g. [\"low\", \"high\"]");
    CHECK(refusal("presets = [\n").starts_with("p.toml:"));
}

TEST_CASE("a presets file written by formatPresets reads back the same") {
    glint::cli::PresetTable table;
    table.names = {"low", "high"};
    table.presets["low"]["reflections"] = {{"denoise=false"}, "no_denoiser", 412.5, 1.25};
    table.presets["low"]["shadows"] = {{}, "defaults", 50.0, 1.0};
    table.presets["high"]["reflections"] = {{"denoise=true", "samplesPerQuad=4"}, "spq_4", 900.0, 0.75};
    const glint::cli::PresetTable back =
        glint::cli::parsePresets(glint::cli::formatPresets(table, "a header\nof two lines"), "written");
    CHECK(back.names == table.names);
    for (const auto& [name, effects] : table.presets)
        for (const auto& [effect, entry] : effects) {
            const glint::cli::PresetEntry& read = back.presets.at(name).at(effect);
            CHECK(read.settings == entry.settings);
            CHECK(read.point == entry.point);
            CHECK(read.timeUs == entry.timeUs); // values with at most 6 significant digits survive
            CHECK(read.error == entry.error);
        }
    CHECK(back.presets.at("high").size() == 1);
}

TEST_CASE("the budget choice is the most accurate point that fits, the faster of equals") {
    const std::vector<StudyPoint> points{point("a", 100, 0.9), point("b", 200, 0.5), point("c", 300, 0.5),
                                         point("d", 250, 0.7), point("e", 400, 0.2)};
    CHECK(!glint::cli::bestWithin(points, 99.0));       // nothing is that fast
    CHECK(glint::cli::bestWithin(points, 100.0) == 0u); // a fits exactly
    CHECK(glint::cli::bestWithin(points, 299.0) == 1u); // b beats a and d
    CHECK(glint::cli::bestWithin(points, 350.0) == 1u); // c is as accurate as b and slower
    CHECK(glint::cli::bestWithin(points, 1e9) == 4u);
    // A point without a finite time or error fits no budget.
    const std::vector<StudyPoint> broken{point("nan", 10, std::nan("")), point("inf", INFINITY, 0.0),
                                         point("ok", 20, 1.0)};
    CHECK(glint::cli::bestWithin(broken, std::numeric_limits<double>::infinity()) == 2u);
    CHECK(!glint::cli::bestWithin(broken, 15.0));
}

TEST_CASE("the Pareto front holds the points nothing beats in time and error") {
    // a (100, 0.9), b (200, 0.5), e (400, 0.2) are on it; c ties b's error and is slower; d is
    // slower and worse than b.
    const std::vector<StudyPoint> points{point("a", 100, 0.9), point("b", 200, 0.5), point("c", 300, 0.5),
                                         point("d", 250, 0.7), point("e", 400, 0.2)};
    CHECK(labels(points, glint::cli::paretoFront(points)) == std::vector<std::string>{"a", "b", "e"});
    CHECK(glint::cli::paretoFront({}).empty());
}

TEST_CASE("the four presets: fastest, best within the midpoint, best within the base's time, most accurate") {
    // Times 100..700; base "base" at 500 with error 0.5. low = fast (100); high = the best within
    // 500 = better (450, 0.4); medium = the best within (100 + 450) / 2 = 275 = mid (250, 0.6);
    // ultra = best (700, 0.1). slowbad (600, 0.8) and worse (300, 0.7) are on no front.
    const std::vector<StudyPoint> points{point("fast", 100, 1.0),  point("mid", 250, 0.6),
                                         point("worse", 300, 0.7), point("better", 450, 0.4),
                                         point("base", 500, 0.5),  point("slowbad", 600, 0.8),
                                         point("best", 700, 0.1)};
    const auto chosen = glint::cli::choosePresets(points, "base");
    REQUIRE(chosen.size() == 4);
    CHECK(chosen[0] == std::pair<std::string, std::size_t>{"low", 0});
    CHECK(chosen[1] == std::pair<std::string, std::size_t>{"medium", 1});
    CHECK(chosen[2] == std::pair<std::string, std::size_t>{"high", 3});
    CHECK(chosen[3] == std::pair<std::string, std::size_t>{"ultra", 6});
}

TEST_CASE("with a short front neighbouring presets share a point") {
    // Two points: the base is the most accurate, so high = ultra = base; the midpoint of
    // low's 100 and high's 300 is 200, which only fast fits: medium = low.
    const std::vector<StudyPoint> points{point("fast", 100, 2.0), point("defaults", 300, 1.0)};
    const auto chosen = glint::cli::choosePresets(points, "defaults");
    REQUIRE(chosen.size() == 4);
    CHECK(chosen[0].second == 0u);
    CHECK(chosen[1].second == 0u);
    CHECK(chosen[2].second == 1u);
    CHECK(chosen[3].second == 1u);
    CHECK(glint::cli::choosePresets({}, "defaults").empty());
    CHECK(glint::cli::choosePresets({point("nan", 1, std::nan(""))}, "defaults").empty());
}
