// Scene files (TOML, docs/scenes.md) -> Scene. Every error is a SceneError whose what() is
// one line: "<file>:<line>: <key>: <problem>" (the line is left out where there is none).
#pragma once

#include "scene/scene_types.h"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace glint::scene {

struct SceneError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Relative paths inside the scene (models, environment maps) are resolved against the scene
// file's folder. Model files are checked for existence here; they are read by buildGeometry.
Scene loadScene(const std::filesystem::path& file);
Scene parseScene(const std::string& text, const std::filesystem::path& file);

// A model file (glTF 2.0 .gltf/.glb, or anything assimp reads) as a static scene for the
// effects that ray trace a capture without a scene of its own (glint run --geometry,
// docs/replay.md): its triangles in the file's world space (every node's transform applied),
// one mesh object per material of the file, with that material's base colour factor, metallic,
// roughness and emissive (times KHR_materials_emissive_strength, read from the glTF's own JSON
// as assimp 5.2.5 does not import it), textures ignored; its punctual lights
// (KHR_lights_punctual): directional and point lights as they are, spot lights as point lights
// (no cone), each of zero size, colour times intensity taken as the scene's irradiance
// (directional) or irradiance at one unit (point). No lights: the shading is the emission
// alone. Camera, environment and everything else keep Scene's defaults. Throws
// SceneError "<file>: <problem>" for a missing, unreadable or malformed file or one without
// triangles; `warnings` (when given) receives one line per thing left out (an ambient or area
// light, a spot light's cone), without the file's name.
Scene loadGeometryScene(const std::filesystem::path& file, std::vector<std::string>* warnings = nullptr);

} // namespace glint::scene
