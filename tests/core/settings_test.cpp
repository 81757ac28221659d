// The settings tables (glint_settings.h): parsing, range checks and their one-line errors.
#include "glint/glint_effect.h"
#include "glint/glint_settings.h"

#include <catch2/catch.hpp>

#include <fstream>
#include <iterator>

namespace {

using glint::SettingDesc;
using glint::SettingType;
using glint::SettingValues;

// A table of its own, so that the expectations do not depend on any effect's defaults.
const std::vector<SettingDesc>& testTable() {
    static const std::vector<SettingDesc> table{
        {"flag", SettingType::Bool, 0.0, 0.0, 1.0, {}, "a flag", "T::flag"},
        {"count", SettingType::Uint, 3.0, 1.0, 8.0, {}, "a count", "T::count"},
        {"scale", SettingType::Float, 0.5, 0.0, 1e6, {}, "a scale", "T::scale"},
        {"mode", SettingType::Choice, 1.0, 0.0, 2.0, {"a", "b", "c"}, "a mode", "T::mode"},
    };
    return table;
}

SettingValues testValues() {
    std::vector<const SettingDesc*> rows;
    for (const SettingDesc& row : testTable()) rows.push_back(&row);
    return SettingValues(rows);
}

} // namespace

TEST_CASE("settings start at their defaults", "[settings]") {
    const SettingValues values = testValues();
    CHECK_FALSE(values.flag("flag"));
    CHECK(values.count("count") == 3);
    CHECK(values.real("scale") == 0.5f);
    CHECK(values.choice("mode") == 1);
    CHECK(values.assignments().empty());
}

TEST_CASE("settings parse every spelling of their type", "[settings]") {
    SettingValues values = testValues();
    for (const char* on : {"flag=1", "flag=true", "flag=on"}) {
        CHECK(values.assign(on).empty());
        CHECK(values.flag("flag"));
        CHECK(values.assign("flag=off").empty());
        CHECK_FALSE(values.flag("flag"));
    }
    CHECK(values.assign("count=8").empty());
    CHECK(values.count("count") == 8);
    CHECK(values.assign("scale=2.5e3").empty());
    CHECK(values.real("scale") == 2500.0f);
    CHECK(values.assign("mode=c").empty());
    CHECK(values.choice("mode") == 2);
    CHECK(values.assignments() == std::vector<std::string>{"flag=1", "flag=off", "flag=true", "flag=off",
                                                           "flag=on", "flag=off", "count=8", "scale=2.5e3",
                                                           "mode=c"});
}

TEST_CASE("bad settings get one line naming the setting, what it needs and what it got", "[settings]") {
    SettingValues values = testValues();
    CHECK(values.assign("nosuch=1") == "unknown setting 'nosuch' (glint settings lists them all)");
    CHECK(values.assign("count") == "--set wants name=value, got 'count'");
    CHECK(values.assign("flag=yes") == "--set flag needs true or false, got 'yes'");
    CHECK(values.assign("count=2.5") == "--set count needs a whole number, got '2.5'");
    CHECK(values.assign("count=-1") == "--set count needs a whole number, got '-1'");
    CHECK(values.assign("count=9") == "--set count needs a value in 1..8, got '9'");
    CHECK(values.assign("scale=1e9") == "--set scale needs a value in 0..1e+06, got '1e9'");
    CHECK(values.assign("scale=nan") == "--set scale needs a finite number, got 'nan'");
    CHECK(values.assign("scale=inf") == "--set scale needs a finite number, got 'inf'");
    CHECK(values.assign("scale=") == "--set scale needs a finite number, got ''");
    CHECK(values.assign("mode=d") == "--set mode needs a, b or c, got 'd'");
    // Rejected assignments leave the values as they were.
    CHECK(values.count("count") == 3);
    CHECK(values.real("scale") == 0.5f);
    CHECK(values.assignments().empty());
}

TEST_CASE("reading a setting no table declares is a programming error", "[settings]") {
    const SettingValues values = testValues();
    CHECK_THROWS_AS(values.real("undeclared"), std::logic_error);
}

TEST_CASE("the listing shows every row with its type, default and range", "[settings]") {
    std::vector<const SettingDesc*> rows;
    for (const SettingDesc& row : testTable()) rows.push_back(&row);
    const std::string text = glint::describeSettings(rows);
    CHECK_THAT(text, Catch::Contains("flag   bool  default false  (true, false)  a flag"));
    CHECK_THAT(text, Catch::Contains("count  uint  default 3  (1..8)  a count"));
    CHECK_THAT(text, Catch::Contains("mode   choice  default b  (a, b or c)  a mode"));
}

TEST_CASE("the roughness threshold is one setting shared by SSSR and the denoiser", "[settings]") {
    std::size_t rows = 0;
    for (const SettingDesc* setting : glint::allSettings()) rows += setting->name == "roughnessThreshold";
    CHECK(rows == 1);
}

TEST_CASE("docs/settings.md holds every effect's settings table as the tables say", "[settings]") {
    std::ifstream file(std::string(GLINT_SOURCE_DIR) + "/docs/settings.md");
    REQUIRE(file);
    const std::string docs((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    for (const glint::EffectDescriptor* effect : glint::effectRegistry()) {
        INFO(effect->name << ": regenerate with glint settings --markdown");
        std::vector<const SettingDesc*> table;
        for (const SettingDesc& setting : effect->settings) table.push_back(&setting);
        CHECK_THAT(docs, Catch::Contains("## " + effect->name + "\n\n" + effect->help + ".\n\n" +
                                         glint::settingsMarkdown(table)));
    }
}
