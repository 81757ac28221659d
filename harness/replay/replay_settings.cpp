#include "replay/replay_settings.h"

#include <stdexcept>

namespace glint::replay {

SettingValues parseSettings(const std::vector<std::string>& assignments) {
    SettingValues settings = defaultSettings(effectRegistry());
    for (const std::string& assignment : assignments)
        if (const std::string error = settings.assign(assignment); !error.empty())
            throw std::invalid_argument(error);
    return settings;
}

} // namespace glint::replay
