// Hybrid tile classification, two ways. Against the CPU classification written from
// docs/hybrid.md (tests/reference): tile classes from the feedback history (reprojection through
// the random pixel's motion, the safe band, the lottery), the counters written for the next
// frame, the routing of every ray, the screen-space list's padding to whole 32-entry blocks per
// tile, the ray-traced list and the denoiser's tile list; at odd sizes, partial tiles and a
// single tile. And by properties that hold whatever the lottery drew, from SSSR's per-pixel
// decision alone: each ray routed once, each class's routes, the switches, the counters'
// provenance, the lottery's spawn frequency.
#include "glint/glint_hybrid.h"
#include "glint/hybrid/glint_hybrid_constants.h"
#include "hybrid/hybrid_test_frame.h"
#include "reference/hybrid_classify_reference.h"
#include "sssr/sssr_classify_view.h"
#include "support/gpu_test_context.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
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
// field within the documented 0..64. A sparse history has only tiles without statistics and
// tiles of at most 2 hits and misses, so that the safe band rarely finds a sure tile and most
// decisions, s + h - w m within (0, 1), are the lottery's.
std::vector<std::uint32_t> randomHistory(std::uint32_t tiles, bool sparse, Rng& rng) {
    std::vector<std::uint32_t> history(tiles);
    for (std::uint32_t& counter : history) {
        const std::uint32_t kind = sparse ? rng.word() % 2 : rng.word() % 4;
        std::uint32_t field[4] = {};
        for (std::uint32_t& f : field) f = rng.word() % (sparse ? 3 : 65);
        if (kind == 0) std::fill(std::begin(field), std::end(field), 0u);
        if (kind == 1 && !sparse) field[2] = field[3] = 0; // hits only
        if (kind == 2) field[0] = field[1] = 0;            // misses only
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
    float rayTracingThreshold = 0.22f;
    bool alternateCheckerboard = true;
    bool sparseHistory = false;
};

std::uint32_t tileOf(std::uint32_t entry, std::uint32_t tilesX) {
    return (((entry >> 15) & 0x3FFFu) / 8) * tilesX + (entry & 0x7FFFu) / 8;
}

std::uint32_t field(std::uint32_t counter, std::uint32_t firstBit) {
    return (counter >> firstBit) & 0xFFu;
}

// What follows from the documented rules whatever the lottery drew, checked against SSSR's
// per-pixel decision (sssr_reference.h) and the history alone, not against the hybrid
// reference: every ray routed once, each tile class's routes, the switches, the counters
// carried to the next frame and the denoiser's tiles.
void checkProperties(const Case& c, const test::HybridFrame& gpu, const reference::SssrClassifyInputs& pixels,
                     const std::vector<std::uint32_t>& history) {
    const std::uint32_t tilesX = (c.width + 7) / 8, tilesY = (c.height + 7) / 8;
    const reference::SssrClassification sssr = reference::sssrClassify(pixels);

    // Every ray of the per-pixel decision is in exactly one of the two lists, and nothing else is.
    std::map<std::uint32_t, bool> screenSpaceOf; // entry -> routed to screen space
    for (const std::uint32_t entry : gpu.swList)
        if (entry != GLINT_HYBRID_PADDING_ENTRY) CHECK(screenSpaceOf.emplace(entry, true).second);
    for (const std::uint32_t entry : gpu.hwList) CHECK(screenSpaceOf.emplace(entry, false).second);
    std::vector<std::uint32_t> routed;
    for (const auto& [entry, screenSpace] : screenSpaceOf) routed.push_back(entry);
    CHECK(routed == sssr.rays);

    // The switches decide every tile, whatever its statistics.
    for (const std::uint32_t tileClass : gpu.tileClass) {
        if (!c.rayTracing || !c.feedback) CHECK(tileClass == GLINT_HYBRID_TILE_FULL_SW);
        if (!c.screenSpace) CHECK(tileClass == GLINT_HYBRID_TILE_FULL_HW);
        CHECK(tileClass <= GLINT_HYBRID_TILE_FULL_HW);
    }
    if (!c.rayTracing) CHECK(gpu.hwList.empty());
    if (!c.screenSpace) CHECK(gpu.swList.empty());

    // Per tile class: FULL_SW tiles ray trace only overridden mirrors, FULL_HW tiles keep only
    // rough rays (at or above the RT threshold) in screen space, HALF_SW tiles split the rest by
    // the checkerboard, whose phase is the frame's parity with alternateCheckerboard.
    std::size_t halfSwChecked = 0;
    for (const auto& [entry, screenSpace] : screenSpaceOf) {
        const std::uint32_t x = entry & 0x7FFFu, y = (entry >> 15) & 0x3FFFu;
        INFO("ray at " << x << ", " << y);
        const std::uint32_t tileClass = gpu.tileClass.at(tileOf(entry, tilesX));
        const float alpha = pixels.alpha[std::size_t{y} * c.width + x];
        const bool forcedToRayTracing = c.mirrorsRayTraced && alpha < pixels.mirrorThreshold;
        const bool rough = alpha >= c.rayTracingThreshold;
        if (!c.rayTracing || !c.screenSpace) {
            CHECK(screenSpace == !c.rayTracing);
        } else if (tileClass == GLINT_HYBRID_TILE_FULL_SW) {
            CHECK(screenSpace == !forcedToRayTracing);
        } else if (tileClass == GLINT_HYBRID_TILE_FULL_HW) {
            CHECK(screenSpace == (rough && !forcedToRayTracing));
        } else if (!forcedToRayTracing && !rough) {
            const std::uint32_t phase = c.alternateCheckerboard ? c.frame % 2 : 0u;
            CHECK(screenSpace == ((x % 2 == y % 2) == (phase == 0)));
            ++halfSwChecked;
        } else {
            CHECK(screenSpace == !forcedToRayTracing);
        }
    }
    if (c.rayTracing && c.screenSpace && c.feedback && c.spawnRate > 0.1f) CHECK(halfSwChecked > 0);

    // This frame's counter: fresh fields 0, last frame's fields the fresh fields of a history
    // counter (or 0 without statistics), with at least the fresh hits of every tile in the
    // 3x3 band around it.
    std::set<std::pair<std::uint32_t, std::uint32_t>> freshInHistory{{0u, 0u}};
    for (const std::uint32_t counter : history)
        freshInHistory.insert({field(counter, 0), field(counter, 16)});
    for (std::uint32_t ty = 0; ty < tilesY; ++ty)
        for (std::uint32_t tx = 0; tx < tilesX; ++tx) {
            INFO("tile " << tx << ", " << ty);
            const std::uint32_t counter = gpu.feedback.at(std::size_t{ty} * tilesX + tx);
            CHECK(field(counter, 0) == 0);
            CHECK(field(counter, 16) == 0);
            CHECK(freshInHistory.count({field(counter, 8), field(counter, 24)}) == 1);
            for (std::uint32_t ny = ty == 0 ? 0 : ty - 1; ny <= std::min(ty + 1, tilesY - 1); ++ny)
                for (std::uint32_t nx = tx == 0 ? 0 : tx - 1; nx <= std::min(tx + 1, tilesX - 1); ++nx)
                    CHECK(field(counter, 8) >= field(history.at(std::size_t{ny} * tilesX + nx), 0));
        }

    // The denoiser's tiles: those with a glossy pixel, which include every tile with a ray.
    std::set<std::uint32_t> glossyTiles, tilesWithRays;
    for (std::uint32_t y = 0; y < c.height; ++y)
        for (std::uint32_t x = 0; x < c.width; ++x)
            if (sssr.classes[std::size_t{y} * c.width + x] & reference::kSssrGlossy)
                glossyTiles.insert(reference::packSssrTile(x / 8, y / 8));
    for (const std::uint32_t entry : sssr.rays)
        tilesWithRays.insert(reference::packSssrTile((entry & 0x7FFFu) / 8, ((entry >> 15) & 0x3FFFu) / 8));
    CHECK(std::set<std::uint32_t>(gpu.tileList.begin(), gpu.tileList.end()) == glossyTiles);
    CHECK(gpu.tileList.size() == glossyTiles.size());
    CHECK(std::includes(glossyTiles.begin(), glossyTiles.end(), tilesWithRays.begin(), tilesWithRays.end()));
}

void checkCase(const Case& c) {
    INFO(c.width << "x" << c.height << " frame " << c.frame << " ss " << c.screenSpace << " rt "
                 << c.rayTracing << " feedback " << c.feedback << " mirrors rt " << c.mirrorsRayTraced
                 << " s " << c.spawnRate << " rt threshold " << c.rayTracingThreshold << " alternate "
                 << c.alternateCheckerboard << " sparse history " << c.sparseHistory);
    Rng rng{c.width * 7919u + c.height * 104729u + c.frame};
    test::SssrTestView view =
        test::randomClassifyView(c.width, c.height, false, c.width + 3 * c.height + c.frame);
    const std::size_t pixels = std::size_t{c.width} * c.height;
    view.inputs.motion = randomMotion(pixels, rng);
    const std::uint32_t tilesX = (c.width + 7) / 8, tilesY = (c.height + 7) / 8;
    const std::vector<std::uint32_t> history = randomHistory(tilesX * tilesY, c.sparseHistory, rng);

    HybridDesc desc;
    desc.sssr = view.desc;
    desc.sssr.frameIndex = c.frame;
    desc.screenSpace = c.screenSpace;
    desc.rayTracing = c.rayTracing;
    desc.feedback = c.feedback;
    desc.mirrorsRayTraced = c.mirrorsRayTraced;
    desc.spawnRate = c.spawnRate;
    desc.missWeight = c.missWeight;
    desc.rayTracingThreshold = c.rayTracingThreshold;
    desc.alternateCheckerboard = c.alternateCheckerboard;
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
    in.rayTracingThreshold = c.rayTracingThreshold;
    in.alternateCheckerboard = c.alternateCheckerboard;
    const reference::HybridClassification expected = reference::hybridClassify(in);

    checkProperties(c, gpu, in.sssr, history);

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

// The classes of frame `frame` when every history counter is `counter` and nothing moves, so
// that every tile's statistics are `counter` whatever its random pixel and safe band.
std::vector<std::uint32_t> classesWithUniformHistory(std::uint32_t counter, std::uint32_t frame,
                                                     float spawnRate) {
    constexpr std::uint32_t kWidth = 160, kHeight = 96; // 20 x 12 tiles
    test::SssrTestView view = test::randomClassifyView(kWidth, kHeight, false, 11);
    view.inputs.motion.assign(2 * std::size_t{kWidth} * kHeight, 0.0f);
    HybridDesc desc;
    desc.sssr = view.desc;
    desc.sssr.frameIndex = frame;
    desc.spawnRate = spawnRate;
    const std::vector<std::uint32_t> history(std::size_t{kWidth / 8} * (kHeight / 8), counter);
    return test::runHybridFrame(desc, view, history, {"intersect", "hw_args", "trace", "shade"}).tileClass;
}

} // namespace

TEST_CASE("hybrid classification matches the CPU classification at odd sizes and partial tiles",
          "[hybrid][classify]") {
    for (const auto& [w, h] :
         {std::pair{37u, 21u}, std::pair{9u, 3u}, std::pair{200u, 72u}, std::pair{8u, 8u}})
        for (const std::uint32_t frame : {6u, 7u}) {
            Case c{w, h, frame};
            c.sparseHistory = frame == 7;
            checkCase(c);
        }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("hybrid classification's switches and overrides match the CPU classification",
          "[hybrid][classify]") {
    checkCase({45, 29, 3, false, true});            // ray tracing only: every ray FULL_HW
    checkCase({45, 29, 3, true, false});            // screen space only
    checkCase({45, 29, 3, true, true, false});      // no feedback: every tile FULL_SW
    checkCase({45, 29, 3, true, true, true, true}); // mirrors always ray traced
    checkCase({45, 29, 4, true, true, true, false, 0.5f, 0.25f, 0.22f, true, true}); // a busy lottery
    // Rough rays (alpha at or above the RT threshold, below SSSR's 0.2) stay in screen space,
    // mirrors still ray traced; and a checkerboard that does not alternate on an odd frame.
    checkCase({45, 29, 5, true, true, true, true, 0.5f, 0.25f, 0.05f});
    checkCase({45, 29, 5, true, true, true, false, 0.5f, 0.25f, 0.22f, false});
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("the lottery spawns screen space in a spawnRate share of tiles without statistics, from "
          "the documented integer hash, at frame indices wrapping through 2^32",
          "[hybrid][classify]") {
    // Every history counter with one hit last frame and nothing this frame: last frame's vote
    // is certain (u <= s + 1), this frame's is u_f <= s, so a tile is FULL_SW when its lottery
    // spawns screen space and HALF_SW when not.
    constexpr float kSpawnRate = 0.25f;
    constexpr std::uint32_t kLastFrameHit = 1u << 8, kThisFrameHit = 1u;
    const std::uint32_t frames[] = {4294967293u, 4294967294u, 4294967295u, 0u, 1u, 2u};
    std::map<std::uint32_t, std::vector<std::uint32_t>> spawnedAt; // frame -> its classes
    std::size_t spawned = 0, tiles = 0;
    for (const std::uint32_t frame : frames) {
        INFO("frame " << frame);
        const std::vector<std::uint32_t> classes =
            classesWithUniformHistory(kLastFrameHit, frame, kSpawnRate);
        for (std::size_t tile = 0; tile < classes.size(); ++tile) {
            CHECK(classes[tile] != GLINT_HYBRID_TILE_FULL_HW);
            // The documented draw: u = (r >> 8) / 2^24 with r = hash(tile xor hash(frame)).
            const std::uint32_t r =
                reference::hybridHash(static_cast<std::uint32_t>(tile) ^ reference::hybridHash(frame));
            const bool expectSpawn = static_cast<double>(r >> 8) / 16777216.0 <= double{kSpawnRate};
            CHECK((classes[tile] == GLINT_HYBRID_TILE_FULL_SW) == expectSpawn);
            spawned += classes[tile] == GLINT_HYBRID_TILE_FULL_SW;
        }
        tiles += classes.size();
        spawnedAt[frame] = classes;
    }
    // Binomial(n, p) with p = P(u <= 0.25) = (2^22 + 1) / 2^24 over n = 6 x 240 tiles; 5 standard
    // deviations (a uniform draw falls outside with probability 6e-7).
    const double p = (4194304.0 + 1.0) / 16777216.0, n = static_cast<double>(tiles);
    CHECK(std::abs(static_cast<double>(spawned) - n * p) < 5.0 * std::sqrt(n * p * (1.0 - p)));

    // One hit this frame and nothing last frame: this frame's vote is certain, last frame's is
    // the previous frame's draw, so frame 0's FULL_SW tiles are those frame 2^32 - 1 spawned.
    const std::vector<std::uint32_t> classes = classesWithUniformHistory(kThisFrameHit, 0u, kSpawnRate);
    for (std::size_t tile = 0; tile < classes.size(); ++tile)
        CHECK((classes[tile] == GLINT_HYBRID_TILE_FULL_SW) ==
              (spawnedAt[4294967295u][tile] == GLINT_HYBRID_TILE_FULL_SW));
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("the documented lottery hash stays uniform at large frame indices", "[hybrid][classify]") {
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
