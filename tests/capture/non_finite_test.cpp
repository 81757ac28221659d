#include "capture/capture_test_support.h"

#include <capture/describe.h>
#include <capture/frame_io.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace glint::capture;

TEST_CASE("NaN and Inf samples load unchanged and are counted per layer", "[capture]") {
    Frame f = test::makeFullFrame(6, 5);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    Layer& color = *findLayer(f, "color");   // HALF: NaN and Inf exist in half too
    Layer& depth = *findLayer(f, "depth");   // FLOAT
    Layer& motion = *findLayer(f, "motion"); // FLOAT, converted on read: NaN must survive
    color.pixels[0] = nan;
    color.pixels[5] = inf;
    color.pixels[9] = -inf;
    depth.pixels[3] = inf;
    motion.pixels[1] = nan;
    const auto file = test::freshTestDir("non_finite") / "frame.exr";
    writeFrame(file, f);

    const Frame read = readFrame(file);
    const Layer& c = *findLayer(read, "color");
    CHECK(std::isnan(c.pixels[0]));
    CHECK(c.pixels[5] == inf);
    CHECK(c.pixels[9] == -inf);
    CHECK(c.nonFinite == 3);
    CHECK(findLayer(read, "depth")->pixels[3] == inf);
    CHECK(findLayer(read, "depth")->nonFinite == 1);
    CHECK(std::isnan(findLayer(read, "motion")->pixels[1]));
    CHECK(findLayer(read, "motion")->nonFinite == 1);
    CHECK(findLayer(read, "normal")->nonFinite == 0);

    const NonFiniteSummary summary = summarizeNonFinite(read);
    CHECK(summary.total == 5);
    REQUIRE(summary.layers.size() == 3);
    CHECK_THAT(describe(read), Catch::Contains("non-finite samples: 5"));
}

TEST_CASE("finite HALF inputs above the half range become Inf and are counted", "[capture]") {
    Frame f = test::makeFullFrame(2, 2);
    findLayer(f, "shadow")->pixels[2] = 1e6f; // > 65504
    const auto file = test::freshTestDir("non_finite_half_overflow") / "frame.exr";
    writeFrame(file, f);
    const Frame read = readFrame(file);
    CHECK(std::isinf(findLayer(read, "shadow")->pixels[2]));
    CHECK(findLayer(read, "shadow")->nonFinite == 1);
}
