// Captures whose header breaks the format: version, attributes, windows, sizes, camera.
#include "capture/capture_test_support.h"

#include <capture/frame_io.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfDoubleAttribute.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfMatrixAttribute.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfStringVectorAttribute.h>
#include <catch2/catch.hpp>

using namespace glint::capture;

namespace {
// A valid full frame's header, to be broken one way by each test.
Imf::Header validHeader(const std::filesystem::path& dir) {
    return test::validFrameHeader(dir, 16, 8);
}

// Header problems are found by the header-only read too, with the same message.
std::string rejection(const std::filesystem::path& file, const Imf::Header& header) {
    const std::string message = test::rejectionOf(file, header);
    CHECK(message == test::captureErrorOf([&] { (void)readFrameHeader(file); }));
    return message;
}
} // namespace

TEST_CASE("an unknown format version is rejected naming the version", "[capture]") {
    const auto dir = test::freshTestDir("header_version");
    Imf::Header header = validHeader(dir);
    header.insert("glint.formatVersion", Imf::IntAttribute(2));
    const std::string message = rejection(dir / "v2.exr", header);
    CHECK_THAT(message, Catch::Contains("unsupported format version 2"));
}

TEST_CASE("each missing required attribute is named", "[capture]") {
    const auto dir = test::freshTestDir("header_missing_attribute");
    const Imf::Header valid = validHeader(dir);
    for (const char* name : {"glint.frameIndex", "glint.view", "glint.projection", "glint.prevViewProjection",
                             "glint.depthConvention", "glint.near", "glint.far", "glint.ndcYDown",
                             "glint.normalEncoding", "glint.motionUnits", "glint.motionScale",
                             "glint.roughnessSource", "glint.roughnessPerceptual", "glint.effects"}) {
        INFO(name);
        const Imf::Header header = test::withoutAttribute(valid, name);
        const std::string message = rejection(dir / "frame.exr", header);
        CHECK_THAT(message, Catch::Contains(std::string("missing attribute '") + name + "'"));
    }
}

TEST_CASE("an attribute of the wrong type is named with both types", "[capture]") {
    const auto dir = test::freshTestDir("header_wrong_type");
    // OpenEXR refuses to change an attribute's type in place: drop it, then add the other type.
    Imf::Header header = test::withoutAttribute(validHeader(dir), "glint.near");
    header.insert("glint.near", Imf::FloatAttribute(0.1f));
    CHECK_THAT(rejection(dir / "float_near.exr", header),
               Catch::Contains("attribute 'glint.near' has type float, expected double"));
    header = test::withoutAttribute(validHeader(dir), "glint.view");
    header.insert("glint.view", Imf::M44fAttribute(Imath::M44f()));
    CHECK_THAT(rejection(dir / "float_view.exr", header), Catch::Contains("'glint.view' has type m44f"));
}

TEST_CASE("invalid attribute values are rejected", "[capture]") {
    const auto dir = test::freshTestDir("header_invalid_values");
    const Imf::Header valid = validHeader(dir);
    struct Case {
        const char* name;
        std::function<void(Imf::Header&)> edit;
        const char* expected;
    };
    const std::vector<Case> cases{
        {"depth", [](Imf::Header& h) { h.insert("glint.depthConvention", Imf::StringAttribute("Reversed")); },
         "'glint.depthConvention' has unknown value 'Reversed'"},
        {"normals",
         [](Imf::Header& h) { h.insert("glint.normalEncoding", Imf::StringAttribute("spherical")); },
         "'glint.normalEncoding' has unknown value"},
        {"units", [](Imf::Header& h) { h.insert("glint.motionUnits", Imf::StringAttribute("mm")); },
         "'glint.motionUnits' has unknown value"},
        {"flag", [](Imf::Header& h) { h.insert("glint.ndcYDown", Imf::IntAttribute(2)); },
         "'glint.ndcYDown' is 2, expected 0 or 1"},
        {"index", [](Imf::Header& h) { h.insert("glint.frameIndex", Imf::IntAttribute(-1)); }, "negative"},
        {"source",
         [](Imf::Header& h) { h.insert("glint.roughnessSource", Imf::StringAttribute("material")); },
         "expected <layer>.<channel>"},
        {"near", [](Imf::Header& h) { h.insert("glint.near", Imf::DoubleAttribute(-1.0)); },
         "near plane -1 is not a positive finite number"},
        {"far", [](Imf::Header& h) { h.insert("glint.far", Imf::DoubleAttribute(0.01)); },
         "far plane 0.01 is not a finite number greater than near"},
        {"singular",
         [](Imf::Header& h) { h.insert("glint.projection", Imf::M44dAttribute(Imath::M44d(0.0))); },
         "projection matrix is singular"},
        {"nan",
         [](Imf::Header& h) {
             Imath::M44d m;
             m[3][0] = std::numeric_limits<double>::quiet_NaN();
             h.insert("glint.view", Imf::M44dAttribute(m));
         },
         "view matrix is not finite"},
        {"effect",
         [](Imf::Header& h) {
             h.insert("glint.effects", Imf::StringVectorAttribute({"reflections", "caustics"}));
         },
         "unknown effect 'caustics'"},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        Imf::Header header = valid;
        c.edit(header);
        CHECK_THAT(rejection(dir / (std::string(c.name) + ".exr"), header), Catch::Contains(c.expected));
    }
}

TEST_CASE("a data window that does not start at the origin is rejected", "[capture]") {
    const auto dir = test::freshTestDir("header_window_origin");
    Imf::Header header = validHeader(dir);
    header.dataWindow() = Imath::Box2i({1, 0}, {16, 7});
    header.displayWindow() = header.dataWindow();
    CHECK_THAT(rejection(dir / "shifted.exr", header), Catch::Contains("does not start at (0,0)"));
    header.dataWindow() = Imath::Box2i({-2, -3}, {13, 4});
    header.displayWindow() = header.dataWindow();
    CHECK_THAT(rejection(dir / "negative.exr", header), Catch::Contains("data window (-2,-3)-(13,4)"));
}

TEST_CASE("a data window that differs from the display window is rejected", "[capture]") {
    const auto dir = test::freshTestDir("header_window_mismatch");
    Imf::Header header = validHeader(dir);
    header.displayWindow() = Imath::Box2i({0, 0}, {31, 15});
    CHECK_THAT(rejection(dir / "cropped.exr", header),
               Catch::Contains("data window (0,0)-(15,7) differs from display window (0,0)-(31,15)"));
}

TEST_CASE("absurd dimensions are rejected from the header before any pixel allocation", "[capture]") {
    const auto dir = test::freshTestDir("header_absurd_size");
    Imf::Header header = validHeader(dir);
    header.channels() = Imf::ChannelList();
    header.channels().insert("depth.Z", Imf::Channel(Imf::FLOAT));
    // Written with only a header and an offset table, as a hostile file would be; the
    // reader must refuse from the header alone.
    auto writeHeaderOnly = [&](const std::filesystem::path& file, int w, int h) {
        header.dataWindow() = Imath::Box2i({0, 0}, {w - 1, h - 1});
        header.displayWindow() = header.dataWindow();
        test::writeHeaderOnlyExr(file, header);
        const std::string message = test::captureErrorOf([&] { (void)readFrame(file); });
        CHECK(test::isOneLine(message));
        return message;
    };
    CHECK_THAT(writeHeaderOnly(dir / "wide.exr", 16385, 1), Catch::Contains("16385x1 exceeds the limit"));
    CHECK_THAT(writeHeaderOnly(dir / "tall.exr", 1, 1 << 30), Catch::Contains("exceeds the limit"));
    CHECK_THAT(writeHeaderOnly(dir / "many_pixels.exr", 16384, 16384),
               Catch::Contains("16384x16384 exceeds"));
}
