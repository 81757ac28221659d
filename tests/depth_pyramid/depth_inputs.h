// Test inputs for the depth pyramid: random depths with structure that a dropped row, column,
// tile or group would change (unique near and far spikes on tile edges and in the last row
// and column), in either depth convention.
#pragma once

#include "glint/glint_depth_pyramid.h"

#include <cstdint>
#include <vector>

namespace glint::test {

// Random depths in the middle of the range, plus:
//   - near spikes (closer than anything else) on the first and last row and column of 64x64
//     tiles, in the input's last row and column, and a closest one of all in the corner
//     (W-1, H-1), each with a value of its own;
//   - far spikes (farther than the random depths, short of the far plane) likewise, so the
//     farthest channel has something to lose too;
//   - a few exact far-plane (background) pixels.
std::vector<float> structuredDepth(std::uint32_t width, std::uint32_t height, DepthConvention convention,
                                   std::uint32_t seed);

} // namespace glint::test
