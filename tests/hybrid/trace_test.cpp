// The hybrid ray tracing pass with the harness's BVH callback against a CPU ray caster
// (harness/scene/scene_trace.h, itself tested against brute force): mirror rays from a
// synthetic G-buffer into random triangles and spheres, every ray ray traced. The CPU draws
// each ray in double from the same depth and normal (the mirror direction, the origin pushed
// by rayOffset along the normal); hit or miss, primitive and distance must agree.
#include "hybrid/hybrid_test_frame.h"
#include "support/gpu_test_context.h"

#include "glint/hybrid/glint_hybrid_constants.h"
#include "scene/scene_trace.h"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstring>

using namespace glint;

namespace {

struct Rng {
    std::uint32_t state;
    double next() {
        state = state * 1664525u + 1013904223u;
        return static_cast<double>(state >> 8) / 16777216.0;
    }
};

shaders::float3 point(double x, double y, double z) {
    return {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)};
}

// Triangles and spheres all around the camera, where the reflected rays go.
std::vector<shaders::ScenePrimitive> randomPrimitives(std::uint32_t count, std::uint32_t seed) {
    Rng rng{seed};
    std::vector<shaders::ScenePrimitive> primitives;
    for (std::uint32_t i = 0; i < count; ++i) {
        shaders::ScenePrimitive p{};
        const double cx = 40.0 * rng.next() - 20.0, cy = 40.0 * rng.next() - 20.0,
                     cz = 30.0 * rng.next() - 25.0;
        if (i % 8 == 7) {
            p.kind = GLINT_SCENE_PRIM_SPHERE;
            p.p0 = point(cx, cy, cz);
            p.p1 = point(0.5 + 1.5 * rng.next(), 0, 0);
        } else {
            p.kind = GLINT_SCENE_PRIM_TRIANGLE;
            const double size = 3.0 + 8.0 * rng.next();
            p.p0 = point(cx, cy, cz);
            p.p1 = point(cx + size * (rng.next() - 0.5), cy + size * (rng.next() - 0.5),
                         cz + size * (rng.next() - 0.5));
            p.p2 = point(cx + size * (rng.next() - 0.5), cy + size * (rng.next() - 0.5),
                         cz + size * (rng.next() - 0.5));
        }
        primitives.push_back(p);
    }
    return primitives;
}

// Row-major 4x4 inverse by Gauss-Jordan elimination (the test's projection is invertible).
std::array<double, 16> inverse(std::array<double, 16> m) {
    std::array<double, 16> r{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    for (std::size_t c = 0; c < 4; ++c) {
        std::size_t pivot = c;
        for (std::size_t k = c + 1; k < 4; ++k)
            if (std::abs(m[4 * k + c]) > std::abs(m[4 * pivot + c])) pivot = k;
        for (std::size_t j = 0; j < 4; ++j) {
            std::swap(m[4 * c + j], m[4 * pivot + j]);
            std::swap(r[4 * c + j], r[4 * pivot + j]);
        }
        const double d = m[4 * c + c];
        for (std::size_t j = 0; j < 4; ++j) {
            m[4 * c + j] /= d;
            r[4 * c + j] /= d;
        }
        for (std::size_t k = 0; k < 4; ++k) {
            if (k == c) continue;
            const double f = m[4 * k + c];
            for (std::size_t j = 0; j < 4; ++j) {
                m[4 * k + j] -= f * m[4 * c + j];
                r[4 * k + j] -= f * r[4 * c + j];
            }
        }
    }
    return r;
}

} // namespace

TEST_CASE("the BVH trace callback's hits equal a CPU ray caster's", "[hybrid][trace]") {
    const std::uint32_t width = 53, height = 31;
    test::SssrTestView view = test::makeSssrTestView(width, height, false);
    test::fillRandomSurfaces(view, 17);
    view.desc.frameIndex = 2; // every material alpha is 0: mirrors, exact reflection directions
    HybridDesc desc;
    desc.sssr = view.desc;
    desc.screenSpace = false; // every ray ray traced
    const test::HybridTestScene scene(randomPrimitives(480, 5), {shaders::SceneMaterial{}}, {});
    const std::uint32_t tiles = ((width + 7) / 8) * ((height + 7) / 8);
    const test::HybridFrame frame =
        test::runHybridFrame(desc, view, std::vector<std::uint32_t>(tiles, 0u), {"shade"}, &scene);
    REQUIRE(frame.hits.size() == 4 * frame.hwList.size());

    // The view is the identity; clip -> view through the inverse projection (D3D-style NDC).
    const std::array<double, 16> viewFromClip = inverse(view.desc.projection);
    std::size_t rays = 0, hits = 0, agree = 0;
    for (std::size_t r = 0; r < frame.hwList.size(); ++r) {
        const std::uint32_t entry = frame.hwList[r];
        const std::uint32_t x = entry & 0x7FFFu, y = (entry >> 15) & 0x3FFFu;
        const std::size_t i = std::size_t{y} * width + x;
        const double u = (x + 0.5) / width, v = (y + 0.5) / height;
        const double clip[4] = {2 * u - 1, 1 - 2 * v, view.inputs.depth[i], 1};
        double p[4] = {};
        for (std::size_t row = 0; row < 4; ++row)
            for (std::size_t k = 0; k < 4; ++k) p[row] += viewFromClip[4 * row + k] * clip[k];
        const double position[3] = {p[0] / p[3], p[1] / p[3], p[2] / p[3]};
        double n[3] = {view.inputs.normals[4 * i], view.inputs.normals[4 * i + 1],
                       view.inputs.normals[4 * i + 2]};
        const double nl = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (double& c : n) c /= nl;
        const double pl =
            std::sqrt(position[0] * position[0] + position[1] * position[1] + position[2] * position[2]);
        const double eye[3] = {-position[0] / pl, -position[1] / pl, -position[2] / pl};
        const double nv = n[0] * eye[0] + n[1] * eye[1] + n[2] * eye[2];
        scene::Ray ray;
        for (int c = 0; c < 3; ++c) {
            ray.origin[c] = static_cast<float>(position[c] + n[c] * static_cast<double>(desc.rayOffset));
            ray.direction[c] = static_cast<float>(2 * nv * n[c] - eye[c]);
        }
        ray.tMax = desc.maxRayDistance;
        const scene::Hit expected = scene::traceClosest(scene.bvh(), ray);
        float t = 0.0f;
        std::memcpy(&t, &frame.hits[4 * r], sizeof t);
        const std::uint32_t primitive = frame.hits[4 * r + 1];
        ++rays;
        hits += expected.t >= 0.0f;
        const bool same = expected.t < 0.0f ? t < 0.0f
                                            : t >= 0.0f && primitive == expected.primitive &&
                                                  std::abs(t - expected.t) <= 1e-3f * (1.0f + expected.t);
        agree += same;
    }
    INFO(rays << " rays, " << hits << " CPU hits, " << agree << " agree");
    REQUIRE(rays > 0);
    CHECK(hits > rays / 10);
    CHECK(hits < rays * 9 / 10);
    // Float (GPU) against double set-up: rays that graze a primitive's edge may differ.
    CHECK(agree >= rays * 995 / 1000);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("deferred shading gives hits the shading callback's radiance and misses the environment",
          "[hybrid][shade]") {
    const std::uint32_t width = 40, height = 24;
    test::SssrTestView view = test::makeSssrTestView(width, height, false);
    test::fillRandomSurfaces(view, 23);
    HybridDesc desc;
    desc.sssr = view.desc;
    desc.screenSpace = false;
    // One emissive material and no lights: the harness's shading returns the emission exactly.
    shaders::SceneMaterial glow{};
    glow.emissive = {2.0f, 0.5f, 0.25f};
    const test::HybridTestScene scene(randomPrimitives(480, 9), {glow}, {});
    const test::HybridTestScene empty({}, {glow}, {});
    const std::uint32_t tiles = ((width + 7) / 8) * ((height + 7) / 8);
    const std::vector<std::uint32_t> history(tiles, 0u);
    const test::HybridFrame frame = test::runHybridFrame(desc, view, history, {}, &scene);
    const test::HybridFrame missed = test::runHybridFrame(desc, view, history, {}, &empty);
    REQUIRE(frame.hits.size() == 4 * frame.hwList.size());

    std::size_t hits = 0, misses = 0;
    for (std::size_t r = 0; r < frame.hwList.size(); ++r) {
        const std::uint32_t entry = frame.hwList[r];
        const std::size_t i = std::size_t{(entry >> 15) & 0x3FFFu} * width + (entry & 0x7FFFu);
        float t = 0.0f;
        std::memcpy(&t, &frame.hits[4 * r], sizeof t);
        INFO("pixel " << i << " t " << t);
        if (t >= 0.0f) {
            ++hits;
            CHECK(frame.radiance[4 * i] == 2.0f);
            CHECK(frame.radiance[4 * i + 1] == 0.5f);
            CHECK(frame.radiance[4 * i + 2] == 0.25f);
            CHECK(frame.radiance[4 * i + 3] == t);
            CHECK(frame.confidence[i] == 1.0f);
        } else {
            ++misses;
            for (std::size_t c = 0; c < 3; ++c)
                CHECK(frame.radiance[4 * i + c] == missed.radiance[4 * i + c]);
            CHECK(frame.radiance[4 * i + 3] == 65504.0f);
            CHECK(frame.confidence[i] == 0.0f);
        }
    }
    CHECK(hits > 0);
    CHECK(misses > 0);
    // With nothing to hit, every ray takes the environment, which is finite and not black here.
    for (const std::uint32_t entry : missed.hwList) {
        const std::size_t i = std::size_t{(entry >> 15) & 0x3FFFu} * width + (entry & 0x7FFFu);
        CHECK(missed.radiance[4 * i] + missed.radiance[4 * i + 1] + missed.radiance[4 * i + 2] > 0.0f);
        CHECK(std::isfinite(missed.radiance[4 * i]));
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("a frame whose every tile is FULL_HW equals the ray-tracing-only path", "[hybrid][shade]") {
    const std::uint32_t width = 45, height = 27;
    test::SssrTestView view = test::makeSssrTestView(width, height, false);
    test::fillRandomSurfaces(view, 31);
    for (std::size_t i = 0; i < std::size_t{width} * height; ++i) // mirrors and glossy quads
        view.inputs.material[4 * i] = (i / 7) % 2 == 0 ? 0.0f : 0.1f;
    shaders::SceneMaterial glow{};
    glow.emissive = {1.0f, 3.0f, 0.5f};
    const test::HybridTestScene scene(randomPrimitives(480, 13), {glow}, {});
    const std::uint32_t tiles = ((width + 7) / 8) * ((height + 7) / 8);

    HybridDesc rayTracingOnly;
    rayTracingOnly.sssr = view.desc;
    rayTracingOnly.screenSpace = false;
    const test::HybridFrame expected =
        test::runHybridFrame(rayTracingOnly, view, std::vector<std::uint32_t>(tiles, 0u), {}, &scene);

    // 64 misses in both frames' fields everywhere: u <= 0.02 + 0 - 0.5 * 64 never holds.
    HybridDesc hybrid;
    hybrid.sssr = view.desc;
    const std::uint32_t allMisses = (64u << 16) | (64u << 24);
    const test::HybridFrame frame =
        test::runHybridFrame(hybrid, view, std::vector<std::uint32_t>(tiles, allMisses), {}, &scene);
    for (const std::uint32_t tileClass : frame.tileClass) CHECK(tileClass == GLINT_HYBRID_TILE_FULL_HW);
    CHECK(frame.counters[1] == 0); // no screen-space entries at all
    CHECK(frame.hwList.size() == expected.hwList.size());
    CHECK(frame.radiance == expected.radiance);
    CHECK(frame.confidence == expected.confidence);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
