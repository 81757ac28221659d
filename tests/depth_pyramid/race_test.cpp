// The last-group pattern under repetition: many groups and coarse levels, built 20 times from
// the same input. Every build must equal the reference: a group whose level-6 texel the last
// group read too early, or a group that never ran, changes levels 7 and up.
#include "depth_pyramid/depth_inputs.h"
#include "depth_pyramid/pyramid_runner.h"
#include "support/gpu_test_context.h"

#include <catch2/catch.hpp>

using namespace glint;

TEST_CASE("20 builds of a 1000x700 pyramid are all identical to the reference", "[race]") {
    DepthPyramidDesc desc;
    desc.size = {1000, 700}; // 16x11 groups, 11 levels
    desc.depth = DepthConvention::Standard;
    desc.channels = DepthPyramidChannels::ClosestAndFarthest;
    const std::vector<float> input = test::structuredDepth(1000, 700, desc.depth, 2024);
    const reference::Pyramid expected =
        reference::buildDepthPyramid(input, 1000, 700, desc.depth, desc.channels, desc.levelCount);
    REQUIRE(expected.levels.size() == 11);
    REQUIRE(reference::checkDepthPyramid(input, 1000, 700, desc.depth, 11, expected).empty());

    test::PyramidRunner runner(test::testContext(), desc);
    REQUIRE(runner.hasCounter());
    for (int build = 0; build < 20; ++build) {
        INFO("build " << build);
        const reference::Pyramid actual = runner.build(input);
        REQUIRE(reference::compareBits(expected, actual) == "");
        REQUIRE(runner.readCounter() == 0u);
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
