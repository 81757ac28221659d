// Hard cases stay finite and in range: NaN and Inf in every input, 1x1 and odd sizes, both
// depth conventions, grazing views, rays toward the camera, depth at 0 and 1, roughness 0 and
// 1, every option permutation; and a grazing mirror scene whose rays must be clipped at the
// near plane.
#include "sssr/sssr_test_scene.h"
#include "support/gpu_test_context.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace glint;

namespace {

void requireFiniteOutputs(const gpu::SssrFrameOutputs& out, std::size_t pixels) {
    for (std::size_t i = 0; i < pixels; ++i) {
        INFO("pixel " << i);
        for (std::size_t c = 0; c < 4; ++c) {
            REQUIRE(std::isfinite(out.radiance[4 * i + c]));
            REQUIRE(out.radiance[4 * i + c] >= 0.0f);
        }
        REQUIRE(out.radiance[4 * i + 3] <= 65504.0f);
        REQUIRE(std::isfinite(out.confidence[i]));
        REQUIRE(out.confidence[i] >= 0.0f);
        REQUIRE(out.confidence[i] <= 1.0f);
        REQUIRE(std::isfinite(out.roughness[i]));
        if (!out.composite.empty())
            for (std::size_t c = 0; c < 4; ++c) REQUIRE(std::isfinite(out.composite[4 * i + c]));
    }
}

// Every input gets non-finite values at scattered pixels, plus extreme legal values.
void poison(test::SssrTestView& view, std::uint32_t seed) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const float specials[] = {nan, inf, -inf, 0.0f, 1.0f, -1.0f, 1e30f, -0.0f};
    std::uint32_t state = seed;
    auto pick = [&state]() {
        state = state * 1664525u + 1013904223u;
        return state >> 8;
    };
    gpu::SssrFrameInputs& in = view.inputs;
    const std::size_t count = in.depth.size();
    for (std::size_t i = 0; i < count; ++i) {
        const std::uint32_t r = pick();
        if (r % 5 == 0) in.depth[i] = specials[(r >> 4) % 8];
        if (r % 7 == 0) in.normals[4 * i + (r >> 5) % 3] = specials[(r >> 8) % 8];
        if (r % 3 == 0) in.material[4 * i] = specials[(r >> 9) % 8];
        if (r % 11 == 0) in.color[4 * i + (r >> 4) % 3] = specials[(r >> 12) % 8];
        if (r % 13 == 0) in.motion[2 * i + (r >> 4) % 2] = specials[(r >> 14) % 8];
        if (r % 17 == 0) in.baseColorMetallic[4 * i + (r >> 4) % 4] = specials[(r >> 15) % 8];
    }
    in.environment[0] = nan;
    in.environment[5] = inf;
}

gpu::SssrFrameOutputs runOnce(const test::SssrTestView& view) {
    gpu::SssrRunner runner(test::testContext(), view.desc);
    runner.upload(view.inputs);
    runner.run(view.desc);
    return runner.readback();
}

} // namespace

TEST_CASE("non-finite and extreme inputs give finite, in-range outputs at every size", "[sssr][hard]") {
    const std::pair<std::uint32_t, std::uint32_t> sizes[] = {{1, 1}, {7, 3}, {1, 37}, {53, 1}, {67, 45}};
    for (const auto& [w, h] : sizes)
        for (const bool reversed : {false, true}) {
            INFO(w << "x" << h << (reversed ? " reversed" : " standard"));
            test::SssrTestView view = test::makeSssrTestView(w, h, reversed);
            test::fillRandomSurfaces(view, w * 7 + h);
            for (std::size_t i = 0; i < view.inputs.material.size() / 4; ++i)
                view.inputs.material[4 * i] = static_cast<float>(i % 5) * 0.05f; // alpha 0 .. 0.2
            poison(view, w * 131 + h);
            view.desc.composite = true;
            view.desc.samplesPerQuad = 1 + static_cast<std::uint32_t>(reversed) * 3;
            view.desc.previousFrameColor = reversed;
            view.desc.halfPrecisionStorage = !reversed;
            requireFiniteOutputs(runOnce(view), std::size_t{w} * h);
        }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("every option permutation stays finite on a poisoned frame", "[sssr][hard]") {
    for (int variant = 0; variant < 6; ++variant) {
        INFO("variant " << variant);
        test::SssrTestView view = test::makeSssrTestView(45, 29, variant % 2 == 1);
        test::fillRandomSurfaces(view, 11u + static_cast<std::uint32_t>(variant));
        for (std::size_t i = 0; i < view.inputs.material.size() / 4; ++i)
            view.inputs.material[4 * i] = static_cast<float>(i % 7) / 6.0f; // alpha 0 .. 1
        poison(view, 77u + static_cast<std::uint32_t>(variant));
        SssrDesc& d = view.desc;
        d.thicknessAware = variant == 0 || variant == 3;
        d.halfResolution = variant == 1;
        d.varianceGuided = variant == 2;
        d.mostDetailedMip = static_cast<std::uint32_t>(variant);
        d.importanceSampleBias = variant == 4 ? 1.0f : 0.3f;
        d.occupancyExitFraction = variant == 5 ? 0.25f : 0.0f;
        d.maxTraversalIterations = variant == 5 ? 3 : 128;
        d.debugOutput = variant % 2 == 0;
        d.halfPrecisionStorage = variant % 3 == 0; // every storage image must match its format
        d.frameIndex = 0xFFFFFFFFu - static_cast<std::uint32_t>(variant);
        const gpu::SssrFrameOutputs out = runOnce(view);
        requireFiniteOutputs(out, 45 * 29);
        for (float value : out.blueNoise) {
            REQUIRE(value >= 0.0f);
            REQUIRE(value < 1.0f);
        }
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("grazing mirrors and rays toward the camera are clipped and stay finite", "[sssr][hard]") {
    for (const bool reversed : {false, true}) {
        INFO((reversed ? "reversed" : "standard"));
        // A floor seen at grazing angles whose normals lean toward the camera, so that most
        // mirror rays come back toward the near plane.
        test::SssrTestView view = test::makeSssrTestView(64, 48, reversed);
        for (std::uint32_t y = 0; y < 48; ++y)
            for (std::uint32_t x = 0; x < 64; ++x) {
                test::setViewDepth(view, x, y, 0.1001 + 0.05 * y);
                const std::size_t i = std::size_t{y} * 64 + x;
                view.inputs.normals[4 * i + 0] = 0.0f;
                view.inputs.normals[4 * i + 1] = y % 2 ? 0.001f : 1.0f;
                view.inputs.normals[4 * i + 2] = y % 2 ? 1.0f : 0.001f;
            }
        view.desc.debugOutput = true;
        const gpu::SssrFrameOutputs out = runOnce(view);
        requireFiniteOutputs(out, 64 * 48);
        for (std::size_t i = 0; i < 64 * 48; ++i) {
            REQUIRE(std::isfinite(out.rayInfo[4 * i]));
            REQUIRE(std::isfinite(out.rayInfo[4 * i + 1]));
            REQUIRE(out.rayInfo[4 * i + 2] <= 6.0f);
        }
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
