// Foreign captures through channel maps: glint's analytic sample frames are written the way
// another tool would write them (Blender's layer names and conventions; a RenderDoc-style
// folder of textures), read back through a map, and compared with the original G-buffer.
// Every expected value is computed here from the sample frame, independently of the
// converter.
#include "capture/blender_capture.h"
#include "capture/capture_test_support.h"

#include <capture/capture_error.h>
#include <capture/channel_map.h>
#include <capture/frame_io.h>
#include <capture/sample_frame.h>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <limits>

using namespace glint::capture;
namespace fs = std::filesystem;

namespace {
constexpr std::uint32_t kWidth = test::kForeignWidth, kHeight = test::kForeignHeight;
constexpr std::size_t kPixels = std::size_t{kWidth} * kHeight;

using test::blenderCameras;
using test::blenderView;
using test::ExrChannel;
using test::isSky;
using test::openGlProjection;
using test::viewDepth;
using test::writeBlenderFrame;
using test::writeForeignExr;

std::string blenderMapPath() {
    return std::string(GLINT_SOURCE_DIR) + "/harness/maps/blender.toml";
}

void writeText(const fs::path& file, const std::string& text) {
    std::ofstream(file, std::ios::binary) << text;
}

std::string readText(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

nlohmann::json rows(const Mat4& m) {
    return test::jsonRows(m);
}

const std::vector<float>& samples(const Frame& f, const char* layer) {
    REQUIRE(findLayer(f, layer) != nullptr);
    return test::layerSamples(f, layer);
}

// The glint projection with reversed depth (docs/conventions.md §2): d = n (f - z) / (z (f - n)).
Mat4 reversedProjection(const Camera& c) {
    Mat4 p = c.projection;
    const double n = c.nearZ, f = c.farZ;
    p.m[10] = n / (f - n);
    p.m[11] = f * n / (f - n);
    return p;
}

fs::path writeBlenderCapture(const std::string& testName) {
    const fs::path dir = test::freshTestDir(testName);
    test::writeBlenderCapture(dir);
    return dir;
}

double maxDifference(const Mat4& a, const Mat4& b) {
    double worst = 0.0;
    for (std::size_t i = 0; i < 16; ++i) worst = std::max(worst, std::abs(a.m[i] - b.m[i]));
    return worst;
}

// Motion error in pixels, worst component over all pixels.
double motionErrorPixels(const Frame& read, const Frame& sample) {
    const std::vector<float>& r = samples(read, "motion");
    const std::vector<float>& s = samples(sample, "motion");
    double worst = 0.0;
    for (std::size_t i = 0; i < kPixels; ++i) {
        worst = std::max(worst, std::abs(static_cast<double>(r[2 * i] - s[2 * i])) * kWidth);
        worst = std::max(worst, std::abs(static_cast<double>(r[2 * i + 1] - s[2 * i + 1])) * kHeight);
    }
    return worst;
}

std::string errorOf(const std::function<void()>& work) {
    try {
        work();
    } catch (const CaptureError& e) {
        return e.what();
    } catch (const std::exception& e) {
        return std::string("OTHER EXCEPTION: ") + e.what();
    }
    return "NO ERROR";
}
} // namespace

TEST_CASE("a Blender-style render read through maps/blender.toml has the G-buffer it was made from",
          "[capture][channel_map]") {
    const fs::path dir = writeBlenderCapture("channel_map_blender");
    const ChannelMap map = loadChannelMap(blenderMapPath());
    const std::vector<std::string> files = mappedSequenceFiles(dir.string(), map);
    REQUIRE(files.size() == 2);
    CHECK(fs::path(files[0]).filename() == "0001.exr");
    CHECK(fs::path(files[1]).filename() == "0002.exr");

    const Frame read = readMappedFrame(files[1], map, 1);
    const Frame sample = makeSampleFrame(kWidth, kHeight, 1);
    REQUIRE(read.width == kWidth);
    REQUIRE(read.height == kHeight);
    CHECK(read.frameIndex == 1);
    CHECK(read.effects == std::vector<std::string>{"reflections"});
    CHECK(read.normalEncoding == NormalEncoding::WorldUnit);
    CHECK(read.motion.units == MotionUnits::Uv);
    CHECK(read.roughness.layer == "roughness");
    CHECK(read.roughness.channel == "Y");
    CHECK(read.roughness.perceptual);

    SECTION("camera: Blender's Z-up view back in glint's world, reversed depth, previous frame's matrices") {
        const Camera& c = read.camera;
        CHECK(c.depth == DepthConvention::Reversed);
        CHECK_FALSE(c.ndcYDown);
        CHECK(c.nearZ == sample.camera.nearZ);
        CHECK(c.farZ == sample.camera.farZ);
        CHECK(maxDifference(c.view, sample.camera.view) < 1e-12);
        CHECK(maxDifference(c.projection, reversedProjection(sample.camera)) < 1e-12);
        const Mat4 previous =
            multiply(reversedProjection(sample.camera), sampleCamera(kWidth, kHeight, 0).view);
        CHECK(maxDifference(c.prevViewProjection, previous) < 1e-9);
    }
    SECTION("depth: within 1e-5 relative of the independently reversed device depth; sky at 0") {
        const std::vector<float>& d = samples(read, "depth");
        const double n = sample.camera.nearZ, f = sample.camera.farZ;
        std::size_t sky = 0, bad = 0;
        for (std::size_t i = 0; i < kPixels; ++i) {
            if (isSky(sample, i)) {
                ++sky;
                bad += d[i] == 0.0f ? 0u : 1u;
                continue;
            }
            const double z = viewDepth(samples(sample, "depth")[i], n, f);
            const double expected = n * (f - z) / (z * (f - n));
            bad += std::abs(static_cast<double>(d[i]) - expected) <= 1e-5 * expected ? 0u : 1u;
        }
        CHECK(sky > 0);
        CHECK(sky < kPixels);
        CHECK(bad == 0);
    }
    SECTION("normals: unit world normals within 1e-5 where something was hit") {
        const std::vector<float>& r = samples(read, "normal");
        const std::vector<float>& s = samples(sample, "normal");
        double worst = 0.0;
        for (std::size_t i = 0; i < kPixels * 3; ++i)
            if (!isSky(sample, i / 3)) worst = std::max(worst, std::abs(static_cast<double>(r[i] - s[i])));
        CHECK(worst < 1e-5);
    }
    SECTION("motion: convention A within 1e-4 px, the sky's rebuilt from the camera") {
        CHECK(motionErrorPixels(read, sample) < 1e-4);
    }
    SECTION("roughness and colour: the stored samples unchanged") {
        const std::vector<float>& r = samples(read, "roughness");
        const std::vector<float>& m = samples(sample, "material");
        const std::vector<float>& c = samples(read, "color");
        const std::vector<float>& sc = samples(sample, "color");
        std::size_t bad = 0;
        for (std::size_t i = 0; i < kPixels; ++i) {
            bad += r[i] == static_cast<float>(Imath::half(m[i * 2 + 1])) ? 0u : 1u;
            for (std::size_t k = 0; k < 3; ++k) bad += c[i * 4 + k] == sc[i * 3 + k] ? 0u : 1u;
            bad += c[i * 4 + 3] == 1.0f ? 0u : 1u;
        }
        CHECK(bad == 0);
        CHECK(findLayer(read, "roughness")->storage == SampleType::Half);
        CHECK(findLayer(read, "depth")->storage == SampleType::Float);
    }
}

TEST_CASE("the first mapped frame has no camera motion unless the side file gives one",
          "[capture][channel_map]") {
    const fs::path dir = writeBlenderCapture("channel_map_first_frame");
    const ChannelMap map = loadChannelMap(blenderMapPath());
    const Frame first = readMappedFrame((dir / "0001.exr").string(), map, 0);
    const Camera c0 = sampleCamera(kWidth, kHeight, 0);
    CHECK(maxDifference(first.camera.view, c0.view) < 1e-12);
    // fov_y_degrees builds the projection from the image's aspect ratio.
    CHECK(maxDifference(first.camera.projection, reversedProjection(c0)) < 1e-12);
    CHECK(maxDifference(first.camera.prevViewProjection, multiply(reversedProjection(c0), c0.view)) < 1e-9);
    // A mapped frame is an ordinary capture: glint writes it and reads it back.
    writeFrame(dir / "converted.exr", first);
    const Frame back = readFrame(dir / "converted.exr");
    CHECK(back.layers.size() == first.layers.size());
    CHECK(samples(back, "depth") == samples(first, "depth"));
}

TEST_CASE("a RenderDoc-style folder of textures per frame reads through a map of file:channel names",
          "[capture][channel_map]") {
    // Device depth, view-space octahedral normals, NDC motion as current - previous, alpha
    // roughness, rows stored bottom-up, row-vector matrices in a positional side file.
    const fs::path dir = test::freshTestDir("channel_map_textures");
    writeText(dir / "engine.toml", R"(version = 1
effects = ["reflections"]
flip_vertical = true
[color]
channels = ["color.exr:R", "color.exr:G", "color.exr:B"]
[depth]
channel = "depth.exr:R"
[normal]
channels = ["normal.exr:R", "normal.exr:G"]
space = "view"
encoding = "octahedral"
[roughness]
channel = "material.exr:A"
convention = "alpha"
[motion]
channels = ["motion.exr:R", "motion.exr:G"]
units = "ndc"
direction = "from_previous"
[camera]
depth_convention = "standard"
)");
    nlohmann::json cameras = nlohmann::json::array();
    for (std::uint32_t index = 0; index < 2; ++index) {
        const Frame s = makeSampleFrame(kWidth, kHeight, index);
        const fs::path frame = dir / ("frame_" + std::to_string(index));
        fs::create_directories(frame);
        std::vector<ExrChannel> color{{"R", {}}, {"G", {}}, {"B", {}}}, depth{{"R", {}}},
            normal{{"R", {}}, {"G", {}}}, material{{"A", {}}}, motion{{"R", {}}, {"G", {}}};
        const auto& v = s.camera.view.m;
        for (std::size_t row = 0; row < kHeight; ++row) {
            const std::size_t y = kHeight - 1 - row; // bottom row first
            for (std::size_t x = 0; x < kWidth; ++x) {
                const std::size_t i = y * kWidth + x;
                for (std::size_t c = 0; c < 3; ++c)
                    color[c].samples.push_back(samples(s, "color")[i * 3 + c]);
                depth[0].samples.push_back(samples(s, "depth")[i]);
                const float* f = &samples(s, "normal")[i * 3];
                const double n[3] = {f[0], f[1], f[2]};
                const double nx = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
                const double ny = v[4] * n[0] + v[5] * n[1] + v[6] * n[2];
                const double nz = v[8] * n[0] + v[9] * n[1] + v[10] * n[2];
                // Octahedral encoding, docs/conventions.md §5.
                const double l1 = std::abs(nx) + std::abs(ny) + std::abs(nz);
                double px = nx / l1, py = ny / l1;
                if (nz < 0.0) {
                    const double ox = (1.0 - std::abs(py)) * (px >= 0.0 ? 1.0 : -1.0);
                    py = (1.0 - std::abs(px)) * (py >= 0.0 ? 1.0 : -1.0);
                    px = ox;
                }
                normal[0].samples.push_back(static_cast<float>(0.5 * px + 0.5));
                normal[1].samples.push_back(static_cast<float>(0.5 * py + 0.5));
                const float r = samples(s, "material")[i * 2 + 1];
                material[0].samples.push_back(r * r);
                // NDC (+y up) current - previous = -(2 du, -2 dv).
                motion[0].samples.push_back(-2.0f * samples(s, "motion")[i * 2]);
                motion[1].samples.push_back(2.0f * samples(s, "motion")[i * 2 + 1]);
            }
        }
        writeForeignExr(frame / "color.exr", color);
        writeForeignExr(frame / "depth.exr", depth);
        writeForeignExr(frame / "normal.exr", normal);
        writeForeignExr(frame / "material.exr", material);
        writeForeignExr(frame / "motion.exr", motion);
        cameras.push_back({{"view", rows(transpose(s.camera.view))},
                           {"projection", rows(transpose(s.camera.projection))},
                           {"near", s.camera.nearZ},
                           {"far", s.camera.farZ}});
    }
    writeText(dir / "camera.json", nlohmann::json{{"vectors", "row"}, {"frames", cameras}}.dump());

    const ChannelMap map = loadChannelMap((dir / "engine.toml").string());
    CHECK(map.framesAreFolders);
    const std::vector<std::string> frames = mappedSequenceFiles(dir.string(), map);
    REQUIRE(frames.size() == 2);
    const Frame read = readMappedFrame(frames[1], map, 1);
    const Frame sample = makeSampleFrame(kWidth, kHeight, 1);

    CHECK(read.camera.view == sample.camera.view);
    CHECK(read.camera.projection == sample.camera.projection);
    CHECK(maxDifference(read.camera.prevViewProjection, sample.camera.prevViewProjection) < 1e-12);
    CHECK(samples(read, "depth") == samples(sample, "depth"));
    double worstNormal = 0.0;
    for (std::size_t i = 0; i < kPixels * 3; ++i)
        worstNormal = std::max(worstNormal, std::abs(static_cast<double>(samples(read, "normal")[i] -
                                                                         samples(sample, "normal")[i])));
    CHECK(worstNormal < 1e-5);
    CHECK(motionErrorPixels(read, sample) < 1e-4);
    CHECK_FALSE(read.roughness.perceptual);
    std::size_t bad = 0;
    for (std::size_t i = 0; i < kPixels; ++i) {
        const float r = samples(sample, "material")[i * 2 + 1];
        bad += samples(read, "roughness")[i] == r * r ? 0u : 1u;
    }
    CHECK(bad == 0);
}

TEST_CASE("mapped sequences list frames in natural order without the environment map",
          "[capture][channel_map]") {
    const fs::path dir = test::freshTestDir("channel_map_listing");
    for (const char* name : {"frame_10.exr", "frame_2.exr", "frame_1.EXR", "sky.exr", "notes.txt"})
        writeText(dir / name, "");
    fs::create_directories(dir / "sub.exr.d");
    const fs::path mapFile = dir / "map.toml";
    writeText(mapFile, "version = 1\neffects = [\"depth_pyramid\"]\nenvironment = \"sky.exr\"\n"
                       "[depth]\nchannel = \"Z\"\n[camera]\n");
    const std::vector<std::string> files =
        mappedSequenceFiles(dir.string(), loadChannelMap(mapFile.string()));
    std::vector<std::string> names;
    for (const std::string& f : files) names.push_back(fs::path(f).filename().string());
    CHECK(names == std::vector<std::string>{"frame_1.EXR", "frame_2.exr", "frame_10.exr"});
}

TEST_CASE("channel map errors are one line naming the map, the line and the key", "[capture][channel_map]") {
    const fs::path dir = test::freshTestDir("channel_map_errors");
    const std::string blender = readText(blenderMapPath());
    auto mapError = [&](const std::string& name, const std::string& from, const std::string& to) {
        const std::size_t at = blender.find(from);
        REQUIRE(at != std::string::npos);
        std::string text = blender;
        text.replace(at, from.size(), to);
        writeText(dir / name, text);
        const std::string message = errorOf([&] { loadChannelMap((dir / name).string()); });
        CHECK(test::isOneLine(message));
        CHECK(message.find(name) != std::string::npos);
        return message;
    };
    const std::string unknownTop =
        mapError("unknown_top.toml", "version = 1", "version = 1\ncolour_space = 1");
    CHECK(unknownTop.find("colour_space: unknown key") != std::string::npos);
    const auto line =
        std::count(blender.begin(),
                   blender.begin() + static_cast<std::ptrdiff_t>(blender.find("version = 1")), '\n') +
        2;
    CHECK(unknownTop.find("unknown_top.toml:" + std::to_string(line) + ": ") != std::string::npos);
    CHECK(mapError("unknown_in_section.toml", "kind = \"view_z\"", "knd = \"view_z\"")
              .find("depth.knd: unknown key") != std::string::npos);
    const std::string badValue = mapError("bad_value.toml", "kind = \"view_z\"", "kind = \"linear\"");
    CHECK(badValue.find("depth.kind") != std::string::npos);
    CHECK(badValue.find("'linear'") != std::string::npos);
    CHECK(mapError("missing_field.toml", "channel = \"ViewLayer.Depth.Z\"", "")
              .find("depth.channel: missing") != std::string::npos);
    CHECK(mapError("unknown_section.toml", "[motion]", "[movement]").find("movement: unknown key") !=
          std::string::npos);
    CHECK(mapError("syntax.toml", "[depth]", "[depth").find("syntax") != std::string::npos);
    CHECK(errorOf([&] { loadChannelMap((dir / "absent.toml").string()); }).find("absent.toml") !=
          std::string::npos);
    writeText(dir / "incomplete.toml",
              "version = 1\neffects = [\"reflections\"]\n[depth]\nchannel = \"Z\"\n[camera]\n");
    CHECK(errorOf([&] {
              loadChannelMap((dir / "incomplete.toml").string());
          }).find("effect 'reflections' needs a [color] section") != std::string::npos);
}

TEST_CASE("a channel the map names but the file lacks is a one-line error naming both",
          "[capture][channel_map]") {
    const fs::path dir = writeBlenderCapture("channel_map_missing_channel");
    writeBlenderFrame(dir, "0002.exr", 1, {.roughness = false}); // no roughness AOV
    const ChannelMap map = loadChannelMap(blenderMapPath());
    const std::string message = errorOf([&] { readMappedFrame((dir / "0002.exr").string(), map, 1); });
    CHECK(test::isOneLine(message));
    CHECK(message.find("0002.exr") != std::string::npos);
    CHECK(message.find("'ViewLayer.roughness.X'") != std::string::npos);
    CHECK(message.find("roughness.channel") != std::string::npos);
}

TEST_CASE("a malformed camera side file is a one-line error naming it and the problem",
          "[capture][channel_map]") {
    const fs::path dir = writeBlenderCapture("channel_map_side_file");
    const ChannelMap map = loadChannelMap(blenderMapPath());
    const std::string frame = (dir / "0002.exr").string();
    auto sideError = [&](const std::string& text) {
        writeText(dir / "camera.json", text);
        const std::string message = errorOf([&] { readMappedFrame(frame, map, 1); });
        CHECK(test::isOneLine(message));
        CHECK(message.find("camera.json") != std::string::npos);
        return message;
    };
    CHECK(sideError(R"({"frames": [{"file": )").find("invalid JSON") != std::string::npos);
    CHECK(sideError("{\"frames\": [\n{\"fov\": 1e999}]}") ==
          (dir / "camera.json").string() +
              ": invalid JSON: line 2: the number 1e999 is too large for a double (beyond 1.8e308)");
    nlohmann::json cameras = blenderCameras();
    cameras["frames"][1].erase("view");
    CHECK(sideError(cameras.dump()).find("frames[1].view: missing") != std::string::npos);
    cameras = blenderCameras();
    cameras["frames"][1]["fov"] = 40.0;
    CHECK(sideError(cameras.dump()).find("frames[1].fov: unknown key") != std::string::npos);
    cameras = blenderCameras();
    cameras["frames"][1]["near"] = "close";
    CHECK(sideError(cameras.dump()).find("frames[1].near") != std::string::npos);
    cameras = blenderCameras();
    cameras["frames"][1]["file"] = "9999.exr";
    CHECK(sideError(cameras.dump()).find("no entry for frame '0002.exr'") != std::string::npos);
    CHECK(sideError(cameras.dump()).find("frames = \"...\" in " + blenderMapPath()) != std::string::npos);
    fs::remove(dir / "camera.json");
    const std::string missing = errorOf([&] { readMappedFrame(frame, map, 1); });
    CHECK(missing.find("camera.json: camera side file does not exist") != std::string::npos);
    CHECK(missing.find("docs/replay.md, \"The camera side file\"") != std::string::npos);
}

TEST_CASE("a side-file projection that does not match the entry's near/far, the map's depth convention "
          "or its y direction is a one-line error naming the entry, what was found and what was expected",
          "[capture][channel_map]") {
    // The shipped Blender map: reversed depth, ndc_y_down = false. Frame 0002.exr is entry 1,
    // sample camera 1 (near 0.1, far 100).
    const fs::path dir = writeBlenderCapture("channel_map_projection_check");
    const ChannelMap map = loadChannelMap(blenderMapPath());
    const std::string frame = (dir / "0002.exr").string();
    const Camera c = sampleCamera(kWidth, kHeight, 1);
    auto withEntry = [&](const std::function<void(nlohmann::json&)>& edit) {
        nlohmann::json cameras = blenderCameras();
        edit(cameras["frames"][1]);
        writeText(dir / "camera.json", cameras.dump());
    };
    auto error = [&] {
        const std::string message = errorOf([&] { readMappedFrame(frame, map, 1); });
        CHECK(test::isOneLine(message));
        CHECK(message.find((dir / "camera.json").string() + ": frames[1].") == 0);
        return message;
    };
    // The OpenGL matrix given as glint's projection: near at -1 and far at +1 (exactly, in
    // double) where reversed depth wants 1 and 0.
    withEntry([&](nlohmann::json& e) {
        e["projection"] = e["projection_gl"];
        e.erase("projection_gl");
    });
    std::string message = error();
    CHECK(message.find("frames[1].projection: used as is, it maps near 0.1 to depth -1 and far 100 to 1, "
                       "expected 1 and 0 for camera.depth_convention = \"reversed\" in blender.toml") !=
          std::string::npos);

    // A Vulkan-style matrix (y row negated) as projection_gl.
    Mat4 flipped = openGlProjection(c);
    for (std::size_t i = 4; i < 8; ++i) flipped.m[i] = -flipped.m[i];
    withEntry([&](nlohmann::json& e) { e["projection_gl"] = rows(flipped); });
    message = error();
    CHECK(message.find("frames[1].projection_gl: its y row") != std::string::npos);
    CHECK(message.find("sends view +y down") != std::string::npos);

    // The OpenGL matrix of far 100 declared with far 50: at 50 it gives
    // ((f + n) 50 - 2 f n) / ((f - n) 50) with f = 100, n = 0.1, not +1.
    withEntry([&](nlohmann::json& e) { e["far"] = 50.0; });
    char found[32];
    std::snprintf(found, sizeof found, "%.6g", (100.1 * 50.0 - 20.0) / (99.9 * 50.0));
    message = error();
    CHECK(message.find("frames[1].projection_gl: an OpenGL projection's depth row maps near 0.1 to depth -1 "
                       "and far 50 to " +
                       std::string(found) + ", expected -1 and 1") != std::string::npos);

    // glint's reversed projection passes as is; with its y row negated it sends +y down.
    withEntry([&](nlohmann::json& e) {
        e["projection"] = rows(reversedProjection(c));
        e.erase("projection_gl");
    });
    CHECK(maxDifference(readMappedFrame(frame, map, 1).camera.projection, reversedProjection(c)) < 1e-12);
    Mat4 down = reversedProjection(c);
    for (std::size_t i = 4; i < 8; ++i) down.m[i] = -down.m[i];
    withEntry([&](nlohmann::json& e) {
        e["projection"] = rows(down);
        e.erase("projection_gl");
    });
    message = error();
    CHECK(message.find("frames[1].projection: used as is, it sends view +y down in NDC") !=
          std::string::npos);
    CHECK(message.find("expected up for camera.ndc_y_down = false in blender.toml") != std::string::npos);
}

TEST_CASE("a map's frames pattern or list picks the frames of a folder and reports the other files",
          "[capture][channel_map]") {
    CHECK(matchesFramePattern("0001.exr", "####.exr"));
    CHECK_FALSE(matchesFramePattern("001.exr", "####.exr"));
    CHECK(matchesFramePattern("shot_12.exr", "*#.exr"));
    CHECK_FALSE(matchesFramePattern("calib_depth.exr", "*#.exr"));
    CHECK(matchesFramePattern("a1b.exr", "?#?.exr"));
    CHECK(matchesFramePattern("x.exr", "*"));

    // The shipped Blender map (frames = "*#.exr") on a render folder with a calibration image.
    const fs::path dir = writeBlenderCapture("channel_map_frames");
    writeBlenderFrame(dir, "calib_depth.exr", 0);
    const ChannelMap blender = loadChannelMap(blenderMapPath());
    std::vector<std::string> ignored;
    const std::vector<std::string> frames = mappedSequenceFiles(dir.string(), blender, &ignored);
    REQUIRE(frames.size() == 2);
    CHECK(fs::path(frames[1]).filename() == "0002.exr");
    CHECK(ignored == std::vector<std::string>{"calib_depth.exr"});
    CHECK(readMappedFrame(frames[1], blender, 1).width == kWidth);

    // A list of names, in any order, plays in natural order; a pattern that matches nothing is
    // one line naming the folder, the pattern and the map.
    const std::string text = readText(blenderMapPath());
    const std::size_t at = text.find("frames = \"*#.exr\"");
    REQUIRE(at != std::string::npos);
    auto mapWith = [&](const std::string& line) {
        std::string edited = text;
        edited.replace(at, std::string("frames = \"*#.exr\"").size(), line);
        writeText(dir / "listed.toml", edited);
        return loadChannelMap((dir / "listed.toml").string());
    };
    ignored.clear();
    const std::vector<std::string> listed =
        mappedSequenceFiles(dir.string(), mapWith("frames = [\"0002.exr\", \"0001.exr\"]"), &ignored);
    REQUIRE(listed.size() == 2);
    CHECK(fs::path(listed[0]).filename() == "0001.exr");
    CHECK(ignored == std::vector<std::string>{"calib_depth.exr"});
    const ChannelMap none = mapWith("frames = \"take_*.exr\"");
    const std::string message = errorOf([&] { mappedSequenceFiles(dir.string(), none); });
    CHECK(message == dir.string() + ": holds no frames that match frames = \"take_*.exr\" in " +
                         (dir / "listed.toml").string());
    CHECK(errorOf([&] { mapWith("frames = \"renders/*.exr\""); }).find("frames: 'renders/*.exr' is a path") !=
          std::string::npos);
}

TEST_CASE("a header camera comes from OpenEXR's worldToCamera and the previous file's header",
          "[capture][channel_map]") {
    const fs::path dir = test::freshTestDir("channel_map_header_camera");
    writeText(dir / "map.toml", R"(version = 1
effects = ["depth_pyramid"]
[depth]
channel = "depth.Z"
kind = "view_z"
[camera]
source = "header"
view_attribute = "worldToCamera"
view_space = "openexr"
fov_y_degrees = 50
near = 0.1
far = 100
)");
    for (std::uint32_t index = 0; index < 2; ++index) {
        const Frame s = makeSampleFrame(kWidth, kHeight, index);
        // OpenEXR's camera looks down +z: worldToCamera = diag(1,1,-1,1)·V, stored transposed
        // (row vectors) as float.
        Imath::M44f worldToCamera;
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c)
                worldToCamera[c][r] = static_cast<float>(
                    (r == 2 ? -1.0 : 1.0) * s.camera.view.m[static_cast<std::size_t>(r * 4 + c)]);
        Imf::Header header(static_cast<int>(kWidth), static_cast<int>(kHeight));
        Imf::addWorldToCamera(header, worldToCamera);
        header.channels().insert("depth.Z", Imf::Channel(Imf::FLOAT));
        std::vector<float> z;
        for (std::size_t i = 0; i < kPixels; ++i)
            z.push_back(isSky(s, i) ? std::numeric_limits<float>::infinity()
                                    : static_cast<float>(viewDepth(samples(s, "depth")[i], 0.1, 100.0)));
        Imf::FrameBuffer buffer;
        buffer.insert("depth.Z", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(z.data()), sizeof(float),
                                            sizeof(float) * kWidth));
        Imf::OutputFile out((dir / ("f" + std::to_string(index) + ".exr")).c_str(), header);
        out.setFrameBuffer(buffer);
        out.writePixels(static_cast<int>(kHeight));
    }
    const ChannelMap map = loadChannelMap((dir / "map.toml").string());
    const Frame read = readMappedFrame((dir / "f1.exr").string(), map, 1);
    const Frame sample = makeSampleFrame(kWidth, kHeight, 1);
    // The matrices went through float; depth did not need them.
    CHECK(maxDifference(read.camera.view, sample.camera.view) < 1e-6);
    CHECK(maxDifference(read.camera.projection, sample.camera.projection) < 1e-12);
    CHECK(maxDifference(read.camera.prevViewProjection, sample.camera.prevViewProjection) < 1e-5);
    std::size_t bad = 0;
    for (std::size_t i = 0; i < kPixels; ++i) {
        const double expected = samples(sample, "depth")[i];
        bad +=
            std::abs(static_cast<double>(samples(read, "depth")[i]) - expected) <= 1e-5 * expected ? 0u : 1u;
    }
    CHECK(bad == 0);
}
