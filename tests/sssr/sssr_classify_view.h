// Random G-buffers for the classification tests (SSSR's and the hybrid's), and the CPU
// reference's view of them.
#pragma once

#include "reference/sssr_reference.h"
#include "sssr/sssr_test_scene.h"

#include <cstdint>

namespace glint::test {

// Random G-buffer: sky, NaN depth, zero and NaN normals, roughness (perceptual, channel 1)
// spread over both sides of the threshold with exact mirrors and NaN.
SssrTestView randomClassifyView(std::uint32_t width, std::uint32_t height, bool reversed, std::uint32_t seed);

// The classification reference's inputs for `view`: depth, normals and the documented roughness
// conversion (alpha = r^2 for a perceptual input, clamped to [0, 1]; non-finite counts as 1).
reference::SssrClassifyInputs classifyReferenceInputs(const SssrTestView& view);

} // namespace glint::test
