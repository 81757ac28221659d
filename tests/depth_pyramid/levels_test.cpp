// Requested level counts (fewer than the tile's 7, exactly 7, one coarse level, the full
// chain) and the completion counter: back at 0 after a build, and a stale count left by an
// aborted frame is cleared by the host before the dispatch (docs/conventions.md, defect DP9).
#include "depth_pyramid/depth_inputs.h"
#include "depth_pyramid/pyramid_runner.h"
#include "support/gpu_test_context.h"

#include <catch2/catch.hpp>

#include <bit>

using namespace glint;

namespace {

// 300x200: level 0 is 320x256 (5x4 groups), the full chain has 9 levels.
DepthPyramidDesc descWithLevels(std::uint32_t levels) {
    DepthPyramidDesc desc;
    desc.size = {300, 200};
    desc.depth = DepthConvention::Reversed;
    desc.channels = DepthPyramidChannels::ClosestAndFarthest;
    desc.levelCount = levels;
    return desc;
}

} // namespace

TEST_CASE("requested level counts build exactly those levels", "[levels]") {
    gpu::Context& context = test::testContext();
    for (const std::uint32_t levels : {1u, 3u, 7u, 8u, 9u, 0u}) {
        const DepthPyramidDesc desc = descWithLevels(levels);
        const std::vector<float> input = test::structuredDepth(300, 200, desc.depth, 100 + levels);
        test::PyramidRunner runner(context, desc);
        const reference::Pyramid p = runner.build(input);
        INFO("levelCount " << levels);
        CHECK(p.levels.size() == (levels == 0 ? 9u : levels));
        test::checkPyramid(input, desc, p);
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("the completion counter is back at 0 after a build", "[levels][counter]") {
    const DepthPyramidDesc desc = descWithLevels(0);
    const std::vector<float> input = test::structuredDepth(300, 200, desc.depth, 7);
    test::PyramidRunner runner(test::testContext(), desc);
    REQUIRE(runner.hasCounter());
    for (int build = 0; build < 3; ++build) {
        test::checkPyramid(input, desc, runner.build(input));
        CHECK(runner.readCounter() == 0u);
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("a stale completion count does not corrupt the coarse levels", "[levels][counter]") {
    // With 20 groups, a stale count of 19 would make the first group to finish act as the last
    // one and build levels 7-8 from an incomplete level 6; the plan zeroes the counter first.
    const DepthPyramidDesc desc = descWithLevels(0);
    const std::vector<float> input = test::structuredDepth(300, 200, desc.depth, 8);
    test::PyramidRunner runner(test::testContext(), desc);
    REQUIRE(runner.hasCounter());
    for (const std::uint32_t stale : {19u, 5u, 0xFFFFFFFFu}) {
        INFO("stale count " << stale);
        test::checkPyramid(input, desc, runner.build(input, stale));
        CHECK(runner.readCounter() == 0u);
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("without the level-0 copy, level 0 is left alone and the other levels are exact", "[levels]") {
    gpu::Context& context = test::testContext();
    for (const auto depth : {DepthConvention::Standard, DepthConvention::Reversed}) {
        DepthPyramidDesc desc = descWithLevels(0);
        desc.depth = depth;
        desc.copyLevel0 = false;
        const std::vector<float> input = test::structuredDepth(300, 200, depth, 9);
        test::PyramidRunner runner(context, desc);
        reference::Pyramid p = runner.build(input);
        REQUIRE(p.levels.size() == 9);
        // The runner fills every level with NaN before the build; level 0 must still hold it.
        std::size_t written = 0;
        for (const float value : p.levels[0].texels)
            written += std::bit_cast<std::uint32_t>(value) != 0x7FC00000u;
        CHECK(written == 0u);
        // Levels 1 and up are the same as with the copy: compare them with level 0 filled in.
        const reference::Pyramid expected =
            reference::buildDepthPyramid(input, 300, 200, depth, desc.channels, 0);
        p.levels[0] = expected.levels[0];
        test::checkPyramid(input, desc, p);
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
