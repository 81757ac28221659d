// Rows of the effects' settings tables (glint_settings.h), spelled briefly.
#pragma once

#include "glint/glint_settings.h"

#include <string>
#include <vector>

namespace glint::core {

inline SettingDesc boolSetting(std::string name, bool value, std::string help, std::string target) {
    return {std::move(name), SettingType::Bool, value ? 1.0 : 0.0, 0.0, 1.0, {},
            std::move(help), std::move(target)};
}

inline SettingDesc uintSetting(std::string name, std::uint32_t value, std::uint32_t minimum,
                               std::uint32_t maximum, std::string help, std::string target) {
    return {std::move(name), SettingType::Uint, double(value), double(minimum), double(maximum), {},
            std::move(help), std::move(target)};
}

inline SettingDesc floatSetting(std::string name, float value, double minimum, double maximum,
                                std::string help, std::string target) {
    return {std::move(name), SettingType::Float, double(value), minimum, maximum, {},
            std::move(help), std::move(target)};
}

inline SettingDesc choiceSetting(std::string name, std::uint32_t index, std::vector<std::string> choices,
                                 std::string help, std::string target) {
    return {std::move(name),    SettingType::Choice, double(index),    0.0, double(choices.size() - 1),
            std::move(choices), std::move(help),     std::move(target)};
}

} // namespace glint::core
