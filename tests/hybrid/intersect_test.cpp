// The hybrid screen-space intersection against SSSR's own results on the same view (SSSR's
// traversal is tested against a brute-force march in tests/sssr): every confident ray keeps its
// SSSR result and counts as a hit, every other ray below the ray-tracing threshold goes to the
// ray-traced list (its pixel untouched) and counts as a miss, each weighted by 1 + its quad
// copies into its tile's counter; the ray tracer's arguments cover the list. With re-shading,
// the rays that keep a screen-space result with any confidence go instead to the re-shaded list
// with SSSR's hit pixel, distance and confidence. With the thickness growth off the screen-space
// half is SSSR's traversal exactly; with it on, no ray loses confidence and some gain.
#include "hybrid/hybrid_test_frame.h"
#include "support/gpu_test_context.h"

#include "glint/hybrid/glint_hybrid_constants.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
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

// SSSR alone on the view: each traced pixel's result, confidence and (debug output) hit.
gpu::SssrFrameOutputs sssrAlone(const test::SssrTestView& view) {
    SssrDesc desc = view.desc;
    desc.debugOutput = true;
    gpu::SssrRunner sssr(test::testContext(), desc);
    sssr.upload(view.inputs);
    sssr.run(desc);
    return sssr.readback();
}

HybridDesc intersectDesc(const test::SssrTestView& view, float rayTracingThreshold, bool reshade) {
    HybridDesc desc;
    desc.sssr = view.desc;
    desc.feedback = false; // every tile FULL_SW: every ray tries screen space first
    desc.rayTracingThreshold = rayTracingThreshold;
    desc.reshade = reshade;
    desc.thicknessRoughnessGrowth = 0.0f; // SSSR's own thickness
    desc.thicknessDistanceGrowth = 0.0f;
    return desc;
}

std::vector<std::uint32_t> noHistory(std::uint32_t width, std::uint32_t height) {
    return std::vector<std::uint32_t>(std::size_t{(width + 7) / 8} * ((height + 7) / 8), 0u);
}

// `bothOutcomes`: the view is large enough that some rays hit on screen and some do not.
// `previousFrameColor`: SSSR's option, hits fetch "color" through the motion at the hit.
void checkIntersection(std::uint32_t width, std::uint32_t height, float rayTracingThreshold, bool reshade,
                       bool bothOutcomes, bool previousFrameColor = false) {
    INFO(width << "x" << height << " ray-tracing threshold " << rayTracingThreshold << " re-shade " << reshade
               << " previous frame's colour " << previousFrameColor);
    test::SssrTestView view = intersectView(width, height, width * 3 + height);
    view.desc.frameIndex = 5;
    view.desc.previousFrameColor = previousFrameColor;
    const gpu::SssrFrameOutputs expected = sssrAlone(view);

    const HybridDesc desc = intersectDesc(view, rayTracingThreshold, reshade);
    const std::uint32_t tilesX = (width + 7) / 8, tilesY = (height + 7) / 8;
    const test::HybridFrame hybrid =
        test::runHybridFrame(desc, view, noHistory(width, height), {"trace", "shade"});

    std::set<std::uint32_t> traced(hybrid.hwList.begin(), hybrid.hwList.end());
    CHECK(traced.size() == hybrid.hwList.size());
    std::map<std::uint32_t, std::size_t> reshaded; // entry -> position in the re-shaded list
    for (std::size_t k = 0; k < hybrid.reshadedList.size(); ++k) reshaded[hybrid.reshadedList[k]] = k;
    CHECK(reshaded.size() == hybrid.reshadedList.size());
    std::map<std::uint32_t, std::uint32_t> feedback; // tile -> expected counter
    std::size_t screenSpaceRays = 0, toRayTracer = 0, toShading = 0, hits = 0;
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
        } else if (reshade && confidence > 0.0f) {
            // Left to the shading pass with SSSR's hit: its pixel, distance and confidence.
            hits += hit;
            ++toShading;
            CHECK(traced.count(entry) == 0);
            REQUIRE(reshaded.count(entry) == 1);
            const std::uint32_t* record = &hybrid.reshadedHits[4 * reshaded[entry]];
            const auto hitX = static_cast<std::uint32_t>(std::floor(expected.rayInfo[4 * i]));
            const auto hitY = static_cast<std::uint32_t>(std::floor(expected.rayInfo[4 * i + 1]));
            CHECK(std::bit_cast<float>(record[0]) == expected.radiance[4 * i + 3]);
            CHECK(record[1] == (std::min(hitX, width - 1) | (std::min(hitY, height - 1) << 16)));
            CHECK(std::bit_cast<float>(record[2]) == confidence);
            CHECK(hybrid.radiance[4 * i + 3] == 65504.0f);
            CHECK(hybrid.confidence[i] == 0.0f);
        } else {
            hits += hit;
            CHECK(traced.count(entry) == 0);
            CHECK(reshaded.count(entry) == 0);
            for (std::uint32_t channel = 0; channel < 4; ++channel)
                CHECK(hybrid.radiance[4 * i + channel] == expected.radiance[4 * i + channel]);
            CHECK(hybrid.confidence[i] == confidence);
        }
    }
    CHECK(screenSpaceRays == expected.rayList.size());
    CHECK(toRayTracer == hybrid.hwList.size());
    CHECK(toShading == hybrid.reshadedList.size());
    if (bothOutcomes) {
        CHECK(hits > 0);
        CHECK(toRayTracer > 0);
        CHECK(reshade == (toShading > 0));
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
    // The shading pass's: over both lists.
    const std::uint32_t shadeGroups = static_cast<std::uint32_t>((toRayTracer + toShading + 63) / 64);
    CHECK(hybrid.arguments[9] == std::min(shadeGroups, 1024u));
    CHECK(hybrid.arguments[10] == (shadeGroups + 1023) / 1024);
    CHECK(hybrid.arguments[11] == 1);
    CHECK(hybrid.counters[4] == 0);
    CHECK(hybrid.counters[6] == 0);
    CHECK(hybrid.counters[0] == 0);
}

} // namespace

TEST_CASE("the hybrid screen-space intersection keeps SSSR's confident results and hands the rest on",
          "[hybrid][intersect]") {
    for (const bool reshade : {false, true}) {
        checkIntersection(61, 37, 0.22f, reshade, true); // every traced ray eligible for ray tracing
        checkIntersection(61, 37, 0.08f, reshade, true); // glossier rays only: the rest keep the blend
        checkIntersection(8, 8, 0.22f, reshade, false);  // one tile
    }
    checkIntersection(61, 37, 0.22f, false, true, true); // screen colour from last frame's colour
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("the hybrid's thickness growth only ever raises screen-space confidence", "[hybrid][intersect]") {
    // The fit 1 - smoothstep(0, thickness, gap) cannot fall as the thickness grows, so every
    // ray's confidence is at least SSSR's; the random view has glossy hits that gain.
    const std::uint32_t width = 61, height = 37;
    test::SssrTestView view = intersectView(width, height, width * 3 + height);
    view.desc.frameIndex = 5;
    const gpu::SssrFrameOutputs expected = sssrAlone(view);
    HybridDesc desc = intersectDesc(view, 0.22f, false);
    desc.rayTracing = false; // every result written, none handed on
    desc.thicknessRoughnessGrowth = 10.0f;
    desc.thicknessDistanceGrowth = 0.01f;
    const test::HybridFrame grown =
        test::runHybridFrame(desc, view, noHistory(width, height), {"trace", "shade"});
    std::size_t gained = 0, compared = 0;
    for (const std::uint32_t entry : grown.swList) {
        if (entry == GLINT_HYBRID_PADDING_ENTRY) continue;
        const std::uint32_t i = pixelIndex(entry, width);
        INFO("pixel " << i);
        ++compared;
        CHECK(grown.confidence[i] >= expected.confidence[i]);
        gained += grown.confidence[i] > expected.confidence[i];
    }
    CHECK(compared == expected.rayList.size());
    CHECK(gained > 0);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
