#include "capture/capture_test_support.h"

#include <capture/describe.h>
#include <capture/frame_io.h>

#include <catch2/catch.hpp>

using namespace glint::capture;

TEST_CASE("describe lists layers with channels, storage and size, the conventions and the effects",
          "[capture]") {
    const auto file = test::freshTestDir("describe") / "frame.exr";
    writeFrame(file, test::makeFullFrame(12, 10));
    const std::string text = describe(readFrameHeader(file));
    CHECK_THAT(text, Catch::Contains("format version 1, frame 1234567, 12x10"));
    CHECK_THAT(text, Catch::Contains("effects: reflections, shadows, depth_pyramid"));
    CHECK_THAT(text, Catch::Contains("depth: reversed, near 0.1, far 333.333333"));
    CHECK_THAT(text, Catch::Contains("ndc: +y down (Vulkan-style)"));
    CHECK_THAT(text, Catch::Contains("view: [1 0.333333333 0 0.3; 0 1 0 -0.142857143; 0 0 1 0; 0 0 0 1]"));
    CHECK_THAT(text, Catch::Contains("roughness: material.G (GGX alpha = r^2)"));
    CHECK_THAT(text, Catch::Contains("motion: uv, scale (1, 1)"));
    CHECK_THAT(text, Catch::Matches(R"((.|\n)*  color +R,G,B,A +HALF +12x10x4\n(.|\n)*)"));
    CHECK_THAT(text, Catch::Matches(R"((.|\n)*  reference\.reflection +R,G,B +FLOAT +12x10x3\n(.|\n)*)"));
}

TEST_CASE("describe of a loaded frame adds non-finite counts per layer", "[capture]") {
    Frame f = test::makeFullFrame(3, 3);
    f.layers[0].nonFinite = 2;
    const std::string text = describe(f);
    CHECK_THAT(text, Catch::Matches(R"((.|\n)*  color .*non-finite 2\n(.|\n)*)"));
    CHECK_THAT(text, Catch::Contains("non-finite samples: 2"));
}
