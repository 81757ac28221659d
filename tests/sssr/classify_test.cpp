// Tile classification and ray-list compaction against the CPU classification (tests/reference):
// the ray list in its documented order (tiles row-major, each tile's pixels row-major), the
// tile list (as a set: its order is arbitrary), the counters and the indirect arguments, the
// extracted roughness, and a frame with nothing to trace.
#include "glint/common/glint_wire_formats.h"
#include "reference/sssr_reference.h"
#include "sssr/sssr_classify_view.h"
#include "sssr/sssr_test_scene.h"
#include "support/gpu_test_context.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

using namespace glint;

namespace {

std::vector<std::uint32_t> sorted(std::vector<std::uint32_t> values) {
    std::sort(values.begin(), values.end());
    return values;
}

// The ray list's order (docs/sssr.md, "The ray list"), from the entries' pixels alone.
std::vector<std::uint32_t> inListOrder(std::vector<std::uint32_t> rays, std::uint32_t width) {
    const std::uint32_t columns = (width + 7) / 8;
    const auto key = [columns](std::uint32_t entry) {
        const std::uint32_t x = shared::GLINT_WIRE_RayEntryX(entry), y = shared::GLINT_WIRE_RayEntryY(entry);
        const std::uint64_t tile = std::uint64_t{y / 8} * columns + x / 8;
        return tile * 64 + (y % 8) * 8 + x % 8;
    };
    std::sort(rays.begin(), rays.end(), [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
    return rays;
}

} // namespace

TEST_CASE("classification matches the CPU classification for 1, 2 and 4 samples per quad",
          "[sssr][classify]") {
    for (const bool reversed : {false, true})
        for (const std::uint32_t samples : {1u, 2u, 4u})
            for (const auto& size : {std::pair{37u, 21u}, std::pair{64u, 16u}, std::pair{9u, 3u}}) {
                INFO("reversed " << reversed << ", samples per quad " << samples << ", " << size.first << "x"
                                 << size.second);
                test::SssrTestView view =
                    test::randomClassifyView(size.first, size.second, reversed, samples * 31u + size.first);
                view.desc.samplesPerQuad = samples;
                gpu::SssrRunner runner(test::testContext(), view.desc);
                runner.upload(view.inputs);
                runner.run(view.desc);
                const gpu::SssrFrameOutputs out = runner.readback();
                const reference::SssrClassification expected =
                    reference::sssrClassify(test::classifyReferenceInputs(view));
                REQUIRE(expected.rayCount > 0);
                CHECK(out.counters[0] == 0); // reset by the arguments pass
                CHECK(out.counters[2] == 0);
                CHECK(out.counters[1] == expected.rayCount);
                CHECK(out.counters[3] == expected.tileCount);
                CHECK(out.rayList == inListOrder(expected.rays, view.desc.size.width));
                CHECK(sorted(out.tileList) == expected.tiles);
                const std::uint32_t groups = (expected.rayCount + 63) / 64;
                CHECK(out.arguments[0] * out.arguments[1] >= groups);
                CHECK(out.arguments[0] == std::min(groups, 1024u));
                CHECK(out.arguments[3] == expected.tileCount);
                const auto inputs = test::classifyReferenceInputs(view);
                for (std::size_t i = 0; i < inputs.alpha.size(); ++i) {
                    INFO("pixel " << i);
                    // Background pixels read no material and store alpha 1 (docs/sssr.md).
                    const bool background =
                        reference::sssrIsBackground(inputs.depth[i], inputs.reversedDepth);
                    REQUIRE(out.roughness[i] == Approx(background ? 1.0f : inputs.alpha[i]).margin(1e-7));
                }
            }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("classification matches the CPU classification on odd tile grids and a single tile",
          "[sssr][classify]") {
    // 200x72 has 25x9 tiles (odd both ways); 8x8 is one tile. (Also the guard for any future
    // grouping of several tiles a group, where such grids leave blocks outside the image.)
    for (const auto& size : {std::pair{200u, 72u}, std::pair{8u, 8u}}) {
        INFO(size.first << "x" << size.second);
        test::SssrTestView view = test::randomClassifyView(size.first, size.second, false, 5u + size.first);
        gpu::SssrRunner runner(test::testContext(), view.desc);
        runner.upload(view.inputs);
        runner.run(view.desc);
        const gpu::SssrFrameOutputs out = runner.readback();
        const auto inputs = test::classifyReferenceInputs(view);
        const reference::SssrClassification expected = reference::sssrClassify(inputs);
        REQUIRE(expected.tileCount > 0);
        CHECK(out.counters[1] == expected.rayCount);
        CHECK(out.counters[3] == expected.tileCount);
        CHECK(out.rayList == inListOrder(expected.rays, view.desc.size.width));
        CHECK(sorted(out.tileList) == expected.tiles);
        for (std::size_t i = 0; i < inputs.alpha.size(); ++i) {
            INFO("pixel " << i);
            const bool background = reference::sssrIsBackground(inputs.depth[i], inputs.reversedDepth);
            REQUIRE(out.roughness[i] == Approx(background ? 1.0f : inputs.alpha[i]).margin(1e-7));
        }
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("variance-guided tracing adds rays where the reprojected variance history is high",
          "[sssr][classify]") {
    test::SssrTestView view = test::randomClassifyView(40, 24, false, 7);
    view.desc.varianceGuided = true;
    view.desc.varianceThreshold = -1.0f; // the (zero) history is above it everywhere
    gpu::SssrRunner runner(test::testContext(), view.desc);
    runner.upload(view.inputs);
    runner.run(view.desc);
    const gpu::SssrFrameOutputs out = runner.readback();
    reference::SssrClassifyInputs in = test::classifyReferenceInputs(view);
    in.varianceGuided = true;
    in.varianceThreshold = -1.0f;
    in.variance.assign(in.alpha.size(), 0.0f);
    const reference::SssrClassification expected = reference::sssrClassify(in);
    const reference::SssrClassification unguided =
        reference::sssrClassify(test::classifyReferenceInputs(view));
    CHECK(expected.rayCount > unguided.rayCount);
    CHECK(out.rayList == inListOrder(expected.rays, view.desc.size.width));
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("a frame with no reflective pixel traces no ray and dispatches zero groups", "[sssr][classify]") {
    for (const bool sky : {true, false}) {
        INFO((sky ? "all sky" : "all rough"));
        test::SssrTestView view = test::makeSssrTestView(33, 17, false);
        if (!sky) {
            for (std::uint32_t y = 0; y < 17; ++y)
                for (std::uint32_t x = 0; x < 33; ++x) test::setViewDepth(view, x, y, 5.0);
            for (std::size_t i = 0; i < 33 * 17; ++i) view.inputs.material[4 * i] = 0.5f; // alpha above 0.2
        }
        gpu::SssrRunner runner(test::testContext(), view.desc);
        runner.upload(view.inputs);
        for (int frame = 0; frame < 2; ++frame) { // the second frame sees the counters the first left
            view.desc.frameIndex = static_cast<std::uint32_t>(frame);
            runner.run(view.desc);
            const gpu::SssrFrameOutputs out = runner.readback();
            CHECK(out.counters[0] == 0);
            CHECK(out.counters[1] == 0);
            CHECK(out.counters[2] == 0);
            CHECK(out.counters[3] == 0);
            CHECK(out.arguments[0] * out.arguments[1] * out.arguments[2] == 0); // intersection groups
            CHECK(out.arguments[3] == 0);                                       // denoiser tiles
            // Rough pixels get the environment, sky pixels 0; every hit distance is the miss value.
            for (std::size_t i = 0; i < 33 * 17; ++i) {
                CHECK(out.radiance[4 * i + 3] == 65504.0f);
                if (sky) CHECK(out.radiance[4 * i] == 0.0f);
                if (!sky) CHECK(out.radiance[4 * i] > 0.0f);
            }
        }
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("the ray list's order is fixed, so a frame with the occupancy exit repeats bit for bit",
          "[sssr][classify]") {
    // 528x512 is 66x64 = 4,224 tiles: 66 blocks of 64 tiles in two superblocks of 64 blocks,
    // so a block's first ray comes from both levels of counts.
    test::SssrTestView view = test::randomClassifyView(528, 512, false, 11);
    view.desc.occupancyExitFraction = 0.25f; // the groups of 64 rays decide when rays stop
    gpu::SssrRunner runner(test::testContext(), view.desc);
    runner.upload(view.inputs);
    const reference::SssrClassification expected =
        reference::sssrClassify(test::classifyReferenceInputs(view));
    const std::uint32_t tiles = 66 * 64;
    // Some block holds more rays than one pass of the compaction's copy loop (4 x 64) moves.
    std::vector<std::uint32_t> blockRays(66, 0);
    for (const std::uint32_t entry : expected.rays)
        ++blockRays[(shared::GLINT_WIRE_RayEntryY(entry) / 8 * 66 + shared::GLINT_WIRE_RayEntryX(entry) / 8) /
                    64];
    REQUIRE(*std::max_element(blockRays.begin(), blockRays.end()) > 256);
    const std::uint32_t firstCount = shared::GLINT_WIRE_RayScratchBlockCount(tiles, 0);
    const std::size_t scratchWords = shared::GLINT_WIRE_RayScratchWords(tiles);
    REQUIRE(scratchWords - firstCount == 66 + 2 + 1); // block and superblock counts, completion
    std::vector<float> firstRadiance;
    for (int run = 0; run < 2; ++run) { // the second run starts from the counts the first left
        INFO("run " << run);
        runner.run(view.desc);
        const gpu::SssrFrameOutputs out = runner.readback();
        CHECK(out.counters[1] == expected.rayCount);
        CHECK(out.rayList == inListOrder(expected.rays, 528));
        const std::vector<std::uint32_t> scratch = runner.bufferWords("sssr_ray_scratch", scratchWords);
        CHECK(
            std::all_of(scratch.begin() + firstCount, scratch.end(), [](std::uint32_t w) { return w == 0; }));
        if (run == 0)
            firstRadiance = out.radiance;
        else
            CHECK(std::memcmp(out.radiance.data(), firstRadiance.data(),
                              firstRadiance.size() * sizeof(float)) == 0);
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
