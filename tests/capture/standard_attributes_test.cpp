// The attribute conventions other tools rely on: glint.* matrices are Imath (row-vector)
// transforms, and the standard worldToCamera / worldToNDC follow OpenEXR's definitions.
#include "capture/capture_test_support.h"

#include <capture/frame_io.h>
#include <capture/sample_frame.h>

#include <OpenEXR/ImfMatrixAttribute.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <catch2/catch.hpp>

using namespace glint::capture;

namespace {
Imf::Header writtenSampleHeader(const std::string& name, bool ndcYDown) {
    Frame f = makeSampleFrame(32, 24, 1);
    if (ndcYDown) {
        // The same camera in Vulkan-style NDC: negate the projection's y row.
        for (std::size_t c = 0; c < 4; ++c) f.camera.projection.m[4 + c] = -f.camera.projection.m[4 + c];
        f.camera.ndcYDown = true;
    }
    const auto file = test::freshTestDir(name) / "frame.exr";
    writeFrame(file, f);
    return test::exrHeaderOf(file);
}

} // namespace

TEST_CASE("glint matrices are stored transposed so that Imath's p*M equals glint's M*p", "[capture]") {
    const Imf::Header header = writtenSampleHeader("standard_attributes_transposed", false);
    const Camera camera = sampleCamera(32, 24, 1);
    const auto* view = header.findTypedAttribute<Imf::M44dAttribute>("glint.view");
    REQUIRE(view != nullptr);
    const Imath::V3d world(0.25, -1.5, 3.0);
    Imath::V3d imath;
    view->value().multVecMatrix(world, imath);
    const Vec4 glint = transform(camera.view, {world.x, world.y, world.z, 1.0});
    CHECK(imath.x == Approx(glint.x).margin(1e-12));
    CHECK(imath.y == Approx(glint.y).margin(1e-12));
    CHECK(imath.z == Approx(glint.z).margin(1e-12));
}

TEST_CASE("worldToCamera puts points in front of the camera at +z, right at +x and up at +y", "[capture]") {
    for (bool ndcYDown : {false, true}) {
        const Imf::Header header = writtenSampleHeader("standard_attributes_camera", ndcYDown);
        REQUIRE(Imf::hasWorldToCamera(header));
        const Imath::M44f m = Imf::worldToCamera(header);
        const Camera camera = sampleCamera(32, 24, 1);
        const Mat4 toWorld = *inverse(camera.view);
        auto toCamera = [&](double x, double y, double z) {
            const Vec4 w = transform(toWorld, {x, y, z, 1.0});
            Imath::V3f out;
            m.multVecMatrix(
                Imath::V3f(static_cast<float>(w.x), static_cast<float>(w.y), static_cast<float>(w.z)), out);
            return out;
        };
        CHECK(toCamera(0.0, 0.0, -5.0).z == Approx(5.0f).epsilon(1e-5)); // in front
        CHECK(toCamera(1.0, 0.0, -5.0).x == Approx(1.0f).margin(1e-4));  // view +x is right
        CHECK(toCamera(0.0, 1.0, -5.0).y == Approx(1.0f).margin(1e-4));  // view +y is up
    }
}

TEST_CASE("worldToNDC maps a world point to its screen uv, (0,0) top-left, for both NDC y conventions",
          "[capture]") {
    for (bool ndcYDown : {false, true}) {
        const Imf::Header header = writtenSampleHeader("standard_attributes_ndc", ndcYDown);
        REQUIRE(Imf::hasWorldToNDC(header));
        const Imath::M44f m = Imf::worldToNDC(header);
        const Camera camera = sampleCamera(32, 24, 1);
        // A point up and to the left of the screen centre must land at u < 0.5, v < 0.5.
        const Mat4 toWorld = *inverse(camera.view);
        const Vec4 w = transform(toWorld, {-0.5, 0.4, -5.0, 1.0});
        Imath::V3f ndc;
        m.multVecMatrix(Imath::V3f(static_cast<float>(w.x), static_cast<float>(w.y), static_cast<float>(w.z)),
                        ndc);
        // Independent expectation from the unflipped projection (D3D-style, y up).
        const Vec4 clip = transform(multiply(camera.projection, camera.view), {w.x, w.y, w.z, 1.0});
        const double u = 0.5 * clip.x / clip.w + 0.5;
        const double v = 0.5 - 0.5 * clip.y / clip.w;
        CHECK(u < 0.5);
        CHECK(v < 0.5);
        CHECK(ndc.x == Approx(u).margin(1e-5));
        CHECK(ndc.y == Approx(v).margin(1e-5));
        CHECK(ndc.z == Approx(clip.z / clip.w).margin(1e-5)); // z keeps device depth
    }
}
