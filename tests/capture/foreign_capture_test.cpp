// Foreign captures as a studio's pipeline meets them (issue 26): a Blender render with or
// without the Diffuse Color pass, the camera of the frame before the first in camera.json, and
// the world rendered as a panorama in Blender's orientation, each read through the shipped
// harness/maps/blender.toml. Expected values are computed here from the sample frames and
// from glint's lat-long convention, independently of the converter.
#include "capture/blender_capture.h"
#include "capture/capture_test_support.h"

#include <capture/capture_error.h>
#include <capture/channel_map.h>
#include <capture/environment_io.h>
#include <capture/sample_frame.h>

#include <Imath/half.h>
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>

using namespace glint::capture;
namespace fs = std::filesystem;

namespace {
constexpr std::uint32_t kWidth = test::kForeignWidth, kHeight = test::kForeignHeight;
constexpr std::size_t kPixels = std::size_t{kWidth} * kHeight;

std::string blenderMapPath() {
    return std::string(GLINT_SOURCE_DIR) + "/harness/maps/blender.toml";
}

std::string readText(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeText(const fs::path& file, const std::string& text) {
    std::ofstream(file, std::ios::binary) << text;
}

// The shipped map with one piece of text replaced, written into dir.
fs::path editedBlenderMap(const fs::path& dir, const std::string& from, const std::string& to) {
    std::string text = readText(blenderMapPath());
    const std::size_t at = text.find(from);
    REQUIRE(at != std::string::npos);
    text.replace(at, from.size(), to);
    const fs::path file = dir / "edited.toml";
    writeText(file, text);
    return file;
}

// The glint projection with reversed depth (docs/conventions.md §2): d = n (f - z) / (z (f - n)).
Mat4 reversedProjection(const Camera& c) {
    Mat4 p = c.projection;
    const double n = c.nearZ, f = c.farZ;
    p.m[10] = n / (f - n);
    p.m[11] = f * n / (f - n);
    return p;
}

double maxDifference(const Mat4& a, const Mat4& b) {
    double worst = 0.0;
    for (std::size_t i = 0; i < 16; ++i) worst = std::max(worst, std::abs(a.m[i] - b.m[i]));
    return worst;
}

// A camera that differs from the sample's first: moved and turned a little.
Camera earlierCamera() {
    Camera c = sampleCamera(kWidth, kHeight, 0);
    const double angle = 0.05;
    Mat4 turn = identity();
    turn.m[0] = std::cos(angle);
    turn.m[2] = std::sin(angle);
    turn.m[8] = -std::sin(angle);
    turn.m[10] = std::cos(angle);
    turn.m[3] = 0.2;
    turn.m[11] = -0.1;
    c.view = multiply(turn, c.view);
    return c;
}

nlohmann::json previousEntry(const Camera& c) {
    return {{"view", test::jsonRows(test::blenderView(c.view))},
            {"projection_gl", test::jsonRows(test::openGlProjection(c))},
            {"near", c.nearZ},
            {"far", c.farZ}};
}
} // namespace

TEST_CASE("a Blender render without the Diffuse Color pass replays through the shipped map, without "
          "a material layer",
          "[capture][channel_map][foreign]") {
    const fs::path dir = test::freshTestDir("foreign_no_diffcol");
    test::writeBlenderCapture(dir);
    const ChannelMap map = loadChannelMap(blenderMapPath());
    CHECK(map.materialOptional);
    CHECK(map.baseColor ==
          std::vector<std::string>{"ViewLayer.DiffCol.R", "ViewLayer.DiffCol.G", "ViewLayer.DiffCol.B"});
    const Frame frame = readMappedFrame((dir / "0002.exr").string(), map, 1);
    CHECK(findLayer(frame, "material") == nullptr);
    CHECK(findLayer(frame, "color") != nullptr);
    CHECK(findLayer(frame, "roughness") != nullptr);
}

TEST_CASE("a render folder without the optional world.exr lists its frames",
          "[capture][channel_map][foreign]") {
    // Only frames: the last entry listed is a frame, compared with the absent environment file.
    const fs::path dir = test::freshTestDir("foreign_listing");
    test::writeBlenderFrame(dir, "0001.exr", 0);
    test::writeBlenderFrame(dir, "0002.exr", 1);
    const std::vector<std::string> files =
        mappedSequenceFiles(dir.string(), loadChannelMap(blenderMapPath()));
    REQUIRE(files.size() == 2);
    CHECK(fs::path(files[0]).filename() == "0001.exr");
    CHECK(fs::path(files[1]).filename() == "0002.exr");
}

TEST_CASE("Cycles' Diffuse Color pass becomes the material layer's base colour",
          "[capture][channel_map][foreign]") {
    const fs::path dir = test::freshTestDir("foreign_diffcol");
    test::writeBlenderCapture(dir, {.roughness = true, .diffuseColor = true});
    const Frame frame = readMappedFrame((dir / "0001.exr").string(), loadChannelMap(blenderMapPath()), 0);
    const Layer* material = findLayer(frame, "material");
    REQUIRE(material != nullptr);
    CHECK(material->channels == std::vector<std::string>{"R", "G", "B"});
    CHECK(material->storage == SampleType::Half); // as Blender stored it
    std::size_t bad = 0;
    for (std::size_t i = 0; i < kPixels; ++i)
        for (std::size_t c = 0; c < 3; ++c)
            bad += material->pixels[i * 3 + c] == static_cast<float>(Imath::half(test::diffuseColorAt(i)[c]))
                       ? 0u
                       : 1u;
    CHECK(bad == 0);
}

TEST_CASE("a [material] section that is not optional still fails on a file without its channels",
          "[capture][channel_map][foreign]") {
    const fs::path dir = test::freshTestDir("foreign_material_required");
    test::writeBlenderCapture(dir);
    const fs::path mapFile = editedBlenderMap(dir, "optional = true  # only composite", "optional = false #");
    const std::string message = test::captureErrorOf(
        [&] { readMappedFrame((dir / "0001.exr").string(), loadChannelMap(mapFile.string()), 0); });
    CHECK(test::isOneLine(message));
    CHECK(message.find("0001.exr") != std::string::npos);
    CHECK(message.find("'ViewLayer.DiffCol.R'") != std::string::npos);
    CHECK(message.find("material.base_color") != std::string::npos);
}

TEST_CASE("camera.json's previous camera gives the first frame its camera motion",
          "[capture][channel_map][foreign]") {
    const fs::path dir = test::freshTestDir("foreign_previous_camera");
    test::writeBlenderCapture(dir);
    const ChannelMap map = loadChannelMap(blenderMapPath());
    const Camera c0 = sampleCamera(kWidth, kHeight, 0);
    const Mat4 ownViewProjection = multiply(reversedProjection(c0), c0.view);

    SECTION("without it the first frame has none") {
        const Frame first = readMappedFrame((dir / "0001.exr").string(), map, 0);
        CHECK(maxDifference(first.camera.prevViewProjection, ownViewProjection) < 1e-9);
    }
    SECTION("with it, the previous view-projection is the given camera's, in glint's world") {
        const Camera before = earlierCamera();
        nlohmann::json cameras = test::blenderCameras();
        cameras["previous"] = previousEntry(before);
        writeText(dir / "camera.json", cameras.dump(1));
        const Frame first = readMappedFrame((dir / "0001.exr").string(), map, 0);
        const Mat4 expected = multiply(reversedProjection(before), before.view);
        CHECK(maxDifference(first.camera.prevViewProjection, expected) < 1e-9);
        CHECK(maxDifference(first.camera.prevViewProjection, ownViewProjection) > 1e-3);
        // The second frame still takes the first entry as its previous camera.
        const Frame second = readMappedFrame((dir / "0002.exr").string(), map, 1);
        CHECK(maxDifference(second.camera.prevViewProjection, ownViewProjection) < 1e-9);
    }
    SECTION("a single static entry: only the folder's first frame moves from it") {
        nlohmann::json cameras = test::blenderCameras();
        nlohmann::json only = cameras["frames"][0];
        only.erase("file");
        cameras["frames"] = nlohmann::json::array({only});
        cameras["previous"] = previousEntry(earlierCamera());
        writeText(dir / "camera.json", cameras.dump(1));
        const Frame first = readMappedFrame((dir / "0001.exr").string(), map, 0);
        const Frame second = readMappedFrame((dir / "0002.exr").string(), map, 1);
        CHECK(maxDifference(first.camera.prevViewProjection, ownViewProjection) > 1e-3);
        CHECK(maxDifference(second.camera.prevViewProjection, ownViewProjection) < 1e-9);
    }
    SECTION("previous names no file") {
        nlohmann::json cameras = test::blenderCameras();
        cameras["previous"] = previousEntry(earlierCamera());
        cameras["previous"]["file"] = "0000.exr";
        writeText(dir / "camera.json", cameras.dump(1));
        const std::string message =
            test::captureErrorOf([&] { readMappedFrame((dir / "0001.exr").string(), map, 0); });
        CHECK(test::isOneLine(message));
        CHECK(message.find("camera.json: previous.file") != std::string::npos);
    }
}

TEST_CASE("a world panorama in Blender's orientation loads through the shipped map in glint's",
          "[capture][channel_map][foreign][environment]") {
    const fs::path dir = test::freshTestDir("foreign_world");
    test::writeBlenderCapture(dir);
    constexpr std::uint32_t kEnvWidth = 32, kEnvHeight = 16;
    test::writeBlenderWorld(dir / "world.exr", kEnvWidth, kEnvHeight);
    const ChannelMap map = loadChannelMap(blenderMapPath());
    // world.exr sits among the frames but is not one.
    CHECK(mappedSequenceFiles(dir.string(), map).size() == 2);
    const std::optional<Environment> env = loadMappedEnvironment(map, dir.string());
    REQUIRE(env.has_value());
    CHECK(env->layout == EnvironmentLayout::LatLong);
    REQUIRE(env->width == kEnvWidth);
    REQUIRE(env->height == kEnvHeight);
    // glint's lat-long (OpenEXR's, sssr_environment.hlsli): the texel centre's direction, then
    // the Blender direction it is, whose value the panorama holds.
    double worst = 0.0;
    for (std::uint32_t y = 0; y < kEnvHeight; ++y)
        for (std::uint32_t x = 0; x < kEnvWidth; ++x) {
            const double longitude = 2.0 * std::numbers::pi * (0.5 - (x + 0.5) / kEnvWidth);
            const double latitude = std::numbers::pi * (0.5 - (y + 0.5) / kEnvHeight);
            const std::array<float, 3> expected =
                test::worldValue(test::toBlender(std::sin(longitude) * std::cos(latitude), std::sin(latitude),
                                                 std::cos(longitude) * std::cos(latitude)));
            for (std::size_t c = 0; c < 3; ++c)
                worst =
                    std::max(worst, std::abs(static_cast<double>(
                                        env->rgb[(std::size_t{y} * kEnvWidth + x) * 3 + c] - expected[c])));
        }
    CHECK(worst < 1e-5);

    SECTION("without world.exr the optional environment is none") {
        fs::remove(dir / "world.exr");
        CHECK_FALSE(loadMappedEnvironment(map, dir.string()).has_value());
    }
    SECTION("a width that a quarter turn does not divide is an error naming the file") {
        test::writeBlenderWorld(dir / "world.exr", 30, 15);
        const std::string message = test::captureErrorOf([&] { loadMappedEnvironment(map, dir.string()); });
        CHECK(test::isOneLine(message));
        CHECK(message.find("world.exr") != std::string::npos);
        CHECK(message.find("divisible by 4") != std::string::npos);
    }
}

TEST_CASE("a map's environment: a missing file, the glint form and a centre that is not horizontal",
          "[capture][channel_map][foreign][environment]") {
    const fs::path dir = test::freshTestDir("foreign_environment_errors");
    test::writeBlenderCapture(dir);

    SECTION("a named file that is not there is one line naming it") {
        const fs::path mapFile =
            editedBlenderMap(dir, "optional = true  # no world.exr", "optional = false #");
        const ChannelMap map = loadChannelMap(mapFile.string());
        const std::string message = test::captureErrorOf([&] { loadMappedEnvironment(map, dir.string()); });
        CHECK(test::isOneLine(message));
        CHECK(message.find((dir / "world.exr").string()) != std::string::npos);
        CHECK(message.find("does not exist") != std::string::npos);
    }
    SECTION("environment = \"file\": a glint environment map, used as it is") {
        const Environment sky = makeSampleEnvironment(16, 8);
        writeEnvironment(dir / "sky.exr", sky);
        writeText(dir / "map.toml",
                  "version = 1\neffects = [\"depth_pyramid\"]\nenvironment = \"sky.exr\"\n"
                  "[world]\naxes = [\"x\", \"z\", \"-y\"]\n"
                  "[depth]\nchannel = \"ViewLayer.Depth.Z\"\nkind = \"view_z\"\n[camera]\n");
        const std::optional<Environment> env =
            loadMappedEnvironment(loadChannelMap((dir / "map.toml").string()), (dir / "0001.exr").string());
        REQUIRE(env.has_value());
        CHECK(env->rgb == sky.rgb);
    }
    SECTION("a centre along the up axis is a map error naming the key") {
        const fs::path mapFile = editedBlenderMap(dir, "center = \"x\"", "center = \"-z\"");
        const std::string message = test::captureErrorOf([&] { loadChannelMap(mapFile.string()); });
        CHECK(test::isOneLine(message));
        CHECK(message.find("edited.toml") != std::string::npos);
        CHECK(message.find("environment.center") != std::string::npos);
    }
}
