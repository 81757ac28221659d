// Small analytic scenes for the simulator's GPU tests, built in code so that each test says
// exactly what it renders.
#pragma once

#include "scene/scene_types.h"

namespace glint::test {

// A glossy floor, a box, a sphere moving to the right, a directional light with a wide disc;
// the camera drifts sideways between frames. Effects and references are left to the test.
scene::Scene analyticScene(std::uint32_t width, std::uint32_t height, std::uint32_t frames);

} // namespace glint::test
