// Independent CPU reference for the hierarchical depth pyramid, written from the contract in
// host/include/glint/glint_depth_pyramid.h and docs/depth_pyramid.md, not from
// the HLSL. Two parts that share nothing but the sanitization rule's statement:
//   - buildDepthPyramid: the exact expected texels (min/max are exact, so the GPU must match
//     bit for bit);
//   - checkDepthPyramid: an independent property check of any pyramid (the reference's own,
//     or one read back from the GPU) against a brute-force scan of every texel's footprint.
#pragma once

#include "glint/glint_depth_pyramid.h"

#include <cstdint>
#include <string>
#include <vector>

namespace glint::reference {

// One mip level as read back from the image: `channels` floats per texel, row-major.
struct PyramidLevel {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<float> texels;
};

struct Pyramid {
    std::uint32_t channels = 1; // 1: closest (R32F); 2: closest, farthest (RG32F)
    std::vector<PyramidLevel> levels;

    float closest(std::uint32_t level, std::uint32_t x, std::uint32_t y) const {
        const PyramidLevel& l = levels[level];
        return l.texels[(static_cast<std::size_t>(y) * l.width + x) * channels];
    }
    // Only when channels == 2.
    float farthest(std::uint32_t level, std::uint32_t x, std::uint32_t y) const {
        const PyramidLevel& l = levels[level];
        return l.texels[(static_cast<std::size_t>(y) * l.width + x) * channels + 1];
    }
};

// The far plane's device depth: 1 for standard depth, 0 for reversed.
float farDepth(DepthConvention convention);

// Non-finite (NaN, +-Inf) -> far; clamp to [0, 1]; -0 and denormals -> +0.
float sanitizeDepth(float depth, DepthConvention convention);

// (W, H) rounded up to multiples of 64.
std::uint32_t paddedExtent(std::uint32_t extent);

// 1 + floor(log2(max(W0, H0))).
std::uint32_t fullLevelCount(std::uint32_t level0Width, std::uint32_t level0Height);

// requestedLevels == 0 means the full chain.
Pyramid buildDepthPyramid(const std::vector<float>& depth, std::uint32_t width, std::uint32_t height,
                          DepthConvention convention, DepthPyramidChannels channels,
                          std::uint32_t requestedLevels);

// Checks `pyramid` against the contract by brute force, without using buildDepthPyramid:
//   - level count and level sizes (W0 x H0, then max(1, W0 >> k) x max(1, H0 >> k));
//   - every value is finite, in [0, 1] and not -0;
//   - the closest channel is at least as close as every sanitized input pixel in the texel's
//     footprint, and the farthest channel at least as far;
//   - each value is bit-identical to one of the footprint's sanitized pixels, or is the far
//     value when the footprint reaches into the padding outside W x H.
// The footprint of texel (i, j) at level k <= 6 is [i 2^k, (i+1) 2^k) x [j 2^k, (j+1) 2^k)
// in level-0 pixels; from level 7 on it is the union of the footprints of the level k-1
// texels it reduces (columns 2i .. 2i+1, the last column also every leftover one; rows alike).
// Every level's footprints partition W0 x H0, so the scan costs O(W0 H0) per level.
// Returns "" when the pyramid obeys the contract, else a description of the first
// `maxFailures` violations.
std::string checkDepthPyramid(const std::vector<float>& depth, std::uint32_t width, std::uint32_t height,
                              DepthConvention convention, std::uint32_t expectedLevels,
                              const Pyramid& pyramid, std::size_t maxFailures = 8);

// The first `maxFailures` texels (level, position, channel, both values as bits) where
// `actual` differs from `expected` bit for bit, or where the shapes differ; "" when identical.
std::string compareBits(const Pyramid& expected, const Pyramid& actual, std::size_t maxFailures = 8);

} // namespace glint::reference
