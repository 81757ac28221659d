// glint public API: the hierarchical depth pyramid (docs/depth_pyramid.md).
//
// One dispatch builds a min/max mip chain of device depth in which every coarse texel bounds
// every pixel of its footprint, at any input size. Layout: level 0 is the input padded with
// the far value to W0 x H0 = (W, H) rounded up to multiples of 64, and level k has the
// ordinary mip size max(1, W0 >> k) x max(1, H0 >> k). Levels 0..6 are exact 2x2 reductions
// (the footprint of texel (i, j) at level k is pixels [i 2^k, (i+1) 2^k) x [j 2^k, (j+1) 2^k));
// from level 7 on, a level's last row and column also absorb the previous level's leftover
// odd row and column, so consumers clamp texel coordinates to the level size there.
#pragma once

#include "glint/glint_pass.h"
#include "glint/glint_types.h"

#include <string>

namespace glint {

enum class DepthConvention : std::uint8_t {
    Standard, // near 0, far 1: closest = min
    Reversed, // near 1, far 0: closest = max (also for an infinite far plane)
};

enum class DepthPyramidChannels : std::uint8_t {
    Closest,            // R32F: the closest depth per texel
    ClosestAndFarthest, // RG32F: closest in R, farthest in G (thickness-aware tracing)
};

struct DepthPyramidDesc {
    Extent2D size; // input depth size, 1..16384 each
    DepthConvention depth = DepthConvention::Standard;
    DepthPyramidChannels channels = DepthPyramidChannels::Closest;
    std::uint32_t levelCount = 0; // 0: the full chain down to 1x1; otherwise 1..full
    // false: level 0 is allocated but not written, saving about 45% of the pass's memory
    // traffic; consumers then read level 0 from the input depth (bounds-checked, far outside).
    bool copyLevel0 = true;
};

// Sizes only: no plan, no validation beyond clamping to the supported range.
struct DepthPyramidLayout {
    Extent2D level0;                  // W0 x H0
    std::uint32_t levelCount = 0;     // levels the plan builds (and the image must have)
    std::uint32_t fullLevelCount = 0; // 1 + floor(log2(max(W0, H0)))
};
DepthPyramidLayout depthPyramidLayout(Extent2D size, std::uint32_t requestedLevels);

// Resources of the plan: "depth" (the application's input, sampled, any float depth format),
// "depth_pyramid" (image described in plan.images: W0 x H0, levelCount levels, R32F or RG32F)
// and "depth_pyramid_counter" (a 4-byte buffer in plan.buffers, always bound; when levelCount
// > 7 the pass zeroes it before the dispatch each frame and the last group zeroes it after).
Result planDepthPyramid(const DepthPyramidDesc& desc, EffectPlan& plan, std::string* error);

} // namespace glint
