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

// The clip: a ray toward the camera escapes only past the end of its segment (or the screen's
// edge before that), and that end lies in front of the near plane: where the view-space ray
// p + t l reaches view depth n, less the documented margin of 1e-3 of the way (docs/sssr.md, "Ray
// setup"; clip space is linear in t, so the margin is 1e-3 of t). The device reports where the
// ray escaped: on the projected line of the 3D ray, at or past the end. Without the clip (defect
// SS3) the end lies behind the camera and projects to the other side of the origin.
namespace {

struct ClipCheck {
    std::size_t checked = 0, onScreenEnds = 0;
};

ClipCheck checkClipped(const test::SssrTestView& view, const gpu::SssrFrameOutputs& out) {
    const std::uint32_t w = view.desc.size.width, h = view.desc.size.height;
    const double n = view.desc.nearPlane;
    const auto& m = view.desc.projection;
    const double ySign = view.desc.vulkanNdc ? 1.0 : -1.0;
    ClipCheck result;
    for (std::uint32_t y = 0; y < h; ++y)
        for (std::uint32_t x = 0; x < w; ++x) {
            const std::size_t i = std::size_t{y} * w + x;
            const test::SssrCpuRay ray = test::sssrMirrorRay(view, x, y);
            if (ray.degenerate || !ray.towardCamera || out.rayInfo[4 * i + 2] != 1.0f) continue; // escaped
            // The device bends normals with n.v < 1e-4 toward the eye; leave those out.
            const auto& p = ray.viewPosition;
            const auto& l = ray.viewDirection;
            const double nrm[3] = {view.inputs.normals[4 * i], view.inputs.normals[4 * i + 1],
                                   view.inputs.normals[4 * i + 2]};
            const double pl = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
            const double nl = std::sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
            if (-(p[0] * nrm[0] + p[1] * nrm[1] + p[2] * nrm[2]) / (pl * nl) < 1e-3) continue;
            // The device's end: t at the near plane, times 1 - 1e-3, projected to pixels.
            const double t = (-p[2] - n) / l[2] * (1.0 - 1e-3);
            const double e[4] = {p[0] + t * l[0], p[1] + t * l[1], p[2] + t * l[2], 1.0};
            double clip[4] = {};
            for (std::size_t r = 0; r < 4; ++r)
                for (std::size_t c = 0; c < 4; ++c) clip[r] += m[4 * r + c] * e[c];
            const double endX = (0.5 * clip[0] / clip[3] + 0.5) * w,
                         endY = (0.5 * ySign * clip[1] / clip[3] + 0.5) * h;
            const double dx = ray.direction[0], dy = ray.direction[1];
            const double length2 = dx * dx + dy * dy;
            const double marginAlong = ((endX - ray.origin[0]) * dx + (endY - ray.origin[1]) * dy) / length2;
            const double hx = double(out.rayInfo[4 * i]) - ray.origin[0];
            const double hy = double(out.rayInfo[4 * i + 1]) - ray.origin[1];
            const double along = (hx * dx + hy * dy) / length2; // 1 at the near plane
            const double perpendicular = std::abs(hx * dy - hy * dx) / std::sqrt(length2);
            INFO("pixel (" << x << ", " << y << "): escaped at (" << out.rayInfo[4 * i] << ", "
                           << out.rayInfo[4 * i + 1] << "), the near plane at (" << ray.origin[0] + dx << ", "
                           << ray.origin[1] + dy << "), the device's end at (" << endX << ", " << endY
                           << "), screen clip " << ray.tEnd);
            ++result.checked;
            result.onScreenEnds += ray.tEnd >= 1.0;
            // Float ray setup on the device: a few 1e-7 of the segment, 1e-3 leaves a wide margin.
            CHECK(perpendicular <= 0.05 + 1e-3 * std::sqrt(hx * hx + hy * hy));
            CHECK(marginAlong > 0.0);
            CHECK(marginAlong < 1.0);
            CHECK(along >= std::min(ray.tEnd, marginAlong) - 1e-3);
        }
    return result;
}

} // namespace

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
        view.desc.maxTraversalIterations = 1024; // every ray finishes: hit or escaped
        const gpu::SssrFrameOutputs out = runOnce(view);
        requireFiniteOutputs(out, 64 * 48);
        for (std::size_t i = 0; i < 64 * 48; ++i) {
            REQUIRE(std::isfinite(out.rayInfo[4 * i]));
            REQUIRE(std::isfinite(out.rayInfo[4 * i + 1]));
            REQUIRE(out.rayInfo[4 * i + 2] <= 6.0f);
        }
        // These rays' near-plane ends lie mostly off screen: the screen clip ends them.
        CHECK(checkClipped(view, out).checked > 500u);

        // A wall at view depth 5 whose normals face the eye but for a tilt of up to 0.01: the
        // mirror rays return toward the camera and reach the near plane on screen, nothing in
        // their way.
        test::SssrTestView wall = test::makeSssrTestView(64, 48, reversed);
        for (std::uint32_t y = 0; y < 48; ++y)
            for (std::uint32_t x = 0; x < 64; ++x) {
                test::setViewDepth(wall, x, y, 5.0);
                const std::size_t i = std::size_t{y} * 64 + x;
                const double tiltX = 0.01 * (static_cast<double>(x % 7) / 3.0 - 1.0);
                const double tiltY = 0.01 * (static_cast<double>(y % 5) / 2.0 - 1.0);
                // toEye of the pixel (view space, D3D-style NDC: +y up on the top row).
                const auto& g = wall.desc.projection;
                const double px = (2.0 * (x + 0.5) / 64.0 - 1.0) * 5.0 / g[0];
                const double py = -(2.0 * (y + 0.5) / 48.0 - 1.0) * 5.0 / g[5];
                const double v[3] = {-px + tiltX * 5.0, -py + tiltY * 5.0, 5.0};
                const double vl = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
                for (std::size_t c = 0; c < 3; ++c)
                    wall.inputs.normals[4 * i + c] = static_cast<float>(v[c] / vl);
            }
        wall.desc.debugOutput = true;
        wall.desc.maxTraversalIterations = 1024;
        const gpu::SssrFrameOutputs wallOut = runOnce(wall);
        requireFiniteOutputs(wallOut, 64 * 48);
        const ClipCheck facing = checkClipped(wall, wallOut);
        INFO("checked " << facing.checked << ", near-plane ends on screen " << facing.onScreenEnds);
        CHECK(facing.onScreenEnds > 500u);
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
