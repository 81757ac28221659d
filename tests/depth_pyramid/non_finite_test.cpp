// Non-finite and out-of-range depths: NaN and +-Inf become the far plane, the rest is clamped
// to [0, 1], -0 becomes +0, and nothing non-finite reaches any level (docs/conventions.md,
// defect DP8: FMin/FMax with a NaN operand is undefined).
#include "depth_pyramid/depth_inputs.h"
#include "depth_pyramid/pyramid_runner.h"
#include "support/gpu_test_context.h"

#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <string>

using namespace glint;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

std::uint32_t bits(float value) {
    return std::bit_cast<std::uint32_t>(value);
}

DepthPyramidDesc descFor(std::uint32_t width, std::uint32_t height, DepthConvention depth,
                         DepthPyramidChannels channels = DepthPyramidChannels::ClosestAndFarthest) {
    DepthPyramidDesc desc;
    desc.size = {width, height};
    desc.depth = depth;
    desc.channels = channels;
    return desc;
}

// Every value of every level: finite, in [0, 1], never -0 or denormal. Returns the first
// offender.
std::string firstNonFinite(const reference::Pyramid& pyramid) {
    for (std::size_t k = 0; k < pyramid.levels.size(); ++k)
        for (const float value : pyramid.levels[k].texels)
            if (!std::isfinite(value) || value < 0.0f || value > 1.0f || bits(value) == 0x80000000u ||
                (value != 0.0f && value < std::numeric_limits<float>::min()))
                return "level " + std::to_string(k) + " holds " + std::to_string(value) + " (bits " +
                       std::to_string(bits(value)) + ")";
    return "";
}

// The number of values, over all levels, whose bits differ from `expected`.
std::size_t countOtherThan(const reference::Pyramid& pyramid, float expected) {
    std::size_t count = 0;
    for (const auto& level : pyramid.levels)
        for (const float value : level.texels) count += bits(value) != bits(expected);
    return count;
}

} // namespace

TEST_CASE("each kind of bad depth gets its documented value", "[non-finite]") {
    // 4x2 input; level 0 keeps a sanitized copy, level 1 texel (0, 0) covers the first two
    // columns and (1, 0) the next two.
    const std::vector<float> input = {kNaN, kInf, -kInf, -0.0f, -0.5f, 1.5f, 0.25f, 0.75f};
    gpu::Context& context = test::testContext();

    SECTION("standard depth: far is 1") {
        const DepthPyramidDesc desc = descFor(4, 2, DepthConvention::Standard);
        test::PyramidRunner runner(context, desc);
        const reference::Pyramid p = runner.build(input);
        CHECK(firstNonFinite(p) == "");
        const float level0[] = {1.0f, 1.0f, 1.0f, 0.0f, 0.0f, 1.0f, 0.25f, 0.75f};
        for (std::uint32_t i = 0; i < 8; ++i) {
            INFO("pixel " << i);
            CHECK(bits(p.closest(0, i % 4, i / 4)) == bits(level0[i]));
            CHECK(bits(p.farthest(0, i % 4, i / 4)) == bits(level0[i]));
        }
        CHECK(bits(p.closest(0, 4, 0)) == bits(1.0f)); // padding
        CHECK(bits(p.closest(1, 0, 0)) == bits(0.0f)); // -0.5 clamped to the near plane
        CHECK(bits(p.farthest(1, 0, 0)) == bits(1.0f));
        CHECK(bits(p.closest(1, 1, 0)) == bits(0.0f));  // -0 stored as +0
        CHECK(bits(p.farthest(1, 1, 0)) == bits(1.0f)); // -Inf is far, not near
        CHECK(bits(p.closest(6, 0, 0)) == bits(0.0f));
        CHECK(bits(p.farthest(6, 0, 0)) == bits(1.0f));
        test::checkPyramid(input, desc, p);
    }
    SECTION("reversed depth: far is 0") {
        const DepthPyramidDesc desc = descFor(4, 2, DepthConvention::Reversed);
        test::PyramidRunner runner(context, desc);
        const reference::Pyramid p = runner.build(input);
        CHECK(firstNonFinite(p) == "");
        const float level0[] = {0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.25f, 0.75f};
        for (std::uint32_t i = 0; i < 8; ++i) {
            INFO("pixel " << i);
            CHECK(bits(p.closest(0, i % 4, i / 4)) == bits(level0[i]));
            CHECK(bits(p.farthest(0, i % 4, i / 4)) == bits(level0[i]));
        }
        CHECK(bits(p.closest(0, 4, 0)) == bits(0.0f)); // padding
        CHECK(bits(p.closest(1, 0, 0)) == bits(1.0f)); // 1.5 clamped to the near plane
        CHECK(bits(p.farthest(1, 0, 0)) == bits(0.0f));
        CHECK(bits(p.closest(1, 1, 0)) == bits(0.75f));
        CHECK(bits(p.farthest(1, 1, 0)) == bits(0.0f)); // -Inf and -0 both far, stored as +0
        CHECK(bits(p.closest(6, 0, 0)) == bits(1.0f));
        CHECK(bits(p.farthest(6, 0, 0)) == bits(0.0f));
        test::checkPyramid(input, desc, p);
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("bad depths scattered over a multi-group image leave every level finite and exact",
          "[non-finite]") {
    // 300x200: 5x4 groups and 9 levels, so the last group's coarse levels see them too.
    const float bad[] = {kNaN, -kNaN, kInf, -kInf, -0.0f, -0.5f, 1.5f, 3e38f, -1e-30f};
    gpu::Context& context = test::testContext();
    std::uint32_t seed = 11;
    for (const auto depth : {DepthConvention::Standard, DepthConvention::Reversed})
        for (const auto channels :
             {DepthPyramidChannels::Closest, DepthPyramidChannels::ClosestAndFarthest}) {
            const DepthPyramidDesc desc = descFor(300, 200, depth, channels);
            std::vector<float> input = test::structuredDepth(300, 200, depth, ++seed);
            std::mt19937 random(seed);
            for (std::size_t k = 0; k < input.size() / 20; ++k)
                input[random() % input.size()] = bad[k % std::size(bad)];
            // A whole 64x64 tile of NaN and the corner pixel as -Inf.
            for (std::uint32_t y = 64; y < 128; ++y)
                for (std::uint32_t x = 128; x < 192; ++x) input[y * 300 + x] = kNaN;
            input.back() = -kInf;
            test::PyramidRunner runner(context, desc);
            const reference::Pyramid p = runner.build(input);
            CHECK(firstNonFinite(p) == "");
            test::checkPyramid(input, desc, p);
        }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("an image of only NaN or only infinities is far at every level", "[non-finite]") {
    gpu::Context& context = test::testContext();
    for (const float fill : {kNaN, -kInf, kInf})
        for (const auto depth : {DepthConvention::Standard, DepthConvention::Reversed}) {
            const float far = depth == DepthConvention::Standard ? 1.0f : 0.0f;
            const DepthPyramidDesc desc = descFor(130, 70, depth);
            const std::vector<float> input(130 * 70, fill);
            test::PyramidRunner runner(context, desc);
            const reference::Pyramid p = runner.build(input);
            REQUIRE(p.levels.size() == 8);
            INFO("input " << fill << ", far " << far);
            CHECK(countOtherThan(p, far) == 0u);
        }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("denormal depths are stored as +0, the smallest normal depth is kept", "[non-finite]") {
    // Devices differ on denormals (NVIDIA flushes them in min/max), so the sanitization makes
    // every value below the smallest normal float +0 and all devices agree bit for bit.
    gpu::Context& context = test::testContext();
    const float smallestNormal = std::numeric_limits<float>::min();
    for (const auto depth : {DepthConvention::Standard, DepthConvention::Reversed}) {
        const DepthPyramidDesc desc = descFor(300, 200, depth);
        std::vector<float> input = test::structuredDepth(300, 200, depth, 3);
        for (std::size_t k = 0; k < input.size(); k += 97) input[k] = 1e-40f;
        for (std::size_t k = 5; k < input.size(); k += 89) input[k] = -1e-40f;
        input[1] = smallestNormal;
        input.back() = 1e-45f; // the smallest denormal, in the corner
        test::PyramidRunner runner(context, desc);
        const reference::Pyramid p = runner.build(input);
        CHECK(bits(p.closest(0, 0, 0)) == bits(0.0f));
        CHECK(bits(p.closest(0, 1, 0)) == bits(smallestNormal));
        CHECK(bits(p.closest(0, 299, 199)) == bits(0.0f));
        CHECK(bits(p.farthest(0, 299, 199)) == bits(0.0f));
        CHECK(firstNonFinite(p) == "");
        test::checkPyramid(input, desc, p);
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
