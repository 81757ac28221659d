// Motion vectors declared in pixels or NDC become convention A (uv_prev - uv_cur, UV units,
// +v down) in exactly one conversion, applied by the reader.
#include "capture/capture_test_support.h"

#include <capture/frame_io.h>
#include <capture/motion_convention.h>

#include <catch2/catch.hpp>

using namespace glint::capture;

TEST_CASE("UV motion with unit scale is left unchanged", "[capture]") {
    const Float2 a = toConventionA({0.125f, -0.3f}, kConventionA, 640, 480, false);
    CHECK(a.x == 0.125f);
    CHECK(a.y == -0.3f);
}

TEST_CASE("pixel motion is divided by the image size, +y down like v", "[capture]") {
    const Float2 a = toConventionA({64.0f, -12.0f}, {MotionUnits::Pixels, {1.0f, 1.0f}}, 640, 480, false);
    CHECK(a.x == Approx(0.1f));
    CHECK(a.y == Approx(-0.025f));
}

TEST_CASE("pixel motion pointing from previous to current is flipped by a negative scale", "[capture]") {
    const Float2 a = toConventionA({64.0f, -12.0f}, {MotionUnits::Pixels, {-1.0f, -1.0f}}, 640, 480, true);
    CHECK(a.x == Approx(-0.1f));
    CHECK(a.y == Approx(0.025f));
}

TEST_CASE("NDC motion halves and flips y for D3D-style NDC but not for Vulkan-style NDC", "[capture]") {
    const MotionConvention ndc{MotionUnits::Ndc, {1.0f, 1.0f}};
    const Float2 d3d = toConventionA({0.2f, 0.4f}, ndc, 100, 50, false);
    CHECK(d3d.x == Approx(0.1f));
    CHECK(d3d.y == Approx(-0.2f)); // NDC +y is up, v is down
    const Float2 vulkan = toConventionA({0.2f, 0.4f}, ndc, 100, 50, true);
    CHECK(vulkan.x == Approx(0.1f));
    CHECK(vulkan.y == Approx(0.2f));
}

TEST_CASE("convention B (NDC, current minus previous, D3D) is NDC with scale (-1,-1)", "[capture]") {
    // A point at NDC (0.5, 0.5) now was at NDC (0.3, 0.1) last frame.
    const double curNdcX = 0.5, curNdcY = 0.5, prevNdcX = 0.3, prevNdcY = 0.1;
    const Float2 b{static_cast<float>(curNdcX - prevNdcX), static_cast<float>(curNdcY - prevNdcY)};
    const Float2 a = toConventionA(b, {MotionUnits::Ndc, {-1.0f, -1.0f}}, 100, 100, false);
    // Independent: uv = (0.5 x + 0.5, 0.5 - 0.5 y).
    const double expectedU = (0.5 * prevNdcX + 0.5) - (0.5 * curNdcX + 0.5);
    const double expectedV = (0.5 - 0.5 * prevNdcY) - (0.5 - 0.5 * curNdcY);
    CHECK(a.x == Approx(expectedU));
    CHECK(a.y == Approx(expectedV));
}

TEST_CASE("readFrame converts a pixel-unit motion layer into convention A once", "[capture]") {
    Frame f = test::makeFullFrame(8, 4);
    f.motion = {MotionUnits::Pixels, {2.0f, -1.0f}};
    Layer& motion = *findLayer(f, "motion");
    for (std::size_t i = 0; i < motion.pixels.size(); i += 2) {
        motion.pixels[i] = 4.0f;
        motion.pixels[i + 1] = 3.0f;
    }
    const auto file = test::freshTestDir("motion_read_converts") / "frame.exr";
    writeFrame(file, f);

    const FrameHeader header = readFrameHeader(file);
    CHECK(header.motion.units == MotionUnits::Pixels); // the header reports what the file declares

    const Frame read = readFrame(file);
    CHECK(read.motion.units == MotionUnits::Uv);
    CHECK(read.motion.scale.x == 1.0f);
    CHECK(read.motion.scale.y == 1.0f);
    const Layer& converted = *findLayer(read, "motion");
    for (std::size_t i = 0; i < converted.pixels.size(); i += 2) {
        CHECK(converted.pixels[i] == Approx(4.0 * 2.0 / 8.0));
        CHECK(converted.pixels[i + 1] == Approx(3.0 * -1.0 / 4.0));
    }
}
