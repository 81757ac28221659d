// The three a-trous passes on the device against the CPU reference, and hard cases.
#include "reference/shadow_denoiser_reference.h"
#include "shadow_denoiser/shadow_runner.h"
#include "support/gpu_test_context.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace glint;

namespace {

// exp/pow/sqrt differ between the device and the C library by a few ulps; three passes
// compound them, so compare with an absolute tolerance well above that and far below any
// visible difference.
constexpr float kTolerance = 2e-4f;

reference::ShadowFilterInputs referenceInputs(const ShadowDenoiserDesc& desc,
                                              const test::ShadowInputs& inputs) {
    reference::ShadowFilterInputs ref;
    ref.width = desc.size.width;
    ref.height = desc.size.height;
    ref.meanVariance = inputs.meanVariance;
    ref.depth = inputs.depth;
    ref.normals = inputs.normals;
    const double n = desc.nearPlane;
    const double f = desc.farPlane;
    ref.viewDepth[0] = static_cast<float>(n * f / (f - n));
    ref.viewDepth[1] = static_cast<float>(f / (f - n));
    ref.viewDepth[2] = -1.0f;
    ref.depthSigma = desc.depthSigma;
    ref.normalPower = desc.normalPower;
    ref.contrastRemap = desc.contrastRemap;
    return ref;
}

void checkFilterOnce(const ShadowDenoiserDesc& desc, const test::ShadowInputs& inputs) {
    const std::uint32_t width = desc.size.width, height = desc.size.height;
    const test::ShadowOutputs outputs = test::runShadowDenoiser(desc, inputs);
    const std::vector<float> expected = reference::shadowFilter(referenceInputs(desc, inputs));
    INFO(width << "x" << height << (desc.pairedFilter ? ", paired" : ", three dispatches"));
    REQUIRE(outputs.filtered.size() == expected.size());
    float worst = 0.0f;
    std::size_t nonFinite = 0;
    for (std::size_t i = 0; i < expected.size(); ++i) {
        if (!std::isfinite(outputs.filtered[i]))
            ++nonFinite;
        else
            worst = std::max(worst, std::abs(outputs.filtered[i] - expected[i]));
    }
    CHECK(nonFinite == 0u);
    CHECK(worst <= kTolerance);
    // The filter does work: receivers move away from their noisy input.
    std::size_t changed = 0;
    for (std::size_t i = 0; i < expected.size(); i += 2)
        changed += std::abs(expected[i] - std::clamp(inputs.meanVariance[i], 0.0f, 1.0f)) > 1e-3f ? 1u : 0u;
    if (expected.size() > 2) CHECK(changed * 4 > expected.size() / 2);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

// Both forms of the filter without classification, over every tile: steps 1 and 2 paired in
// one dispatch ("filter01", then "filter2"), and three dispatches ("filter0..2").
void checkFilter(std::uint32_t width, std::uint32_t height, const test::ShadowInputs& inputs,
                 bool contrastRemap = false) {
    for (bool paired : {true, false}) {
        ShadowDenoiserDesc desc;
        desc.size = {width, height};
        desc.classify = false;
        desc.contrastRemap = contrastRemap;
        desc.pairedFilter = paired;
        // Against the reference at 2e-4, variance included: both channels in 32-bit floats.
        desc.outputFormat = Format::RG32Float;
        checkFilterOnce(desc, inputs);
    }
}
} // namespace

TEST_CASE("filter 64x48: matches the CPU reference", "[filter]") {
    checkFilter(64, 48, test::makeShadowInputs(64, 48, 1));
    checkFilter(64, 48, test::makeShadowInputs(64, 48, 1), true); // FidelityFX's contrast remap
}
TEST_CASE("filter 1x1 and 13x7: match the CPU reference", "[filter]") {
    checkFilter(1, 1, test::makeShadowInputs(1, 1, 2));
    checkFilter(13, 7, test::makeShadowInputs(13, 7, 3));
}
TEST_CASE("filter 317x123: matches the CPU reference", "[filter]") {
    checkFilter(317, 123, test::makeShadowInputs(317, 123, 4));
}
TEST_CASE("filter: NaN and Inf depth, normals and moments give finite output", "[filter][finite]") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    test::ShadowInputs inputs = test::makeShadowInputs(45, 29, 5);
    for (std::size_t i = 0; i < inputs.depth.size(); i += 5) inputs.depth[i] = i % 2 ? nan : -inf;
    for (std::size_t i = 1; i < inputs.depth.size(); i += 3)
        inputs.normals[4 * i + (i % 3)] = i % 2 ? nan : inf;
    for (std::size_t i = 2; i < inputs.depth.size(); i += 4)
        inputs.meanVariance[2 * i + (i % 2)] = i % 3 ? nan : inf;
    for (std::size_t i = 6; i < inputs.depth.size(); i += 9)
        inputs.normals[4 * i] = inputs.normals[4 * i + 1] = 0.0f;
    checkFilter(45, 29, inputs);
}

TEST_CASE("an invalid desc is refused with the planner's message, its prefix once", "[filter][plan]") {
    ShadowDenoiserDesc desc;
    desc.size = {8, 8};
    desc.depthSigma = 0.0f;
    CHECK_THROWS_WITH(test::ShadowRunner(desc), "shadow denoiser: depthSigma must be finite and >= 1e-6");
    desc.depthSigma = 1.0f;
    desc.normalPower = 0.5f;
    CHECK_THROWS_WITH(test::ShadowRunner(desc), "shadow denoiser: normalPower must be 1..256");
}
