// The hybrid screen-space intersection against SSSR's own results on the same view (SSSR's
// traversal is tested against a brute-force march in tests/sssr): every confident ray keeps its
// SSSR result and counts as a hit, every other ray below the ray-tracing threshold goes to the
// ray-traced list (its pixel untouched) and counts as a miss, each weighted by 1 + its quad
// copies into its tile's counter; the ray tracer's arguments cover the list.
#include "hybrid/hybrid_test_frame.h"
#include "support/gpu_test_context.h"

#include "glint/hybrid/glint_hybrid_constants.h"

#include <catch2/catch.hpp>

#include <bit>
#include <map>
#include <set>

using namespace glint;

namespace {

// Random surfaces with mirrors, glossy pixels that share quad rays, and rough ones.
test::SssrTestView intersectView(std::uint32_t width, std::uint32_t height, std::uint32_t seed) {
    test::SssrTestView view = test::makeSssrTestView(width, height, false);
    test::fillRandomSurfaces(view, seed);
    std::uint32_t state = seed;
    for (std::size_t i = 0; i < std::size_t{width} * height; ++i) {
        state = state * 1664525u + 1013904223u;
        const float alphas[] = {0.0f, 0.05f, 0.12f, 0.3f};
        view.inputs.material[4 * i] = alphas[(state >> 16) % 4];
    }
    return view;
}

std::uint32_t pixelIndex(std::uint32_t entry, std::uint32_t width) {
    return ((entry >> 15) & 0x3FFFu) * width + (entry & 0x7FFFu);
}

// `bothOutcomes`: the view is large enough that some rays hit on screen and some do not.
void checkIntersection(std::uint32_t width, std::uint32_t height, float rayTracingThreshold,
                       bool bothOutcomes) {
    INFO(width << "x" << height << " ray-tracing threshold " << rayTracingThreshold);
    test::SssrTestView view = intersectView(width, height, width * 3 + height);
    view.desc.frameIndex = 5;
    // SSSR alone on the same view: each traced pixel's result and confidence.
    gpu::SssrRunner sssr(test::testContext(), view.desc);
    sssr.upload(view.inputs);
    sssr.run(view.desc);
    const gpu::SssrFrameOutputs expected = sssr.readback();

    HybridDesc desc;
    desc.sssr = view.desc;
    desc.feedback = false; // every tile FULL_SW: every ray tries screen space first
    desc.rayTracingThreshold = rayTracingThreshold;
    const std::uint32_t tilesX = (width + 7) / 8, tilesY = (height + 7) / 8;
    const test::HybridFrame hybrid = test::runHybridFrame(
        desc, view, std::vector<std::uint32_t>(std::size_t{tilesX} * tilesY, 0u), {"trace", "shade"});

    std::set<std::uint32_t> traced(hybrid.hwList.begin(), hybrid.hwList.end());
    CHECK(traced.size() == hybrid.hwList.size());
    std::map<std::uint32_t, std::uint32_t> feedback; // tile -> expected counter
    std::size_t screenSpaceRays = 0, toRayTracer = 0, hits = 0;
    for (const std::uint32_t entry : hybrid.swList) {
        if (entry == GLINT_HYBRID_PADDING_ENTRY) continue;
        ++screenSpaceRays;
        const std::uint32_t i = pixelIndex(entry, width);
        const float confidence = expected.confidence[i];
        const bool hit = confidence >= desc.confidenceThreshold;
        const float alpha = expected.roughness[i];
        const std::uint32_t weight = 1u + static_cast<std::uint32_t>(std::popcount(entry >> 29));
        const std::uint32_t tile = (((entry >> 15) & 0x3FFFu) / 8) * tilesX + (entry & 0x7FFFu) / 8;
        feedback[tile] += hit ? weight : weight << 16;
        INFO("pixel " << i << " confidence " << confidence << " alpha " << alpha);
        if (!hit && alpha < rayTracingThreshold) {
            ++toRayTracer;
            CHECK(traced.count(entry) == 1);
            CHECK(hybrid.radiance[4 * i + 3] == 65504.0f); // untouched since classification
            CHECK(hybrid.confidence[i] == 0.0f);
        } else {
            hits += hit;
            CHECK(traced.count(entry) == 0);
            for (std::uint32_t channel = 0; channel < 4; ++channel)
                CHECK(hybrid.radiance[4 * i + channel] == expected.radiance[4 * i + channel]);
            CHECK(hybrid.confidence[i] == confidence);
        }
    }
    CHECK(screenSpaceRays == expected.rayList.size());
    CHECK(toRayTracer == hybrid.hwList.size());
    if (bothOutcomes) {
        CHECK(hits > 0);
        CHECK(toRayTracer > 0);
    }
    for (std::uint32_t tile = 0; tile < tilesX * tilesY; ++tile) {
        INFO("tile " << tile);
        CHECK(hybrid.feedback[tile] == (feedback.count(tile) ? feedback[tile] : 0u));
    }
    // The ray tracer's arguments: ceil(n / 64) groups in rows of at most 1024; counter 4 reset.
    const std::uint32_t groups = static_cast<std::uint32_t>((toRayTracer + 63) / 64);
    CHECK(hybrid.arguments[6] == std::min(groups, 1024u));
    CHECK(hybrid.arguments[7] == (groups + 1023) / 1024);
    CHECK(hybrid.arguments[8] == 1);
    CHECK(hybrid.counters[4] == 0);
    CHECK(hybrid.counters[0] == 0);
}

} // namespace

TEST_CASE("the hybrid screen-space intersection keeps SSSR's confident results and hands the rest on",
          "[hybrid][intersect]") {
    checkIntersection(61, 37, 0.22f, true); // every traced ray eligible for ray tracing
    checkIntersection(61, 37, 0.08f, true); // glossier rays only: the rest keep the screen-space blend
    checkIntersection(8, 8, 0.22f, false);  // one tile
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
