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

// The penumbra estimate (docs/shadow_denoiser.md, "Penumbra-aware filtering") against the CPU
// reference, and two analytic expectations: where every blocker is close (a penumbra far under
// a pixel) the filter takes no taps, so the output is its input; where every blocker is far
// (a penumbra wider than 2 x the largest step) it is the full filter, as without the estimate.
TEST_CASE("penumbra-aware filter: hard shadows keep their input, wide penumbrae get the full filter",
          "[filter][penumbra]") {
    constexpr std::uint32_t kWidth = 64, kHeight = 48;
    test::ShadowInputs inputs = test::makeShadowInputs(kWidth, kHeight, 6);
    // Columns 0..23 close blockers, 24..47 far ones, 48.. lit samples (0), unknown (-1) and NaN.
    // Pass 3 reads pass 2 at +-5 (taps +-4, variance +-1), which reads pass 1 at +-7, which
    // reads the input at +-8; each pass's estimate spans +-2 more.
    inputs.blockerDistance.resize(std::size_t{kWidth} * kHeight);
    for (std::uint32_t y = 0; y < kHeight; ++y)
        for (std::uint32_t x = 0; x < kWidth; ++x) {
            float& b = inputs.blockerDistance[std::size_t{y} * kWidth + x];
            const std::uint32_t k = (x * 7u + y * 3u) % 5u;
            if (x < 24)
                b = k == 0 ? 0.0f : 0.01f;
            else if (x < 48)
                b = k == 0 ? 0.0f : 50.0f;
            else
                b = k == 0 ? -1.0f : (k == 1 ? std::numeric_limits<float>::quiet_NaN() : 0.0f);
        }
    for (bool paired : {true, false}) {
        ShadowDenoiserDesc desc;
        desc.size = {kWidth, kHeight};
        desc.classify = false;
        desc.pairedFilter = paired;
        desc.outputFormat = Format::RG32Float;
        desc.lightTanHalfAngle = 0.01746f; // tan(1 degree)
        desc.pixelAngularSize = 0.01f;
        INFO((paired ? "paired" : "three dispatches"));
        // Receivers here have view depth 1..5 (device depth 0.9..0.98, near 0.1, far 1000), and
        // 2 tan / pixel = 3.49: a 0.01 blocker gives a penumbra under 0.04 pixels, a 50 one over
        // 34 (>= 5, the full filter in every pass).
        const test::ShadowOutputs outputs = test::runShadowDenoiser(desc, inputs);
        reference::ShadowFilterInputs ref = referenceInputs(desc, inputs);
        ref.penumbraScale = 2.0f * desc.lightTanHalfAngle / desc.pixelAngularSize;
        ref.blockerDistance = inputs.blockerDistance;
        const std::vector<float> expected = reference::shadowFilter(ref);
        ref.penumbraScale = -1.0f; // no estimate
        const std::vector<float> full = reference::shadowFilter(ref);
        REQUIRE(outputs.filtered.size() == expected.size());
        float worst = 0.0f, hardWorst = 0.0f, wideWorst = 0.0f;
        std::size_t nonFinite = 0, hard = 0, wideChanged = 0;
        for (std::uint32_t y = 0; y < kHeight; ++y)
            for (std::uint32_t x = 0; x < kWidth; ++x) {
                const std::size_t i = std::size_t{y} * kWidth + x;
                const float out = outputs.filtered[2 * i];
                if (!std::isfinite(out) || !std::isfinite(outputs.filtered[2 * i + 1])) {
                    ++nonFinite;
                    continue;
                }
                worst = std::max({worst, std::abs(out - expected[2 * i]),
                                  std::abs(outputs.filtered[2 * i + 1] - expected[2 * i + 1])});
                const bool receiver = inputs.depth[i] < 1.0f;
                // x <= 21: the pixel's own estimate sees only close blockers in every pass, so
                // its value passes through; 33..38: everything it depends on (+-9) is far.
                if (receiver && x <= 21) {
                    ++hard;
                    hardWorst = std::max(hardWorst, std::abs(out - inputs.meanVariance[2 * i]));
                }
                if (receiver && x >= 33 && x <= 38) {
                    wideWorst = std::max(wideWorst, std::abs(out - full[2 * i]));
                    wideChanged += std::abs(out - inputs.meanVariance[2 * i]) > 1e-3f ? 1u : 0u;
                }
            }
        CHECK(nonFinite == 0u);
        CHECK(worst <= kTolerance);
        REQUIRE(hard > 0u);
        CHECK(hardWorst == 0.0f); // no taps: the (in-range) input passes through unchanged
        CHECK(wideWorst <= kTolerance);
        CHECK(wideChanged > 0u);
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
