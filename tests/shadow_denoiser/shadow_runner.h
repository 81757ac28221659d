// Runs the shadow denoiser plan on the test context with the application's inputs uploaded
// from CPU arrays; the plan's own resources persist across frames.
#pragma once

#include "glint/glint_shadow_denoiser.h"

#include "support/test_shadow_runner.h"

#include <cstdint>
#include <vector>

namespace glint::test {

using gpu::ShadowInputs;
using gpu::ShadowOutputs;

// gpu::ShadowRunner on the test context.
class ShadowRunner : public gpu::ShadowRunner {
  public:
    explicit ShadowRunner(const ShadowDenoiserDesc& desc);
};

ShadowOutputs runShadowDenoiser(const ShadowDenoiserDesc& desc, const ShadowInputs& inputs);

// Deterministic inputs: binary visibility with structure plus noise, a sloped depth with a
// step and a sky region, normals with a crease, noisy (mean, variance), zero motion.
ShadowInputs makeShadowInputs(std::uint32_t width, std::uint32_t height, std::uint32_t seed);

// makeShadowInputs with a motion of (1.3, -0.7) pixels and a region whose previous depth is
// farther (histories reprojected, some rejected).
ShadowInputs movingShadowInputs(std::uint32_t width, std::uint32_t height, std::uint32_t seed);

// A lit band (x < 12) and a shadowed band (x >= 40) around the penumbra, so tiles of every kind
// meet at group borders.
void addUniformBands(ShadowInputs& inputs, std::uint32_t width, std::uint32_t height);

// The last of three frames (the first a camera cut) with the same inputs, on a new runner.
ShadowOutputs runThreeFrames(ShadowDenoiserDesc desc, const ShadowInputs& inputs);

} // namespace glint::test
