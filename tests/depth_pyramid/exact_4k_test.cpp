// 3840x2160: twelve levels, 60x34 groups. One convention and channel layout only; the other
// combinations run at the smaller sizes (exact_test.cpp).
#include "depth_pyramid/depth_inputs.h"
#include "depth_pyramid/pyramid_runner.h"
#include "support/gpu_test_context.h"

#include <catch2/catch.hpp>

using namespace glint;

TEST_CASE("3840x2160 reversed depth, closest and farthest: bit-exact pyramid", "[exact][4k]") {
    DepthPyramidDesc desc;
    desc.size = {3840, 2160};
    desc.depth = DepthConvention::Reversed;
    desc.channels = DepthPyramidChannels::ClosestAndFarthest;
    const std::vector<float> input = test::structuredDepth(3840, 2160, desc.depth, 4096);
    test::PyramidRunner runner(test::testContext(), desc);
    const reference::Pyramid pyramid = runner.build(input);
    REQUIRE(pyramid.levels.size() == 12);
    test::checkPyramid(input, desc, pyramid);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
