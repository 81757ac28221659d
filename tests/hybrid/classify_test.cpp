// Hybrid tile classification against the CPU classification (tests/reference): tile classes
// from the feedback history (reprojection through the random pixel's motion, the safe band,
// the lottery), the counters written for the next frame, the routing of every ray, the
// screen-space list's padding to whole 32-entry blocks per tile, the ray-traced list and the
// denoiser's tile list; at odd sizes, partial tiles and a single tile.
#include "glint/glint_hybrid.h"
#include "glint/hybrid/glint_hybrid_constants.h"
#include "hybrid/hybrid_test_frame.h"
#include "reference/hybrid_classify_reference.h"
#include "sssr/sssr_classify_view.h"
#include "support/gpu_test_context.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <limits>
#include <map>
#include <set>

using namespace glint;

namespace {

struct Rng {
    std::uint32_t state;
    std::uint32_t word() {
        state = state * 1664525u + 1013904223u;
        return state >> 8;
    }
    float uniform() { return static_cast<float>(word()) / 16777216.0f; }
};

// A history of every kind of tile: no statistics, all hits, all misses, and mixtures, each
// field within the documented 0..64.
std::vector<std::uint32_t> randomHistory(std::uint32_t tiles, Rng& rng) {
    std::vector<std::uint32_t> history(tiles);
    for (std::uint32_t& counter : history) {
        const std::uint32_t kind = rng.word() % 4;
        std::uint32_t field[4] = {};
        for (std::uint32_t& f : field) f = rng.word() % 65;
        if (kind == 0) std::fill(std::begin(field), std::end(field), 0u);
        if (kind == 1) field[2] = field[3] = 0; // hits only
        if (kind == 2) field[0] = field[1] = 0; // misses only
        counter = field[0] | (field[1] << 8) | (field[2] << 16) | (field[3] << 24);
    }
    return history;
}

// Motion in uv: mostly within the frame, some off screen, some NaN.
std::vector<float> randomMotion(std::size_t pixels, Rng& rng) {
    std::vector<float> motion(2 * pixels);
    for (std::size_t i = 0; i < pixels; ++i) {
        const float kind = rng.uniform();
        motion[2 * i] = 0.6f * rng.uniform() - 0.3f;
        motion[2 * i + 1] = 0.6f * rng.uniform() - 0.3f;
        if (kind < 0.05f)
            motion[2 * i] = std::numeric_limits<float>::quiet_NaN();
        else if (kind < 0.1f)
            motion[2 * i + 1] = 2.0f;
    }
    return motion;
}

struct Case {
    std::uint32_t width, height, frame;
    bool screenSpace = true, rayTracing = true, feedback = true, mirrorsRayTraced = false;
    float spawnRate = 0.02f, missWeight = 0.5f;
};

std::uint32_t tileOf(std::uint32_t entry, std::uint32_t tilesX) {
    return (((entry >> 15) & 0x3FFFu) / 8) * tilesX + (entry & 0x7FFFu) / 8;
}

void checkCase(const Case& c) {
    INFO(c.width << "x" << c.height << " frame " << c.frame << " ss " << c.screenSpace << " rt "
                 << c.rayTracing << " feedback " << c.feedback << " mirrors rt " << c.mirrorsRayTraced
                 << " s " << c.spawnRate);
    Rng rng{c.width * 7919u + c.height * 104729u + c.frame};
    test::SssrTestView view =
        test::randomClassifyView(c.width, c.height, false, c.width + 3 * c.height + c.frame);
    const std::size_t pixels = std::size_t{c.width} * c.height;
    view.inputs.motion = randomMotion(pixels, rng);
    const std::uint32_t tilesX = (c.width + 7) / 8, tilesY = (c.height + 7) / 8;
    const std::vector<std::uint32_t> history = randomHistory(tilesX * tilesY, rng);

    HybridDesc desc;
    desc.sssr = view.desc;
    desc.sssr.frameIndex = c.frame;
    desc.screenSpace = c.screenSpace;
    desc.rayTracing = c.rayTracing;
    desc.feedback = c.feedback;
    desc.mirrorsRayTraced = c.mirrorsRayTraced;
    desc.spawnRate = c.spawnRate;
    desc.missWeight = c.missWeight;
    // Classification alone: the intersection would append its misses to the ray-traced list.
    const test::HybridFrame gpu =
        test::runHybridFrame(desc, view, history, {"intersect", "hw_args", "trace", "shade"});

    reference::HybridClassifyInputs in;
    in.sssr = test::classifyReferenceInputs(view);
    in.motion = view.inputs.motion;
    in.history = history;
    in.frameIndex = c.frame;
    in.screenSpace = c.screenSpace;
    in.rayTracing = c.rayTracing;
    in.feedback = c.feedback;
    in.mirrorsRayTraced = c.mirrorsRayTraced;
    in.spawnRate = c.spawnRate;
    in.missWeight = c.missWeight;
    in.rayTracingThreshold = desc.rayTracingThreshold;
    in.alternateCheckerboard = desc.alternateCheckerboard;
    const reference::HybridClassification expected = reference::hybridClassify(in);

    CHECK(gpu.tileClass == expected.tileClass);
    CHECK(gpu.feedback == expected.feedback);
    std::vector<std::uint32_t> tiles = gpu.tileList;
    std::sort(tiles.begin(), tiles.end());
    CHECK(tiles == expected.tiles);

    // The screen-space list: whole blocks of 32, each block one tile's; a tile's real entries
    // first, then padding up to 32 (at most 32 rays) or 64.
    REQUIRE(gpu.swList.size() % 32 == 0);
    std::map<std::uint32_t, std::set<std::uint32_t>> screenSpace;
    std::size_t block = 0;
    while (block * 32 < gpu.swList.size()) {
        const std::uint32_t first = gpu.swList[block * 32];
        REQUIRE(first != GLINT_HYBRID_PADDING_ENTRY);
        const std::uint32_t tile = tileOf(first, tilesX);
        const std::size_t expectedCount =
            expected.screenSpace.count(tile) ? expected.screenSpace.at(tile).size() : 0;
        const std::size_t allocation = expectedCount <= 32 ? 32 : 64;
        REQUIRE(block * 32 + allocation <= gpu.swList.size());
        for (std::size_t i = 0; i < allocation; ++i) {
            const std::uint32_t entry = gpu.swList[block * 32 + i];
            if (i < expectedCount) {
                CHECK(entry != GLINT_HYBRID_PADDING_ENTRY);
                CHECK(tileOf(entry, tilesX) == tile);
                CHECK(screenSpace[tile].insert(entry).second);
            } else {
                CHECK(entry == GLINT_HYBRID_PADDING_ENTRY);
            }
        }
        block += allocation / 32;
    }
    CHECK(screenSpace == expected.screenSpace);

    std::map<std::uint32_t, std::set<std::uint32_t>> rayTraced;
    for (const std::uint32_t entry : gpu.hwList) CHECK(rayTraced[tileOf(entry, tilesX)].insert(entry).second);
    CHECK(rayTraced == expected.rayTraced);
}

} // namespace

TEST_CASE("hybrid classification matches the CPU classification at odd sizes and partial tiles",
          "[hybrid][classify]") {
    for (const auto& [w, h] :
         {std::pair{37u, 21u}, std::pair{9u, 3u}, std::pair{200u, 72u}, std::pair{8u, 8u}})
        for (const std::uint32_t frame : {6u, 7u}) checkCase({w, h, frame});
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("hybrid classification's switches and overrides match the CPU classification",
          "[hybrid][classify]") {
    checkCase({45, 29, 3, false, true});                          // ray tracing only: every ray FULL_HW
    checkCase({45, 29, 3, true, false});                          // screen space only
    checkCase({45, 29, 3, true, true, false});                    // no feedback: every tile FULL_SW
    checkCase({45, 29, 3, true, true, true, true});               // mirrors always ray traced
    checkCase({45, 29, 4, true, true, true, false, 0.5f, 0.25f}); // a busy lottery
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("the lottery draws from an integer hash that stays uniform at large frame indices",
          "[hybrid][classify]") {
    // Tiles without statistics try screen space with probability s each frame (both frames:
    // FULL_SW with s^2, HALF_SW with 2 s (1 - s)); frame indices near 2^32 wrap without loss.
    for (const std::uint32_t frame : {5u, 4000000000u}) {
        INFO("frame " << frame);
        std::size_t screenSpaceNow = 0;
        const std::uint32_t tiles = 100000;
        for (std::uint32_t tile = 0; tile < tiles; ++tile) {
            const std::uint32_t word = reference::hybridHash(tile ^ reference::hybridHash(frame));
            screenSpaceNow += static_cast<float>(word >> 8) / 16777216.0f <= 0.25f;
        }
        // Binomial(100000, 0.25): standard deviation 137; 5 sigma.
        CHECK(std::abs(static_cast<double>(screenSpaceNow) - 25000.0) < 5 * 137.0);
    }
}
