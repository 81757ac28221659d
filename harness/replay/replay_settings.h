// "name=value" settings for the effects, shared by `glint bench`, `glint run`, `glint dump`,
// `glint check` and `glint study`, so that one spelling sweeps the same option everywhere. The
// names, types, ranges and help come from the effects' settings tables (glint_effect.h);
// `glint settings` lists them.
#pragma once

#include "glint/glint_effect.h"

#include <string>
#include <vector>

namespace glint::replay {

// Every registered effect's settings at their defaults, then `assignments` in order. Throws
// std::invalid_argument with the table's one-line error.
SettingValues parseSettings(const std::vector<std::string>& assignments);

} // namespace glint::replay
