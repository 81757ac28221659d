// Scene files (TOML, docs/scenes.md) -> Scene. Every error is a SceneError whose what() is
// one line: "<file>:<line>: <key>: <problem>" (the line is left out where there is none).
#pragma once

#include "scene/scene_types.h"

#include <filesystem>
#include <stdexcept>
#include <string>

namespace glint::scene {

struct SceneError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Relative paths inside the scene (models, environment maps) are resolved against the scene
// file's folder. Model files are checked for existence here; they are read by buildGeometry.
Scene loadScene(const std::filesystem::path& file);
Scene parseScene(const std::string& text, const std::filesystem::path& file);

} // namespace glint::scene
