#include "gbuffer/roughness_runner.h"
#include "reference/roughness_reference.h"
#include "support/gpu_test_context.h"

#include <gpu/gpu_half.h>

#include <catch2/catch.hpp>

#include <cfloat>
#include <cmath>
#include <limits>
#include <random>

using namespace glint;

namespace {

// A material with every channel different, covering [0,1], slightly out of range, and the
// non-finite values the header promises to handle.
std::vector<float> testMaterial(uint32_t width, uint32_t height) {
    std::mt19937 rng(1234);
    std::uniform_real_distribution<float> uniform(-0.1f, 1.1f);
    std::vector<float> material(std::size_t{width} * height * 4);
    for (float& value : material) value = uniform(rng);
    const float specials[] = {
        std::numeric_limits<float>::quiet_NaN(), INFINITY, -INFINITY, 0.0f, 1.0f, -0.0f, 1e-3f};
    for (std::size_t i = 0; i < std::size(specials) * 4 && i < material.size(); ++i)
        material[i] = specials[i % 7];
    return material;
}

// Vulkan lets an implementation flush denormal results to zero, so a reference below the
// smallest normal may come back as 0; anything else must match bit for bit (the pass does
// one clamp and at most one multiply, both exact in IEEE fp32).
void requireMatchesFp32(const std::vector<float>& gpu, const std::vector<float>& reference) {
    REQUIRE(gpu.size() == reference.size());
    for (std::size_t i = 0; i < gpu.size(); ++i) {
        INFO("pixel " << i << ": gpu " << gpu[i] << " reference " << reference[i]);
        REQUIRE(std::isfinite(gpu[i]));
        if (reference[i] < FLT_MIN && gpu[i] == 0.0f) continue;
        REQUIRE(gpu[i] == reference[i]);
    }
}

// Narrowing to R16F may round to nearest or toward zero (implementation-defined), so the
// result must be one of the two half values bracketing the fp32 reference.
void requireMatchesFp16(const std::vector<float>& gpu, const std::vector<float>& reference) {
    REQUIRE(gpu.size() == reference.size());
    for (std::size_t i = 0; i < gpu.size(); ++i) {
        INFO("pixel " << i << ": gpu " << gpu[i] << " reference " << reference[i]);
        REQUIRE(std::isfinite(gpu[i]));
        // Alpha is never negative, so toward zero means one half step down from nearest.
        const uint16_t nearestBits = gpu::floatToHalf(reference[i]);
        const float nearest = gpu::halfToFloat(nearestBits);
        const float towardZero = (nearest > reference[i] && nearestBits > 0)
                                     ? gpu::halfToFloat(static_cast<uint16_t>(nearestBits - 1))
                                     : nearest;
        const bool flushed = reference[i] < 6.1035156e-5f && gpu[i] == 0.0f; // below the smallest normal half
        REQUIRE((gpu[i] == nearest || gpu[i] == towardZero || flushed));
    }
}

} // namespace

TEST_CASE("roughness extraction matches the CPU reference for every channel and input kind",
          "[gbuffer][gpu]") {
    const uint32_t width = 13, height = 7; // odd sizes: partial groups in both dimensions
    const std::vector<float> material = testMaterial(width, height);
    for (uint32_t channel = 0; channel < 4; ++channel) {
        for (bool perceptual : {true, false}) {
            INFO("channel " << channel << (perceptual ? " perceptual" : " alpha"));
            RoughnessExtractionDesc desc;
            desc.size = {width, height};
            desc.materialChannel = channel;
            desc.inputIsPerceptual = perceptual;
            const test::RoughnessRun run = test::runRoughnessExtraction(test::testContext(), material, desc);
            requireMatchesFp32(run.alpha, reference::extractRoughness(material, 4, channel, perceptual));
        }
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("the fp16 roughness permutation matches the reference to half precision", "[gbuffer][gpu]") {
    const uint32_t width = 17, height = 9;
    const std::vector<float> material = testMaterial(width, height);
    RoughnessExtractionDesc desc;
    desc.size = {width, height};
    desc.materialChannel = 1;
    desc.halfPrecisionOutput = true;
    const test::RoughnessRun run = test::runRoughnessExtraction(test::testContext(), material, desc);
    requireMatchesFp16(run.alpha, reference::extractRoughness(material, 4, 1, true));
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("a one-pixel image is extracted", "[gbuffer][gpu]") {
    const std::vector<float> material = {0.25f, 0.5f, 0.75f, 1.0f};
    RoughnessExtractionDesc desc;
    desc.size = {1, 1};
    desc.materialChannel = 2;
    const test::RoughnessRun run = test::runRoughnessExtraction(test::testContext(), material, desc);
    REQUIRE(run.alpha.size() == 1);
    CHECK(run.alpha[0] == 0.5625f); // 0.75^2, exact in binary
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
