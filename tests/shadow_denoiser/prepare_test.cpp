// Prepare on the device against the CPU packer, bit for bit, at odd sizes; NaN visibility
// counts as shadowed.
#include "reference/shadow_denoiser_reference.h"
#include "shadow_denoiser/shadow_runner.h"
#include "support/gpu_test_context.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace glint;

namespace {

void checkPrepare(std::uint32_t width, std::uint32_t height) {
    ShadowDenoiserDesc desc;
    desc.size = {width, height};
    desc.filter = false;
    desc.classify = false;
    test::ShadowInputs inputs = test::makeShadowInputs(width, height, width * 31u + height);
    // Values other than 0 and 1 exercise the threshold; NaN is shadowed.
    for (std::size_t i = 0; i < inputs.visibility.size(); i += 7) inputs.visibility[i] = 0.5f;
    for (std::size_t i = 3; i < inputs.visibility.size(); i += 11) inputs.visibility[i] = 0.49f;
    for (std::size_t i = 5; i < inputs.visibility.size(); i += 13)
        inputs.visibility[i] = std::numeric_limits<float>::quiet_NaN();
    const test::ShadowOutputs outputs = test::runShadowDenoiser(desc, inputs);
    const std::vector<std::uint32_t> expected = reference::packShadowMask(inputs.visibility, width, height);
    INFO(width << "x" << height);
    REQUIRE(outputs.mask.size() == expected.size());
    std::size_t mismatches = 0;
    for (std::size_t i = 0; i < expected.size(); ++i) mismatches += outputs.mask[i] != expected[i] ? 1u : 0u;
    CHECK(mismatches == 0u);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

} // namespace

TEST_CASE("prepare 1x1: bit-exact mask", "[prepare]") {
    checkPrepare(1, 1);
}
TEST_CASE("prepare 13x7: bit-exact mask", "[prepare]") {
    checkPrepare(13, 7);
}
TEST_CASE("prepare 8x4 and 33x17 (group edges): bit-exact mask", "[prepare]") {
    checkPrepare(8, 4);
    checkPrepare(33, 17);
}
TEST_CASE("prepare 1917x1077: bit-exact mask", "[prepare]") {
    checkPrepare(1917, 1077);
}
