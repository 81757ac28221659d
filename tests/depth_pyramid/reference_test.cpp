// The CPU reference and the property checker against each other and against hand-worked
// examples, and the checker against pyramids broken the ways the references break them.
#include "depth_pyramid/depth_inputs.h"
#include "reference/depth_pyramid_reference.h"

#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <limits>
#include <random>

using namespace glint;
using reference::Pyramid;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

std::uint32_t bits(float value) {
    return std::bit_cast<std::uint32_t>(value);
}

void setClosest(Pyramid& pyramid, std::uint32_t level, std::uint32_t x, std::uint32_t y, float value) {
    auto& l = pyramid.levels[level];
    l.texels[(static_cast<std::size_t>(y) * l.width + x) * pyramid.channels] = value;
}

void setFarthest(Pyramid& pyramid, std::uint32_t level, std::uint32_t x, std::uint32_t y, float value) {
    auto& l = pyramid.levels[level];
    l.texels[(static_cast<std::size_t>(y) * l.width + x) * pyramid.channels + 1] = value;
}

// Sprinkles every kind of non-finite and out-of-range value over an input.
void sprinkleBadValues(std::vector<float>& depth, std::uint32_t seed) {
    const float bad[] = {kNaN, -kNaN, kInf, -kInf, -0.0f, -0.5f, 1.5f, 1e30f, -1e-30f, 1e-40f, -1e-40f};
    std::mt19937 random(seed);
    for (std::size_t k = 0; k < depth.size() / 50 + 1; ++k)
        depth[random() % depth.size()] = bad[k % std::size(bad)];
}

} // namespace

TEST_CASE("sanitization: non-finite is far, the rest is clamped to [0, 1], -0 and denormals are +0",
          "[reference]") {
    for (const auto convention : {DepthConvention::Standard, DepthConvention::Reversed}) {
        const float far = convention == DepthConvention::Standard ? 1.0f : 0.0f;
        INFO("far " << far);
        CHECK(bits(reference::sanitizeDepth(kNaN, convention)) == bits(far));
        CHECK(bits(reference::sanitizeDepth(-kNaN, convention)) == bits(far));
        CHECK(bits(reference::sanitizeDepth(kInf, convention)) == bits(far));
        CHECK(bits(reference::sanitizeDepth(-kInf, convention)) == bits(far));
        CHECK(bits(reference::sanitizeDepth(-0.0f, convention)) == bits(0.0f));
        CHECK(bits(reference::sanitizeDepth(-0.5f, convention)) == bits(0.0f));
        CHECK(bits(reference::sanitizeDepth(1.5f, convention)) == bits(1.0f));
        CHECK(bits(reference::sanitizeDepth(0.375f, convention)) == bits(0.375f));
        // Denormals become +0 (devices that flush them and devices that keep them agree);
        // the smallest normal float is kept.
        CHECK(bits(reference::sanitizeDepth(1e-40f, convention)) == bits(0.0f));
        CHECK(bits(reference::sanitizeDepth(1e-45f, convention)) == bits(0.0f));
        CHECK(bits(reference::sanitizeDepth(-1e-40f, convention)) == bits(0.0f));
        const float smallestNormal = std::numeric_limits<float>::min();
        CHECK(bits(reference::sanitizeDepth(smallestNormal, convention)) == bits(smallestNormal));
    }
}

TEST_CASE("reference: a 3x2 input, padded with far, by hand", "[reference]") {
    const std::vector<float> depth = {0.5f, 0.25f, 0.75f, 0.125f, 1.0f, 0.625f};
    {
        const Pyramid p = reference::buildDepthPyramid(depth, 3, 2, DepthConvention::Standard,
                                                       DepthPyramidChannels::ClosestAndFarthest, 0);
        REQUIRE(p.levels.size() == 7);
        CHECK(p.levels[0].width == 64);
        CHECK(p.levels[6].width == 1);
        CHECK(p.closest(0, 2, 1) == 0.625f);
        CHECK(p.closest(0, 3, 1) == 1.0f); // padding
        CHECK(p.closest(1, 0, 0) == 0.125f);
        CHECK(p.farthest(1, 0, 0) == 1.0f);
        CHECK(p.closest(1, 1, 0) == 0.625f);
        CHECK(p.farthest(1, 1, 0) == 1.0f); // padding is far in both channels
        CHECK(p.closest(1, 2, 0) == 1.0f);
        CHECK(p.closest(6, 0, 0) == 0.125f);
        CHECK(p.farthest(6, 0, 0) == 1.0f);
    }
    {
        const Pyramid p = reference::buildDepthPyramid(depth, 3, 2, DepthConvention::Reversed,
                                                       DepthPyramidChannels::ClosestAndFarthest, 0);
        CHECK(p.closest(0, 3, 1) == 0.0f);
        CHECK(p.closest(1, 0, 0) == 1.0f);
        CHECK(p.farthest(1, 0, 0) == 0.125f);
        CHECK(p.closest(1, 1, 0) == 0.75f);
        CHECK(p.farthest(1, 1, 0) == 0.0f);
        CHECK(p.closest(6, 0, 0) == 1.0f);
        CHECK(p.farthest(6, 0, 0) == 0.0f);
    }
}

TEST_CASE("reference: from level 7 the last row absorbs the leftover odd row", "[reference]") {
    // 64x192: level 6 is 1x3, level 7 is 1x1. A plain 2x2 reduction would read only rows 0-1
    // of level 6 and lose the spikes in the third tile.
    std::vector<float> depth(64 * 192, 0.5f);
    depth[150 * 64 + 10] = 0.125f;
    depth[170 * 64 + 20] = 0.875f;
    const Pyramid p = reference::buildDepthPyramid(depth, 64, 192, DepthConvention::Standard,
                                                   DepthPyramidChannels::ClosestAndFarthest, 0);
    REQUIRE(p.levels.size() == 8);
    REQUIRE(p.levels[6].height == 3);
    REQUIRE(p.levels[7].width == 1);
    REQUIRE(p.levels[7].height == 1);
    CHECK(p.closest(6, 0, 2) == 0.125f);
    CHECK(p.closest(7, 0, 0) == 0.125f);
    CHECK(p.farthest(7, 0, 0) == 0.875f);
    CHECK(reference::checkDepthPyramid(depth, 64, 192, DepthConvention::Standard, 8, p).empty());

    Pyramid dropped = p;
    setClosest(dropped, 7, 0, 0, 0.5f);
    setFarthest(dropped, 7, 0, 0, 0.5f);
    const std::string report =
        reference::checkDepthPyramid(depth, 64, 192, DepthConvention::Standard, 8, dropped);
    CHECK_THAT(report, Catch::Contains("level 7 texel (0, 0) closest"));
    CHECK_THAT(report, Catch::Contains("level 7 texel (0, 0) farthest"));
}

TEST_CASE("reference and property checker agree on random inputs", "[reference]") {
    const std::uint32_t sizes[][2] = {{1, 1},   {1, 37},   {53, 1},    {7, 3},      {7, 4},      {64, 64},
                                      {65, 65}, {128, 32}, {200, 150}, {130, 1000}, {1000, 130}, {333, 777}};
    std::uint32_t seed = 1;
    for (const auto& size : sizes)
        for (const auto convention : {DepthConvention::Standard, DepthConvention::Reversed})
            for (const auto channels :
                 {DepthPyramidChannels::Closest, DepthPyramidChannels::ClosestAndFarthest})
                for (const bool bad : {false, true}) {
                    const std::uint32_t w = size[0], h = size[1];
                    INFO(w << "x" << h
                           << (convention == DepthConvention::Reversed ? " reversed" : " standard")
                           << (channels == DepthPyramidChannels::Closest ? " closest" : " closest+farthest")
                           << (bad ? " with non-finite values" : ""));
                    std::vector<float> depth = test::structuredDepth(w, h, convention, ++seed);
                    if (bad) sprinkleBadValues(depth, seed);
                    const std::uint32_t full =
                        reference::fullLevelCount(reference::paddedExtent(w), reference::paddedExtent(h));
                    for (const std::uint32_t levels : {full, std::min(full, 3u)}) {
                        const Pyramid p =
                            reference::buildDepthPyramid(depth, w, h, convention, channels, levels);
                        CHECK(p.channels == (channels == DepthPyramidChannels::Closest ? 1u : 2u));
                        CHECK(reference::checkDepthPyramid(depth, w, h, convention, levels, p) == "");
                    }
                }
}

TEST_CASE("the property checker rejects broken pyramids", "[reference]") {
    const std::uint32_t w = 1000, h = 700; // level 6 is 16x11, level 7 is 8x5: row 10 is a leftover
    const auto convention = DepthConvention::Standard;
    const std::vector<float> depth = test::structuredDepth(w, h, convention, 77);
    const Pyramid good =
        reference::buildDepthPyramid(depth, w, h, convention, DepthPyramidChannels::ClosestAndFarthest, 0);
    REQUIRE(good.levels.size() == 11);
    REQUIRE(reference::checkDepthPyramid(depth, w, h, convention, 11, good).empty());
    auto check = [&](const Pyramid& p) {
        return reference::checkDepthPyramid(depth, w, h, convention, 11, p);
    };

    SECTION("the leftover row dropped at level 7 (SPD's 'last row omitted')") {
        // The corner pixel (999, 699) holds the closest depth of the image, in level 6 row 10.
        Pyramid p = good;
        const std::uint32_t i = 7, j = 4;
        float nearest = 1.0f;
        for (std::uint32_t y = 2 * j; y <= 2 * j + 1; ++y)
            for (std::uint32_t x = 2 * i; x <= 2 * i + 1; ++x)
                nearest = std::min(nearest, p.closest(6, x, y));
        REQUIRE(nearest != good.closest(7, i, j));
        setClosest(p, 7, i, j, nearest);
        CHECK_THAT(check(p),
                   Catch::Contains("level 7 texel (7, 4) closest") && Catch::Contains("which is closer"));
    }
    SECTION("a closest value one step too far") {
        Pyramid p = good;
        setClosest(p, 4, 3, 5, std::nextafter(good.closest(4, 3, 5), 2.0f));
        CHECK_THAT(check(p),
                   Catch::Contains("level 4 texel (3, 5) closest") && Catch::Contains("which is closer"));
    }
    SECTION("a closest value one step closer than any pixel") {
        Pyramid p = good;
        setClosest(p, 2, 10, 9, std::nextafter(good.closest(2, 10, 9), -1.0f));
        CHECK_THAT(check(p), Catch::Contains("level 2 texel (10, 9) closest") &&
                                 Catch::Contains("equals no sanitized"));
    }
    SECTION("a farthest value one step too close") {
        Pyramid p = good;
        setFarthest(p, 9, 1, 0, std::nextafter(good.farthest(9, 1, 0), -1.0f));
        CHECK_THAT(check(p),
                   Catch::Contains("level 9 texel (1, 0) farthest") && Catch::Contains("which is farther"));
    }
    SECTION("far in a footprint without padding") {
        Pyramid p = good;
        setFarthest(p, 3, 0, 0, 1.0f);
        CHECK_THAT(check(p), Catch::Contains("level 3 texel (0, 0) farthest"));
    }
    SECTION("non-finite and negative zero values") {
        Pyramid p = good;
        setClosest(p, 0, 5, 5, kNaN);
        setClosest(p, 10, 0, 0, -0.0f);
        const std::string report = check(p);
        CHECK_THAT(report, Catch::Contains("level 0 texel (5, 5) closest nan"));
        CHECK_THAT(report, Catch::Contains("level 10 texel (0, 0) closest -0"));
    }
    SECTION("level 0 padding that is not far") {
        Pyramid p = good;
        setClosest(p, 0, 1010, 3, 0.5f);
        CHECK_THAT(check(p), Catch::Contains("level 0 texel (1010, 3) closest"));
    }
    SECTION("wrong level count or level size") {
        Pyramid p = good;
        p.levels.pop_back();
        CHECK_THAT(check(p), Catch::Contains("10 levels, expected 11"));
        p = good;
        p.levels[8].width = 8;
        CHECK_THAT(check(p), Catch::Contains("level 8 is 8x"));
    }
}

TEST_CASE("compareBits reports every differing level and the first texels", "[reference]") {
    const std::vector<float> depth = test::structuredDepth(100, 100, DepthConvention::Reversed, 5);
    const Pyramid expected = reference::buildDepthPyramid(depth, 100, 100, DepthConvention::Reversed,
                                                          DepthPyramidChannels::Closest, 0);
    Pyramid actual = expected;
    CHECK(reference::compareBits(expected, actual).empty());
    setClosest(actual, 1, 3, 2, std::nextafter(expected.closest(1, 3, 2), 2.0f));
    setClosest(actual, 7, 0, 0, expected.closest(7, 0, 0) == 0.0f ? -0.0f : 0.0f);
    const std::string report = reference::compareBits(expected, actual);
    CHECK_THAT(report, Catch::Contains("level 1 texel (3, 2) closest"));
    CHECK_THAT(report, Catch::Contains("level 7: 1 mismatching"));
    CHECK_THAT(report, Catch::Contains("2 mismatching values in all"));
}
