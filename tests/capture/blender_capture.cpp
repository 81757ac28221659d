#include "capture/blender_capture.h"

#include <capture/sample_frame.h>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <stdexcept>

namespace glint::capture::test {

namespace {
constexpr std::size_t kPixels = std::size_t{kForeignWidth} * kForeignHeight;
} // namespace

void writeForeignExr(const std::filesystem::path& file, std::vector<ExrChannel> channels, std::uint32_t width,
                     std::uint32_t height) {
    Imf::Header header(static_cast<int>(width), static_cast<int>(height));
    header.compression() = Imf::ZIP_COMPRESSION;
    Imf::FrameBuffer buffer;
    std::vector<std::vector<Imath::half>> halves;
    halves.reserve(channels.size());
    for (ExrChannel& c : channels) {
        header.channels().insert(c.name, Imf::Channel(c.half ? Imf::HALF : Imf::FLOAT));
        if (c.half) {
            halves.emplace_back(c.samples.begin(), c.samples.end());
            buffer.insert(c.name, Imf::Slice(Imf::HALF, reinterpret_cast<char*>(halves.back().data()),
                                             sizeof(Imath::half), sizeof(Imath::half) * width));
        } else {
            buffer.insert(c.name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(c.samples.data()),
                                             sizeof(float), sizeof(float) * width));
        }
    }
    Imf::OutputFile out(file.c_str(), header);
    out.setFrameBuffer(buffer);
    out.writePixels(static_cast<int>(height));
}

const std::vector<float>& layerSamples(const Frame& frame, const char* layer) {
    const Layer* l = findLayer(frame, layer);
    if (!l) throw std::runtime_error(std::string("the frame has no layer '") + layer + "'");
    return l->pixels;
}

bool isSky(const Frame& sample, std::size_t pixel) {
    return layerSamples(sample, "depth")[pixel] >= 1.0f;
}

std::array<double, 3> toBlender(double x, double y, double z) {
    return {x, -z, y};
}

Mat4 blenderView(const Mat4& v) {
    Mat4 b = v;
    for (std::size_t r = 0; r < 4; ++r) {
        b.m[r * 4 + 1] = -v.m[r * 4 + 2];
        b.m[r * 4 + 2] = v.m[r * 4 + 1];
    }
    return b;
}

// Depth row mapping [-near, -far] to NDC z in [-1, 1].
Mat4 openGlProjection(const Camera& c) {
    Mat4 p = c.projection;
    const double n = c.nearZ, f = c.farZ;
    p.m[10] = -(f + n) / (f - n);
    p.m[11] = -2.0 * f * n / (f - n);
    return p;
}

double viewDepth(double d, double n, double f) {
    return n * f / (f - d * (f - n));
}

nlohmann::json jsonRows(const Mat4& m) {
    nlohmann::json out = nlohmann::json::array();
    for (std::size_t r = 0; r < 4; ++r)
        out.push_back({m.m[r * 4], m.m[r * 4 + 1], m.m[r * 4 + 2], m.m[r * 4 + 3]});
    return out;
}

std::array<float, 3> diffuseColorAt(std::size_t pixel) {
    const float x = static_cast<float>(pixel % kForeignWidth) / kForeignWidth;
    const float y = static_cast<float>(pixel / kForeignWidth) / kForeignHeight;
    return {x, y, 0.25f + 0.5f * x * y};
}

void writeBlenderFrame(const std::filesystem::path& dir, const std::string& name, std::uint32_t index,
                       BlenderPasses passes) {
    const Frame s = makeSampleFrame(kForeignWidth, kForeignHeight, index);
    const std::vector<float>& color = layerSamples(s, "color");
    const std::vector<float>& depth = layerSamples(s, "depth");
    const std::vector<float>& normal = layerSamples(s, "normal");
    const std::vector<float>& material = layerSamples(s, "material");
    const std::vector<float>& motion = layerSamples(s, "motion");
    std::vector<ExrChannel> ch;
    for (const char* c : {"R", "G", "B", "A"}) ch.push_back({std::string("ViewLayer.Combined.") + c, {}});
    for (const char* c : {"X", "Y", "Z"}) ch.push_back({std::string("ViewLayer.Normal.") + c, {}});
    for (const char* c : {"X", "Y", "Z", "W"}) ch.push_back({std::string("ViewLayer.Vector.") + c, {}});
    ch.push_back({"ViewLayer.Depth.Z", {}});
    for (std::size_t i = 0; i < kPixels; ++i) {
        const bool sky = isSky(s, i);
        for (std::size_t c = 0; c < 3; ++c) ch[c].samples.push_back(color[i * 3 + c]);
        ch[3].samples.push_back(1.0f);
        // Cycles writes zero normals and zero motion where nothing was hit, and depth 1e10.
        const std::array<double, 3> n = sky ? std::array<double, 3>{0.0, 0.0, 0.0}
                                            : toBlender(normal[i * 3], normal[i * 3 + 1], normal[i * 3 + 2]);
        for (std::size_t c = 0; c < 3; ++c) ch[4 + c].samples.push_back(static_cast<float>(n[c]));
        // Vector.xy: pixels towards the previous frame, +y up; .zw (towards the next frame)
        // must be ignored, so it holds junk.
        ch[7].samples.push_back(sky ? 0.0f : motion[i * 2] * static_cast<float>(kForeignWidth));
        ch[8].samples.push_back(sky ? 0.0f : -motion[i * 2 + 1] * static_cast<float>(kForeignHeight));
        ch[9].samples.push_back(123.0f);
        ch[10].samples.push_back(-45.0f);
        ch[11].samples.push_back(
            sky ? 1e10f : static_cast<float>(viewDepth(depth[i], s.camera.nearZ, s.camera.farZ)));
    }
    if (passes.roughness) {
        ch.push_back({"ViewLayer.roughness.X", {}, true});
        for (std::size_t i = 0; i < kPixels; ++i) ch.back().samples.push_back(material[i * 2 + 1]);
    }
    if (passes.diffuseColor) {
        // Blender stores colour passes in HALF when the output's colour depth is Half.
        for (std::size_t c = 0; c < 3; ++c) {
            ch.push_back({std::string("ViewLayer.DiffCol.") + "RGB" [c], {}, true});
            for (std::size_t i = 0; i < kPixels; ++i) ch.back().samples.push_back(diffuseColorAt(i)[c]);
        }
    }
    writeForeignExr(dir / name, std::move(ch));
}

nlohmann::json blenderCameras() {
    const Camera c0 = sampleCamera(kForeignWidth, kForeignHeight, 0);
    const Camera c1 = sampleCamera(kForeignWidth, kForeignHeight, 1);
    nlohmann::json frames = nlohmann::json::array();
    frames.push_back({{"file", "0001.exr"},
                      {"view", jsonRows(blenderView(c0.view))},
                      {"fov_y_degrees", 50.0},
                      {"near", c0.nearZ},
                      {"far", c0.farZ}});
    frames.push_back({{"file", "0002.exr"},
                      {"view", jsonRows(blenderView(c1.view))},
                      {"projection_gl", jsonRows(openGlProjection(c1))},
                      {"near", c1.nearZ},
                      {"far", c1.farZ}});
    return {{"format", "glint-camera"}, {"version", 1}, {"frames", frames}};
}

void writeBlenderCapture(const std::filesystem::path& dir, BlenderPasses passes) {
    std::filesystem::create_directories(dir);
    writeBlenderFrame(dir, "0001.exr", 0, passes);
    writeBlenderFrame(dir, "0002.exr", 1, passes);
    std::ofstream(dir / "camera.json", std::ios::binary) << blenderCameras().dump(1);
}

std::array<float, 3> worldValue(const std::array<double, 3>& d) {
    return {static_cast<float>(0.5 + 0.5 * d[0]), static_cast<float>(0.5 + 0.5 * d[1]),
            static_cast<float>(0.5 + 0.5 * d[2])};
}

void writeBlenderWorld(const std::filesystem::path& file, std::uint32_t width, std::uint32_t height) {
    std::vector<ExrChannel> ch{{"R", {}}, {"G", {}}, {"B", {}}, {"A", {}}};
    for (std::uint32_t row = 0; row < height; ++row) {
        for (std::uint32_t col = 0; col < width; ++col) {
            // Cycles' equirectangular_range_to_direction with the full range: u = 0 on the
            // left, v = 0 on the bottom row (Blender's images are stored bottom-up; the file's
            // first row is the top one), phi = pi - 2 pi u, polar angle theta = pi - pi v.
            const double u = (col + 0.5) / width;
            const double v = 1.0 - (row + 0.5) / height;
            const double phi = std::numbers::pi - 2.0 * std::numbers::pi * u;
            const double theta = std::numbers::pi - std::numbers::pi * v;
            const std::array<float, 3> value = worldValue(
                {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)});
            for (std::size_t c = 0; c < 3; ++c) ch[c].samples.push_back(value[c]);
            ch[3].samples.push_back(1.0f);
        }
    }
    writeForeignExr(file, std::move(ch), width, height);
}

} // namespace glint::capture::test
