#include "capture/capture_test_support.h"

#include <capture/capture_error.h>
#include <capture/frame_io.h>
#include <capture/motion_convention.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStdIO.h>
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>

namespace glint::capture::test {

std::filesystem::path freshTestDir(std::string_view name) {
    const std::filesystem::path dir = std::filesystem::path(GLINT_TEST_OUTPUT_DIR) / "capture" / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

namespace {
Layer makeLayer(std::string name, std::vector<std::string> channels, SampleType storage, std::uint32_t w,
                std::uint32_t h, float seed) {
    Layer layer{std::move(name), std::move(channels), {}, 0, storage};
    const std::size_t n = std::size_t{w} * h * layer.channels.size();
    layer.pixels.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        // Irrational-looking values in a range that HALF represents with rounding.
        layer.pixels[i] = std::sin(seed + 0.7310585f * static_cast<float>(i)) * 3.14159f;
    }
    return layer;
}
} // namespace

Frame makeFullFrame(std::uint32_t width, std::uint32_t height) {
    Frame f;
    f.width = width;
    f.height = height;
    f.frameIndex = 1234567;
    Camera& c = f.camera;
    for (std::size_t i = 0; i < 16; ++i) {
        c.projection.m[i] =
            (i % 5 == 0) ? 1.0 + 1e-12 * static_cast<double>(i) : 1e-17 * static_cast<double>(i);
        c.prevViewProjection.m[i] = std::sqrt(2.0) * static_cast<double>(i + 1) - 7.0;
    }
    c.view = identity();
    c.view.m[1] = 1.0 / 3.0;
    c.view.m[3] = 0.1 + 0.2; // 0.30000000000000004: exactness of the doubles shows
    c.view.m[7] = -1.0 / 7.0;
    c.depth = DepthConvention::Reversed;
    c.nearZ = 0.1 + 1e-15;
    c.farZ = 1000.0 / 3.0;
    c.ndcYDown = true;
    f.normalEncoding = NormalEncoding::WorldUnit;
    f.motion = {MotionUnits::Uv, {1.0f, 1.0f}};
    f.roughness = {"material", "G", false};
    f.effects = {"reflections", "shadows", "depth_pyramid"};
    f.layers = {
        makeLayer("color", {"R", "G", "B", "A"}, SampleType::Half, width, height, 0.1f),
        makeLayer("depth", {"Z"}, SampleType::Float, width, height, 0.2f),
        makeLayer("normal", {"X", "Y", "Z"}, SampleType::Float, width, height, 0.3f),
        makeLayer("material", {"R", "G", "B"}, SampleType::Half, width, height, 0.4f),
        makeLayer("roughness", {"Y"}, SampleType::Half, width, height, 0.5f),
        makeLayer("motion", {"X", "Y"}, SampleType::Float, width, height, 0.6f),
        makeLayer("shadow", {"Y"}, SampleType::Half, width, height, 0.7f),
        makeLayer("reference.reflection", {"R", "G", "B"}, SampleType::Float, width, height, 0.8f),
        makeLayer("reference.shadow", {"Y"}, SampleType::Half, width, height, 0.9f),
    };
    return f;
}

Frame makeDepthOnlyFrame(std::uint32_t width, std::uint32_t height) {
    Frame f;
    f.width = width;
    f.height = height;
    f.camera.view = identity();
    f.camera.projection = identity();
    f.camera.prevViewProjection = identity();
    f.effects = {"depth_pyramid"};
    f.layers = {makeLayer("depth", {"Z"}, SampleType::Float, width, height, 1.0f)};
    return f;
}

Imf::Header exrHeaderOf(const std::filesystem::path& file) {
    Imf::InputFile input(file.c_str());
    return input.header();
}

void writeZeroExr(const std::filesystem::path& file, const Imf::Header& header) {
    Imf::OutputFile output(file.c_str(), header);
    output.setFrameBuffer(Imf::FrameBuffer{}); // channels without a slice are written as zeros
    const Imath::Box2i& dw = header.dataWindow();
    output.writePixels(dw.max.y - dw.min.y + 1);
}

void writeHeaderOnlyExr(const std::filesystem::path& file, const Imf::Header& header) {
    Imf::StdOFStream out(file.c_str());
    const char preamble[8] = {0x76, 0x2f, 0x31, 0x01, 0x02, 0x00, 0x00, 0x00}; // magic, version 2, no flags
    out.write(preamble, 8);
    header.writeTo(out);
}

Imf::Header withoutChannel(const Imf::Header& header, const std::string& drop) {
    Imf::Header copy = header;
    Imf::ChannelList kept;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it)
        if (drop != it.name()) kept.insert(it.name(), it.channel());
    copy.channels() = kept;
    return copy;
}

Imf::Header withoutAttribute(const Imf::Header& header, const std::string& drop) {
    Imf::Header copy; // holds only the attributes every header has, all of which `header` has too
    for (auto it = header.begin(); it != header.end(); ++it)
        if (drop != it.name()) copy.insert(it.name(), it.attribute());
    return copy;
}

std::string captureErrorOf(const std::function<void()>& read) {
    try {
        read();
    } catch (const CaptureError& e) {
        return e.what();
    } catch (const std::exception& e) {
        return std::string("OTHER EXCEPTION: ") + e.what();
    }
    return "NO ERROR";
}

bool isOneLine(const std::string& text) {
    return !text.empty() && text.find('\n') == std::string::npos && text.find('\r') == std::string::npos;
}

void writeBytes(const std::filesystem::path& file, const std::string& bytes) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::string readBytes(const std::filesystem::path& file) {
    std::string bytes(static_cast<std::size_t>(std::filesystem::file_size(file)), '\0');
    std::ifstream in(file, std::ios::binary);
    in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return bytes;
}

Imf::Header validFrameHeader(const std::filesystem::path& dir, std::uint32_t width, std::uint32_t height) {
    writeFrame(dir / "valid.exr", makeFullFrame(width, height));
    return exrHeaderOf(dir / "valid.exr");
}

std::string rejectionOf(const std::filesystem::path& file, const Imf::Header& header) {
    writeZeroExr(file, header);
    const std::string message = captureErrorOf([&] { (void)readFrame(file); });
    CHECK(isOneLine(message));
    CHECK(message.find(file.filename().string()) != std::string::npos);
    return message;
}

} // namespace glint::capture::test
