// The BVH (binned SAH) finds exactly what a loop over every primitive finds.
#include "scene/scene_bvh.h"
#include "scene/scene_trace.h"

#include <catch2/catch.hpp>

#include <random>

namespace glint::scene {
namespace {

std::vector<shaders::ScenePrimitive> randomPrimitives(std::mt19937& rng, std::size_t count) {
    std::uniform_real_distribution<float> pos(-5.0f, 5.0f), small(-0.6f, 0.6f), radius(0.05f, 0.5f);
    std::vector<shaders::ScenePrimitive> out;
    for (std::size_t i = 0; i < count; ++i) {
        shaders::ScenePrimitive p{};
        p.p0 = {pos(rng), pos(rng), pos(rng)};
        if (i % 5 == 0) {
            p.kind = GLINT_SCENE_PRIM_SPHERE;
            p.p1 = {radius(rng), 0.0f, 0.0f};
        } else {
            p.kind = GLINT_SCENE_PRIM_TRIANGLE;
            p.p1 = {p.p0.x + small(rng), p.p0.y + small(rng), p.p0.z + small(rng)};
            p.p2 = {p.p0.x + small(rng), p.p0.y + small(rng), p.p0.z + small(rng)};
        }
        p.material = static_cast<std::uint32_t>(i); // identifies the primitive after reordering
        out.push_back(p);
    }
    return out;
}

TEST_CASE("BVH traversal finds the same nearest hit as brute force on random rays", "[scene][bvh]") {
    std::mt19937 rng(7);
    const auto primitives = randomPrimitives(rng, 2000);
    const Bvh bvh = buildBvh(primitives);
    REQUIRE(bvh.primitives.size() == primitives.size());
    std::uniform_real_distribution<float> origin(-8.0f, 8.0f), dir(-1.0f, 1.0f);
    std::size_t hits = 0;
    for (int i = 0; i < 20000; ++i) {
        Ray ray{{origin(rng), origin(rng), origin(rng)}, {dir(rng), dir(rng), dir(rng)}};
        if (i % 7 == 0) ray.tMax = 3.0f;
        const Hit expected = traceBruteForce(primitives, ray);
        const Hit actual = traceClosest(bvh, ray);
        REQUIRE((expected.t > 0.0f) == (actual.t > 0.0f));
        REQUIRE(traceAny(bvh, ray) == (expected.t > 0.0f));
        if (expected.t > 0.0f) {
            ++hits;
            REQUIRE(actual.t == expected.t);
            REQUIRE(bvh.primitives[actual.primitive].material == primitives[expected.primitive].material);
        }
    }
    CHECK(hits > 2000); // the rays exercise hits, not just misses
}

TEST_CASE("BVH nodes bound their primitives and leaves stay small", "[scene][bvh]") {
    std::mt19937 rng(3);
    const Bvh bvh = buildBvh(randomPrimitives(rng, 1000));
    std::vector<int> covered(bvh.primitives.size(), 0);
    for (const auto& node : bvh.nodes) {
        if (node.count == 0) {
            REQUIRE(node.first + 1 < bvh.nodes.size());
            continue;
        }
        CHECK(node.count <= kMaxLeafSize);
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
            ++covered[i];
            const auto& p = bvh.primitives[i];
            const float r = p.kind == GLINT_SCENE_PRIM_SPHERE ? p.p1.x : 0.0f;
            CHECK(p.p0.x - r >= node.boundsMin.x);
            CHECK(p.p0.y + r <= node.boundsMax.y);
        }
    }
    for (int c : covered) REQUIRE(c == 1);
}

TEST_CASE("An empty BVH misses every ray", "[scene][bvh]") {
    const Bvh bvh = buildBvh({});
    REQUIRE(bvh.nodes.size() == 1);
    const Ray ray{{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}};
    CHECK(traceClosest(bvh, ray).t < 0.0f);
    CHECK_FALSE(traceAny(bvh, ray));
}

TEST_CASE("Identical primitives still split into small leaves", "[scene][bvh]") {
    shaders::ScenePrimitive p{};
    p.kind = GLINT_SCENE_PRIM_SPHERE;
    p.p1 = {1.0f, 0.0f, 0.0f};
    const Bvh bvh = buildBvh(std::vector<shaders::ScenePrimitive>(100, p));
    for (const auto& node : bvh.nodes) CHECK(node.count <= kMaxLeafSize);
}

} // namespace
} // namespace glint::scene
