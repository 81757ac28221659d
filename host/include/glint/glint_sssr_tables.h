// glint public API: the tables the stochastic screen-space reflections (SSSR) read, generated on
// the CPU (docs/sssr.md). The application uploads them once.
//
// Blue noise: a 128 x 128 two-channel tile that the intersection pass samples toroidally (with
// per-frame R2 offsets) to pick each pixel's ray. Upload as RG16_UNORM or RG32F: every value is
// (rank + 0.5) / 16384 for a distinct rank, so 16 bits keep all levels apart.
//
// BRDF LUT: the split-sum DFG table for the composite,
//   L_out = L_lit + R * (F0 * A + B),
// with A, B at (u = N.V, v = perceptual roughness); sample it bilinearly with clamp-to-edge.
#pragma once

#include <cstdint>
#include <vector>

namespace glint {

inline constexpr std::uint32_t kSssrBlueNoiseSize = 128;

// 128 * 128 * 2 floats, RG interleaved, row-major, origin top-left; values (rank + 0.5) / 16384.
// Each channel is a void-and-cluster rank map (Ulichney 1993): a permutation of the 16384 levels
// whose spectrum has almost no low-frequency energy; the two channels are independent.
// Computed once (thread-safe), then cached; the same on every platform.
const std::vector<float>& sssrBlueNoise();

inline constexpr std::uint32_t kSssrBrdfLutSize = 32;
inline constexpr std::uint32_t kSssrBrdfLutMaxSize = 1024;

// size * size * 2 floats (A, B), row-major: row j holds perceptual roughness (j + 0.5) / size,
// column i holds N.V = (i + 0.5) / size. GGX with alpha = roughness^2, height-correlated Smith
// masking-shadowing and Schlick Fresnel, so that F0 * A + B is the directional albedo of the
// specular lobe; 0 <= A, B and A + B <= 1. Empty when size is 0 or above kSssrBrdfLutMaxSize.
std::vector<float> sssrBrdfLut(std::uint32_t size = kSssrBrdfLutSize);

} // namespace glint
