// Settings tables: parsing, range checks and their one-line errors, listings.
#include "glint/glint_settings.h"

#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace glint {
namespace {

std::string number(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

// "a, b or c"
std::string alternatives(const std::vector<std::string>& choices) {
    std::string text;
    for (std::size_t i = 0; i < choices.size(); ++i) {
        if (i > 0) text += i + 1 == choices.size() ? " or " : ", ";
        text += choices[i];
    }
    return text;
}

bool parseNumber(std::string_view text, double& value) {
    if (text.empty()) return false;
    const char* end = text.data() + text.size();
    const auto [used, error] = std::from_chars(text.data(), end, value);
    return error == std::errc{} && used == end;
}

const char* typeName(SettingType type) {
    switch (type) {
    case SettingType::Bool:
        return "bool";
    case SettingType::Uint:
        return "uint";
    case SettingType::Float:
        return "float";
    case SettingType::Choice:
        return "choice";
    }
    return "?";
}

std::string rangeOf(const SettingDesc& setting) {
    switch (setting.type) {
    case SettingType::Bool:
        return "true, false";
    case SettingType::Choice:
        return alternatives(setting.choices);
    default:
        return number(setting.minimum) + ".." + number(setting.maximum);
    }
}

// The value `text` gives `setting`, or an error line.
std::string parseValue(const SettingDesc& setting, std::string_view text, double& value) {
    const std::string prefix = "--set " + setting.name + " needs ";
    const std::string got = ", got '" + std::string(text) + "'";
    switch (setting.type) {
    case SettingType::Bool:
        if (text == "1" || text == "true" || text == "on")
            value = 1.0;
        else if (text == "0" || text == "false" || text == "off")
            value = 0.0;
        else
            return prefix + "true or false" + got;
        return {};
    case SettingType::Choice:
        for (std::size_t i = 0; i < setting.choices.size(); ++i)
            if (text == setting.choices[i]) {
                value = static_cast<double>(i);
                return {};
            }
        return prefix + alternatives(setting.choices) + got;
    case SettingType::Uint:
        if (!parseNumber(text, value) || value < 0.0 || value != std::floor(value))
            return prefix + "a whole number" + got;
        break;
    case SettingType::Float:
        if (!parseNumber(text, value) || !std::isfinite(value)) return prefix + "a finite number" + got;
        break;
    }
    if (value < setting.minimum || value > setting.maximum)
        return prefix + "a value in " + rangeOf(setting) + got;
    return {};
}

} // namespace

SettingValues::SettingValues(const std::vector<const SettingDesc*>& table) : table_(table) {
    for (const SettingDesc* setting : table_) values_[setting->name] = setting->defaultValue;
}

std::string SettingValues::assign(std::string_view assignment) {
    const std::size_t equals = assignment.find('=');
    if (equals == std::string_view::npos)
        return "--set wants name=value, got '" + std::string(assignment) + "'";
    const std::string_view name = assignment.substr(0, equals);
    const std::string_view text = assignment.substr(equals + 1);
    for (const SettingDesc* setting : table_) {
        if (setting->name != name) continue;
        double parsed = 0.0;
        if (std::string error = parseValue(*setting, text, parsed); !error.empty()) return error;
        values_[setting->name] = parsed;
        assignments_.emplace_back(assignment);
        return {};
    }
    return "unknown setting '" + std::string(name) + "' (glint settings lists them all)";
}

bool SettingValues::has(std::string_view name) const {
    return values_.find(name) != values_.end();
}

double SettingValues::value(std::string_view name) const {
    const auto found = values_.find(name);
    if (found == values_.end())
        throw std::logic_error("glint: no settings table declares '" + std::string(name) + "'");
    return found->second;
}

void SettingValues::set(std::string_view name, double value) {
    this->value(name); // declared?
    values_.find(name)->second = value;
}

bool SettingValues::flag(std::string_view name) const {
    return value(name) != 0.0;
}

std::uint32_t SettingValues::count(std::string_view name) const {
    return static_cast<std::uint32_t>(value(name));
}

float SettingValues::real(std::string_view name) const {
    return static_cast<float>(value(name));
}

std::uint32_t SettingValues::choice(std::string_view name) const {
    return static_cast<std::uint32_t>(value(name));
}

std::string formatSettingValue(const SettingDesc& setting, double value) {
    switch (setting.type) {
    case SettingType::Bool:
        return value != 0.0 ? "true" : "false";
    case SettingType::Choice: {
        const auto index = static_cast<std::size_t>(value);
        return index < setting.choices.size() ? setting.choices[index] : "?";
    }
    default:
        return number(value);
    }
}

std::string describeSettings(const std::vector<const SettingDesc*>& table) {
    std::size_t width = 0;
    for (const SettingDesc* setting : table) width = std::max(width, setting->name.size());
    std::string text;
    for (const SettingDesc* setting : table) {
        std::string line = "  " + setting->name;
        line.append(width + 2 - setting->name.size(), ' ');
        line += std::string(typeName(setting->type)) + "  default " +
                formatSettingValue(*setting, setting->defaultValue) + "  (" + rangeOf(*setting) + ")  " +
                setting->help + "\n";
        text += line;
    }
    return text;
}

std::string settingsMarkdown(const std::vector<const SettingDesc*>& table) {
    std::string text =
        "| setting | type | default | range | what it does | goes to |\n|---|---|---|---|---|---|\n";
    for (const SettingDesc* setting : table)
        text += "| `" + setting->name + "` | " + typeName(setting->type) + " | " +
                formatSettingValue(*setting, setting->defaultValue) + " | " + rangeOf(*setting) + " | " +
                setting->help + " | `" + setting->target + "` |\n";
    return text;
}

} // namespace glint
