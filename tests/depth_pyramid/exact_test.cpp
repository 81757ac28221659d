// The pass on the device against the CPU reference, bit for bit at every level, for the sizes
// where the references fail (odd, thin, partial tiles, 1080p's leftover rows), in both depth
// conventions and both channel layouts. The property checker judges the same output.
#include "depth_pyramid/depth_inputs.h"
#include "depth_pyramid/pyramid_runner.h"
#include "support/gpu_test_context.h"

#include <catch2/catch.hpp>

using namespace glint;

namespace {

void buildEveryVariant(std::uint32_t width, std::uint32_t height) {
    gpu::Context& context = test::testContext();
    std::uint32_t seed = width * 7919u + height;
    for (const auto depth : {DepthConvention::Standard, DepthConvention::Reversed})
        for (const auto channels :
             {DepthPyramidChannels::Closest, DepthPyramidChannels::ClosestAndFarthest}) {
            DepthPyramidDesc desc;
            desc.size = {width, height};
            desc.depth = depth;
            desc.channels = channels;
            const std::vector<float> input = test::structuredDepth(width, height, depth, ++seed);
            test::PyramidRunner runner(context, desc);
            test::checkPyramid(input, desc, runner.build(input));
        }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

} // namespace

TEST_CASE("1x1 depth: bit-exact pyramid", "[exact]") {
    buildEveryVariant(1, 1);
}
TEST_CASE("1x37 depth: bit-exact pyramid", "[exact]") {
    buildEveryVariant(1, 37);
}
TEST_CASE("53x1 depth: bit-exact pyramid", "[exact]") {
    buildEveryVariant(53, 1);
}
TEST_CASE("7x3 depth: bit-exact pyramid", "[exact]") {
    buildEveryVariant(7, 3);
}
TEST_CASE("7x4 depth (SPD drops a column): bit-exact pyramid", "[exact]") {
    buildEveryVariant(7, 4);
}
TEST_CASE("128x32 depth (SPD issue 2): bit-exact pyramid", "[exact]") {
    buildEveryVariant(128, 32);
}
TEST_CASE("1917x1077 depth: bit-exact pyramid", "[exact]") {
    buildEveryVariant(1917, 1077);
}
TEST_CASE("1920x1080 depth: bit-exact pyramid", "[exact]") {
    buildEveryVariant(1920, 1080);
}
