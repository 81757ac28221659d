// The scene's environment as the lat-long map that both the ray caster samples and the
// capture sequence carries (environment.exr), so that misses in the references and in the
// colour buffer see exactly the map a consumer of the capture sees.
#pragma once

#include "capture/environment_io.h"
#include "scene/scene_types.h"

#include "scene_constants.h"

#include <vector>

namespace glint::scene {

// Procedural sky (zenith/horizon/ground gradient plus each directional light's disc) or the
// scene's lat-long EXR, times environment.intensity. Throws SceneError for a map that cannot
// be read or is a cube map.
capture::Environment bakeEnvironment(const Scene& scene);

// The sampling table of a baked map (alias method over its texels, one entry per texel, row
// by row), a texel's weight being its luminance times its solid angle (the shader spreads each
// drawn texel over its bilinear footprint: scene_environment_sampling.hlsli). Empty when the
// map has no positive finite weight: nothing to sample.
std::vector<shaders::SceneEnvironmentSample> environmentSamplingTable(const capture::Environment& env);

// Direction of the centre of lat-long texel (x, y) (docs/scenes.md, "Environment").
Vec3 latLongDirection(std::uint32_t x, std::uint32_t y, std::uint32_t width, std::uint32_t height);

} // namespace glint::scene
