#include "capture/capture_test_support.h"

#include <capture/frame_io.h>

#include <Imath/half.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfTiledOutputFile.h>
#include <catch2/catch.hpp>

#include <bit>
#include <cstdint>
#include <limits>

using namespace glint::capture;

namespace {
// Bit patterns, so that -0.0 vs 0.0 and any NaN payload count as differences.
std::uint32_t bits(float v) {
    return std::bit_cast<std::uint32_t>(v);
}
std::uint64_t bits(double v) {
    return std::bit_cast<std::uint64_t>(v);
}

bool sameBits(const Mat4& a, const Mat4& b) {
    for (std::size_t i = 0; i < 16; ++i)
        if (bits(a.m[i]) != bits(b.m[i])) return false;
    return true;
}

Frame writeAndRead(const std::string& testName, const Frame& frame) {
    const auto file = test::freshTestDir(testName) / "frame.exr";
    writeFrame(file, frame);
    return readFrame(file);
}
} // namespace

TEST_CASE("FLOAT layers read back bit-exact and HALF layers equal the independently rounded half",
          "[capture]") {
    const Frame written = test::makeFullFrame(13, 7);
    const Frame read = writeAndRead("round_trip_samples", written);
    REQUIRE(read.layers.size() == written.layers.size());
    for (const Layer& w : written.layers) {
        INFO("layer " << w.name);
        const Layer* r = findLayer(read, w.name);
        REQUIRE(r != nullptr);
        REQUIRE(r->channels == w.channels);
        REQUIRE(r->storage == w.storage);
        REQUIRE(r->pixels.size() == w.pixels.size());
        std::size_t mismatches = 0;
        for (std::size_t i = 0; i < w.pixels.size(); ++i) {
            const float expected =
                w.storage == SampleType::Half ? static_cast<float>(Imath::half(w.pixels[i])) : w.pixels[i];
            if (bits(r->pixels[i]) != bits(expected)) ++mismatches;
        }
        CHECK(mismatches == 0);
        CHECK(r->nonFinite == 0);
    }
}

TEST_CASE("HALF storage really rounds: the test data is not representable in half", "[capture]") {
    const Frame frame = test::makeFullFrame(13, 7);
    const Layer* color = findLayer(frame, "color");
    REQUIRE(color != nullptr);
    std::size_t changedByHalf = 0;
    for (float v : color->pixels)
        if (static_cast<float>(Imath::half(v)) != v) ++changedByHalf;
    CHECK(changedByHalf > color->pixels.size() / 2);
}

TEST_CASE("camera matrices and every header attribute read back bit-exact", "[capture]") {
    const Frame written = test::makeFullFrame(5, 3);
    const Frame read = writeAndRead("round_trip_attributes", written);
    CHECK(read.width == 5);
    CHECK(read.height == 3);
    CHECK(read.formatVersion == 1);
    CHECK(read.frameIndex == written.frameIndex);
    CHECK(sameBits(read.camera.view, written.camera.view));
    CHECK(sameBits(read.camera.projection, written.camera.projection));
    CHECK(sameBits(read.camera.prevViewProjection, written.camera.prevViewProjection));
    CHECK(read.camera.depth == written.camera.depth);
    CHECK(bits(read.camera.nearZ) == bits(written.camera.nearZ));
    CHECK(bits(read.camera.farZ) == bits(written.camera.farZ));
    CHECK(read.camera.ndcYDown == written.camera.ndcYDown);
    CHECK(read.normalEncoding == written.normalEncoding);
    CHECK(read.motion.units == MotionUnits::Uv);
    CHECK(read.motion.scale.x == 1.0f);
    CHECK(read.motion.scale.y == 1.0f);
    CHECK(read.roughness.layer == "material");
    CHECK(read.roughness.channel == "G");
    CHECK(read.roughness.perceptual == false);
    CHECK(read.effects == written.effects);
}

// glint.shadowLightTanHalfAngle is optional: written only when known (>= 0; 0 is a light of size
// 0), read back bit-exact, and negative (unknown) when absent (docs/capture-format.md).
TEST_CASE("the optional shadow light angle reads back bit-exact, and as unknown when absent", "[capture]") {
    Frame written = test::makeFullFrame(5, 3);
    written.shadowLightTanHalfAngle = -1.0;
    CHECK(writeAndRead("round_trip_no_light_angle", written).shadowLightTanHalfAngle < 0.0);
    written.shadowLightTanHalfAngle = 0.0; // a light of angular radius 0
    CHECK(writeAndRead("round_trip_point_light_angle", written).shadowLightTanHalfAngle == 0.0);
    written.shadowLightTanHalfAngle = 0.017455064928217585; // tan(1 degree)
    const Frame read = writeAndRead("round_trip_light_angle", written);
    CHECK(bits(read.shadowLightTanHalfAngle) == bits(written.shadowLightTanHalfAngle));
}

TEST_CASE("every enumeration value survives the file attributes", "[capture]") {
    for (DepthConvention depth :
         {DepthConvention::Standard, DepthConvention::Reversed, DepthConvention::ReversedInfinite}) {
        for (NormalEncoding normal :
             {NormalEncoding::WorldUnit, NormalEncoding::WorldUnorm, NormalEncoding::Octahedral}) {
            Frame f = test::makeDepthOnlyFrame(2, 2);
            f.camera.depth = depth;
            f.camera.farZ =
                depth == DepthConvention::ReversedInfinite ? std::numeric_limits<double>::infinity() : 50.0;
            f.normalEncoding = normal;
            f.motion = {MotionUnits::Ndc, {-1.0f, 0.5f}};
            const auto file = test::freshTestDir("round_trip_enums") / "frame.exr";
            writeFrame(file, f);
            const FrameHeader h = readFrameHeader(file);
            CHECK(h.camera.depth == depth);
            CHECK(h.camera.farZ == f.camera.farZ);
            CHECK(h.normalEncoding == normal);
            CHECK(h.motion.units == MotionUnits::Ndc);
            CHECK(h.motion.scale.x == -1.0f);
            CHECK(h.motion.scale.y == 0.5f);
        }
    }
}

TEST_CASE("layers read back in canonical order: known layers, other layers, then references", "[capture]") {
    Frame f = test::makeFullFrame(3, 2);
    f.layers.push_back({"albedo", {"R", "G", "B"}, std::vector<float>(3 * 2 * 3, 0.5f), 0, SampleType::Half});
    const Frame read = writeAndRead("round_trip_layer_order", f);
    std::vector<std::string> names;
    for (const Layer& layer : read.layers) names.push_back(layer.name);
    CHECK(names == std::vector<std::string>{"color", "depth", "normal", "roughness", "material", "motion",
                                            "shadow", "albedo", "reference.reflection", "reference.shadow"});
}

TEST_CASE("the header-only read reports layers, storage and the declared conventions", "[capture]") {
    const Frame written = test::makeFullFrame(6, 4);
    const auto file = test::freshTestDir("round_trip_header_only") / "frame.exr";
    writeFrame(file, written);
    const FrameHeader h = readFrameHeader(file);
    CHECK(h.width == 6);
    CHECK(h.height == 4);
    REQUIRE(h.layers.size() == written.layers.size());
    const LayerInfo* color = findLayer(h, "color");
    REQUIRE(color != nullptr);
    CHECK(color->channels == std::vector<std::string>{"R", "G", "B", "A"}); // canonical, not alphabetical
    CHECK(color->storage == SampleType::Half);
    const LayerInfo* reference = findLayer(h, "reference.reflection");
    REQUIRE(reference != nullptr);
    CHECK(reference->channels == std::vector<std::string>{"R", "G", "B"});
    CHECK(findLayer(h, "depth")->storage == SampleType::Float);
}

TEST_CASE("a tiled file with ZIP or PIZ compression reads like the scanline file it was made from",
          "[capture]") {
    const auto dir = test::freshTestDir("round_trip_tiled");
    const Frame written = test::makeDepthOnlyFrame(37, 21); // FLOAT only: one slice type
    writeFrame(dir / "scanline.exr", written);
    for (Imf::Compression compression : {Imf::ZIP_COMPRESSION, Imf::PIZ_COMPRESSION}) {
        Imf::Header header = test::exrHeaderOf(dir / "scanline.exr");
        header.compression() = compression;
        header.setTileDescription(Imf::TileDescription(16, 8, Imf::ONE_LEVEL));
        {
            Imf::TiledOutputFile out((dir / "tiled.exr").c_str(), header);
            const Layer& depth = *findLayer(written, "depth");
            Imf::FrameBuffer buffer;
            buffer.insert("depth.Z",
                          Imf::Slice(Imf::FLOAT,
                                     reinterpret_cast<char*>(const_cast<float*>(depth.pixels.data())),
                                     sizeof(float), sizeof(float) * written.width));
            out.setFrameBuffer(buffer);
            out.writeTiles(0, out.numXTiles() - 1, 0, out.numYTiles() - 1);
        }
        const Frame read = readFrame(dir / "tiled.exr");
        CHECK(findLayer(read, "depth")->pixels == findLayer(written, "depth")->pixels);
    }
}
