// Tests only: a scene's geometry at one frame written as a glTF 2.0 file, so that the scene
// read back through scene::loadGeometryScene (glint run --geometry) can be compared with the
// scene itself. The triangles are the world-space ones buildGeometry makes (bit for bit, one
// glTF mesh and node per object, in the scene's order), the materials the scene's (emissive
// above 1 through KHR_materials_emissive_strength), the lights the frame's, as
// KHR_lights_punctual (directional lights on a node whose -z is the light's travel, spheres as
// point lights at their centres; sizes are not written, glTF's lights have none).
#pragma once

#include <scene/scene_types.h>

#include <cstdint>
#include <string>

namespace glint::test {

// Throws std::invalid_argument for what glTF cannot hold exactly: an analytic sphere or a
// roughness ramp.
std::string sceneAsGltf(const scene::Scene& scene, std::uint32_t frame = 0);

} // namespace glint::test
