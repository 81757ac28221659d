#include "depth_pyramid/depth_inputs.h"

#include <random>

namespace glint::test {

std::vector<float> structuredDepth(std::uint32_t width, std::uint32_t height, DepthConvention convention,
                                   std::uint32_t seed) {
    // Values are generated as "standard" depths (0 near, 1 far) and mirrored for reversed depth.
    std::mt19937 random(seed);
    auto unit = [&random]() { return static_cast<float>(random() >> 8) * (1.0f / 16777216.0f); };
    std::vector<float> depth(static_cast<std::size_t>(width) * height);
    for (float& d : depth) d = 0.25f + 0.5f * unit();

    std::uniform_int_distribution<std::uint32_t> column(0, width - 1), row(0, height - 1);
    // Background pixels, exactly the far plane (before the spikes, which may overwrite them).
    for (int k = 0; k < 3; ++k) depth[static_cast<std::size_t>(row(random)) * width + column(random)] = 1.0f;

    // Each spike gets its own value, stepping towards the plane it imitates, so that whichever
    // spike a coarse texel must keep is unique.
    float near = 0.2f, far = 0.8f;
    auto nearSpike = [&](std::uint32_t x, std::uint32_t y) {
        if (x < width && y < height) depth[static_cast<std::size_t>(y) * width + x] = near;
        near *= 0.97f;
    };
    auto farSpike = [&](std::uint32_t x, std::uint32_t y) {
        if (x < width && y < height) depth[static_cast<std::size_t>(y) * width + x] = far;
        far = 1.0f - (1.0f - far) * 0.97f;
    };
    // Tile edges: the columns and rows either side of every 64-pixel boundary.
    for (std::uint32_t edge = 0; edge < width + 64; edge += 64) {
        if (edge > 0) nearSpike(edge - 1, row(random));
        nearSpike(edge, row(random));
        farSpike(edge == 0 ? 0 : edge - 1, row(random));
    }
    for (std::uint32_t edge = 0; edge < height + 64; edge += 64) {
        if (edge > 0) nearSpike(column(random), edge - 1);
        nearSpike(column(random), edge);
        farSpike(column(random), edge == 0 ? 0 : edge - 1);
    }
    // The last row and column, where a dropped odd row or column would lose them; then the
    // corner, last, so it is the closest (and the farthest spike) of the whole image.
    for (int k = 0; k < 4; ++k) {
        nearSpike(column(random), height - 1);
        nearSpike(width - 1, row(random));
        farSpike(column(random), height - 1);
        farSpike(width - 1, row(random));
    }
    nearSpike(width - 1, height - 1);
    if (width * height > 1) farSpike(width > 1 ? width - 2 : 0, width > 1 ? height - 1 : height - 2);

    if (convention == DepthConvention::Reversed)
        for (float& d : depth) d = 1.0f - d;
    return depth;
}

} // namespace glint::test
