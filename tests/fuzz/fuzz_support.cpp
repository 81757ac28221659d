#include "fuzz_support.h"

#include <capture/sample_frame.h>
#include <capture/sequence_io.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace glint::fuzz {

namespace {
std::filesystem::path makeScratchDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "glint-fuzz-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create a scratch folder in $TMPDIR");
    return pattern;
}

void removeScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(scratchDir(), ignored);
}

std::string matrixJson(const capture::Mat4& m) {
    std::string out = "[";
    for (std::size_t i = 0; i < 16; ++i) {
        char number[40];
        std::snprintf(number, sizeof(number), "%s%.17g", i ? ", " : "", m.m[i]);
        out += number;
    }
    return out + "]";
}

// Blender's world is Z-up: the view over Blender's axes, V_b · p_b = V · p for p = (x, z, -y).
capture::Mat4 blenderView(const capture::Mat4& v) {
    capture::Mat4 b = v;
    for (std::size_t r = 0; r < 4; ++r) {
        b.m[r * 4 + 1] = -v.m[r * 4 + 2];
        b.m[r * 4 + 2] = v.m[r * 4 + 1];
    }
    return b;
}

void writeBlenderFrame(const std::filesystem::path& file, std::uint32_t index) {
    const capture::Frame s = capture::makeSampleFrame(kBlenderWidth, kBlenderHeight, index);
    const std::size_t pixels = std::size_t{kBlenderWidth} * kBlenderHeight;
    struct Source {
        const char* name;
        const char* layer;
        std::size_t channel;
    };
    const std::vector<Source> sources{
        {"ViewLayer.Combined.R", "color", 0},     {"ViewLayer.Combined.G", "color", 1},
        {"ViewLayer.Combined.B", "color", 2},     {"ViewLayer.Combined.A", "color", 0},
        {"ViewLayer.Depth.Z", "depth", 0},        {"ViewLayer.Normal.X", "normal", 0},
        {"ViewLayer.Normal.Y", "normal", 2},      {"ViewLayer.Normal.Z", "normal", 1},
        {"ViewLayer.roughness.X", "material", 1}, {"ViewLayer.Vector.X", "motion", 0},
        {"ViewLayer.Vector.Y", "motion", 1},      {"ViewLayer.Vector.Z", "motion", 0},
        {"ViewLayer.Vector.W", "motion", 1},
    };
    Imf::Header header(static_cast<int>(kBlenderWidth), static_cast<int>(kBlenderHeight));
    header.compression() = Imf::ZIP_COMPRESSION;
    // OpenEXR's camera looks down +z: worldToCamera = diag(1,1,-1,1)·V, stored transposed.
    Imath::M44f worldToCamera;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            worldToCamera[c][r] = static_cast<float>((r == 2 ? -1.0 : 1.0) *
                                                     s.camera.view.m[static_cast<std::size_t>(r * 4 + c)]);
    Imf::addWorldToCamera(header, worldToCamera);
    std::vector<std::vector<float>> planes;
    planes.reserve(sources.size());
    Imf::FrameBuffer buffer;
    for (const Source& src : sources) {
        const capture::Layer* layer = capture::findLayer(s, src.layer);
        std::vector<float>& plane = planes.emplace_back(pixels);
        for (std::size_t i = 0; i < pixels; ++i) {
            float v = layer->pixels[i * layer->channels.size() + src.channel];
            if (std::string_view(src.layer) == "depth") v = v >= 1.0f ? 1e10f : 0.1f / (1.0f - 0.999f * v);
            plane[i] = v;
        }
        header.channels().insert(src.name, Imf::Channel(Imf::FLOAT));
        buffer.insert(src.name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(plane.data()), sizeof(float),
                                           sizeof(float) * kBlenderWidth));
    }
    Imf::OutputFile out(file.c_str(), header);
    out.setFrameBuffer(buffer);
    out.writePixels(static_cast<int>(kBlenderHeight));
}
} // namespace

const std::filesystem::path& scratchDir() {
    static const std::filesystem::path dir = makeScratchDir();
    // Registered once `dir` is constructed, so that it runs before `dir` is destroyed.
    static const bool removedAtExit = std::atexit(removeScratchDir) == 0;
    (void)removedAtExit;
    return dir;
}

void writeBytes(const std::filesystem::path& file, const std::uint8_t* data, std::size_t size) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out) throw std::runtime_error("cannot write " + file.string());
}

void writeText(const std::filesystem::path& file, std::string_view text) {
    writeBytes(file, reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
}

void writeSampleSequence(const std::filesystem::path& dir) {
    const std::vector<capture::Frame> frames{capture::makeSampleFrame(16, 12, 0),
                                             capture::makeSampleFrame(16, 12, 1)};
    const capture::Environment environment = capture::makeSampleEnvironment(16, 8);
    capture::writeSequence(dir, frames, 30.0, &environment);
}

std::string blenderCameraJson() {
    std::string json = "{\"format\": \"glint-camera\", \"version\": 1, \"frames\": [\n";
    for (std::uint32_t i = 0; i < 2; ++i) {
        const capture::Camera c = capture::sampleCamera(kBlenderWidth, kBlenderHeight, i);
        json += std::string(i ? ",\n" : "") + "  {\"file\": \"000" + std::to_string(i + 1) +
                ".exr\", \"view\": " + matrixJson(blenderView(c.view)) +
                ", \"fov_y_degrees\": 50, \"near\": 0.1, \"far\": 100}";
    }
    return json + "\n]}\n";
}

void writeBlenderCapture(const std::filesystem::path& dir) {
    std::filesystem::create_directories(dir);
    writeBlenderFrame(dir / "0001.exr", 0);
    writeBlenderFrame(dir / "0002.exr", 1);
    writeText(dir / "camera.json", blenderCameraJson());
}

std::string blenderMapPath() {
    return std::string(GLINT_SOURCE_DIR) + "/harness/maps/blender.toml";
}

std::string headerCameraMap() {
    return R"(version = 1
effects = ["depth_pyramid"]
[depth]
channel = "ViewLayer.Depth.Z"
kind = "distance"
background_from = 1e9
[motion]
channels = ["ViewLayer.Vector.X", "ViewLayer.Vector.Y"]
units = "pixels"
background = "camera"
[camera]
source = "header"
view_attribute = "worldToCamera"
view_space = "openexr"
fov_y_degrees = 50
near = 0.1
far = 100
)";
}

} // namespace glint::fuzz
