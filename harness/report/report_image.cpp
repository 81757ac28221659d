#include "report/report_image.h"

#include "capture/capture_error.h"
#include "capture/exr_file.h"
#include "capture/frame_validation.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <png.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace glint::report {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& problem) {
    throw std::runtime_error(capture::oneLine(path) + ": " + capture::oneLine(problem));
}

std::string sizeText(const Image& image) {
    return std::to_string(image.width) + "x" + std::to_string(image.height) + "x" +
           std::to_string(image.channels);
}

// Checks the invariants of Image and the size limits of the capture format (so every file
// written here is one readExr accepts).
void checkImage(const std::string& path, const Image& image) {
    if (image.width == 0 || image.height == 0 || image.channels == 0)
        fail(path, "cannot write an empty image (" + sizeText(image) + ")");
    if (auto problem = capture::checkDimensions(image.width, image.height)) fail(path, *problem);
    const std::uint64_t samples = std::uint64_t{image.width} * image.height * image.channels;
    if (image.pixels.size() != samples)
        fail(path, "image of " + sizeText(image) + " holds " + std::to_string(image.pixels.size()) +
                       " samples, expected " + std::to_string(samples));
}

// Writes through a sibling "<path>.partial" renamed into place at the end, so that a failed
// or interrupted write never leaves a truncated file under the final name.
template <typename Write> void writeAtomically(const std::string& path, Write&& write) {
    const std::string partial = path + ".partial";
    try {
        write(partial);
        std::error_code ec;
        std::filesystem::rename(partial, path, ec);
        if (ec) fail(path, "cannot rename " + partial + " into place: " + ec.message());
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(partial, ignored);
        throw;
    }
}

// ---- PNG mappings --------------------------------------------------------------------------

std::uint8_t quantize(double v) {
    const double clamped = std::clamp(v, 0.0, 1.0);
    return static_cast<std::uint8_t>(std::lround(clamped * 255.0));
}

// IEC 61966-2-1 sRGB encoding of a linear value in [0, 1].
double srgbEncode(double linear) {
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

// Reinhard x / (1 + x) per channel rather than an ACES fit: the previews exist to inspect
// noise and denoiser artefacts, and Reinhard has slope 1 at 0 with no toe, so dark regions
// (where the noise lives) are not crushed; it never clips, is monotonic and exactly
// invertible (x = t / (1 - t)), so a reader can still estimate the radiance of a pixel.
// Per channel keeps it a pure function of each sample; hue shifts only in the highlights.
double reinhard(double x) {
    return x / (1.0 + x);
}

// Stops of matplotlib's viridis (CC0) at t = 0, 1/8, ..., 1, interpolated linearly in sRGB:
// lightness rises monotonically, it reads in greyscale and for common colour-vision
// deficiencies, and it contains no magenta, the colour kept for non-finite samples.
constexpr std::array<std::array<std::uint8_t, 3>, 9> kViridisStops{{
    {68, 1, 84},
    {71, 45, 123},
    {59, 82, 139},
    {44, 114, 142},
    {33, 144, 140},
    {39, 173, 129},
    {92, 200, 99},
    {170, 220, 50},
    {253, 231, 37},
}};

// Distinct colours for classes (Tableau 10 without its pink, after black for class 0); none
// is magenta or white (white marks negative classes).
constexpr std::array<Rgb8, 10> kCategoryPalette{{
    {0, 0, 0},
    {31, 119, 180},
    {255, 127, 14},
    {44, 160, 44},
    {214, 39, 40},
    {148, 103, 189},
    {140, 86, 75},
    {127, 127, 127},
    {188, 189, 34},
    {23, 190, 207},
}};
constexpr Rgb8 kNegativeClassColor{255, 255, 255};

struct PixelMapper {
    const Image& image;
    const PngMapping& mapping;

    // The channels a mapping reads: channel 0 for Categories, otherwise up to three.
    std::uint32_t usedChannels() const {
        return std::holds_alternative<Categories>(mapping) ? 1u : std::min(image.channels, 3u);
    }

    Rgb8 operator()(const float* px) const {
        const std::uint32_t used = usedChannels();
        for (std::uint32_t c = 0; c < used; ++c)
            if (!std::isfinite(px[c])) return kNonFiniteColor;
        return std::visit([&](const auto& m) { return map(m, px); }, mapping);
    }

    // Applies `f` to each used channel: grey for one channel, (R, G, 0) for two, RGB for more.
    template <typename F> Rgb8 perChannel(const float* px, F&& f) const {
        if (image.channels == 1) {
            const std::uint8_t v = f(px[0]);
            return {v, v, v};
        }
        if (image.channels == 2) return {f(px[0]), f(px[1]), 0};
        return {f(px[0]), f(px[1]), f(px[2])};
    }

    Rgb8 map(const Tonemap& m, const float* px) const {
        return perChannel(px, [&](float v) {
            const double x = std::max(0.0, double{v} * double{m.exposure});
            return quantize(srgbEncode(reinhard(x)));
        });
    }

    Rgb8 map(const Linear& m, const float* px) const {
        const double range = double{m.max} - double{m.min};
        return perChannel(px, [&](float v) { return quantize((double{v} - double{m.min}) / range); });
    }

    Rgb8 map(const Heat& m, const float* px) const {
        double s = 0.0;
        if (image.channels == 1)
            s = px[0];
        else if (image.channels == 2)
            s = std::hypot(double{px[0]}, double{px[1]});
        else
            s = 0.2126 * double{px[0]} + 0.7152 * double{px[1]} + 0.0722 * double{px[2]};
        float r = 0, g = 0, b = 0;
        // Clamped in double first: s / max can exceed the float range.
        heatRamp(static_cast<float>(std::clamp(s / double{m.max}, 0.0, 1.0)), r, g, b);
        return {quantize(double{r}), quantize(double{g}), quantize(double{b})};
    }

    Rgb8 map(const Categories&, const float* px) const {
        const double k = std::floor(double{px[0]} + 0.5);
        if (k < 0.0) return kNegativeClassColor;
        // fmod keeps classes beyond the range of integers well defined.
        return categoryColor(static_cast<std::uint64_t>(std::fmod(k, double{kCategoryPalette.size()})));
    }
};

void checkMapping(const std::string& path, const PngMapping& mapping) {
    if (const auto* t = std::get_if<Tonemap>(&mapping)) {
        if (!std::isfinite(t->exposure) || t->exposure < 0.0f)
            fail(path, "Tonemap exposure must be finite and >= 0, got " + std::to_string(t->exposure));
    } else if (const auto* l = std::get_if<Linear>(&mapping)) {
        if (!std::isfinite(l->min) || !std::isfinite(l->max) || !(l->min < l->max) ||
            !std::isfinite(double{l->max} - double{l->min}))
            fail(path, "Linear mapping needs finite min < max, got [" + std::to_string(l->min) + ", " +
                           std::to_string(l->max) + "]");
    } else if (const auto* h = std::get_if<Heat>(&mapping)) {
        if (!std::isfinite(h->max) || !(h->max > 0.0f))
            fail(path, "Heat mapping needs a finite max > 0, got " + std::to_string(h->max));
    }
}

// ---- OpenEXR ----------------------------------------------------------------------------------

// R, G, B, A first (in that order), then the rest by name.
bool channelOrder(const std::string& a, const std::string& b) {
    static constexpr std::array<const char*, 4> kFirst{"R", "G", "B", "A"};
    auto rank = [](const std::string& name) {
        for (std::size_t i = 0; i < kFirst.size(); ++i)
            if (name == kFirst[i]) return i;
        return kFirst.size();
    };
    const std::size_t ra = rank(a), rb = rank(b);
    if (ra != rb) return ra < rb;
    return a < b;
}

Imf::Slice floatSlice(const float* base, std::uint32_t channel, const Image& image) {
    const std::size_t xStride = sizeof(float) * image.channels;
    const std::size_t yStride = xStride * image.width;
    // Slice takes a mutable pointer for both directions; OutputFile only reads through it.
    char* bytes = const_cast<char*>(reinterpret_cast<const char*>(base + channel));
    return Imf::Slice(Imf::FLOAT, bytes, xStride, yStride);
}

} // namespace

Rgb8 categoryColor(std::uint64_t k) {
    return kCategoryPalette[static_cast<std::size_t>(k % kCategoryPalette.size())];
}

void heatRamp(float t, float& r, float& g, float& b) {
    // NaN goes to the first stop (clamp would pass it through).
    const double x = std::isnan(t) ? 0.0 : std::clamp(double{t}, 0.0, 1.0);
    const double scaled = x * double{kViridisStops.size() - 1};
    const std::size_t i = std::min(static_cast<std::size_t>(scaled), kViridisStops.size() - 2);
    const double f = scaled - static_cast<double>(i);
    auto lerp = [&](std::size_t c) {
        const double a = kViridisStops[i][c], z = kViridisStops[i + 1][c];
        return static_cast<float>((a + (z - a) * f) / 255.0);
    };
    r = lerp(0);
    g = lerp(1);
    b = lerp(2);
}

std::vector<std::uint8_t> mapToRgb8(const std::string& what, const Image& image, PngMapping mapping) {
    checkImage(what, image);
    if (image.channels > 4) fail(what, "a PNG preview takes 1 to 4 channels, got " + sizeText(image));
    checkMapping(what, mapping);

    const std::size_t pixelCount = std::size_t{image.width} * image.height;
    std::vector<std::uint8_t> rgb(pixelCount * 3);
    const PixelMapper mapper{image, mapping};
    for (std::size_t i = 0; i < pixelCount; ++i) {
        const Rgb8 c = mapper(image.pixels.data() + i * image.channels);
        rgb[3 * i + 0] = c.r;
        rgb[3 * i + 1] = c.g;
        rgb[3 * i + 2] = c.b;
    }
    return rgb;
}

void writePng(const std::string& path, const Image& image, PngMapping mapping) {
    writeRgbPng(path, image.width, image.height, mapToRgb8(path, image, mapping));
}

void writeRgbPng(const std::string& path, std::uint32_t width, std::uint32_t height,
                 const std::vector<std::uint8_t>& rgb) {
    if (auto problem = capture::checkDimensions(width, height)) fail(path, *problem);
    if (rgb.size() != std::size_t{width} * height * 3)
        fail(path, std::to_string(rgb.size()) + " bytes for an RGB image of " + std::to_string(width) + "x" +
                       std::to_string(height));
    writeAtomically(path, [&](const std::string& partial) {
        std::FILE* file = std::fopen(partial.c_str(), "wb");
        if (file == nullptr) fail(path, std::string("cannot open for writing: ") + std::strerror(errno));
        // libpng's simplified API reports errors through png.message instead of longjmp,
        // which would otherwise skip C++ destructors.
        png_image png{};
        png.version = PNG_IMAGE_VERSION;
        png.width = width;
        png.height = height;
        png.format = PNG_FORMAT_RGB;
        const int ok = png_image_write_to_stdio(&png, file, 0, rgb.data(), 0, nullptr);
        const std::string message = png.message;
        png_image_free(&png);
        const bool closed = std::fclose(file) == 0;
        if (!ok) fail(path, "cannot write PNG: " + message);
        if (!closed) fail(path, std::string("cannot write PNG: ") + std::strerror(errno));
    });
}

std::string encodeRgbPng(const std::string& what, const RgbImage& image) {
    if (auto problem = capture::checkDimensions(image.width, image.height)) fail(what, *problem);
    if (image.rgb.size() != std::size_t{image.width} * image.height * 3)
        fail(what, std::to_string(image.rgb.size()) + " bytes for an RGB image of " +
                       std::to_string(image.width) + "x" + std::to_string(image.height));
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    png.width = image.width;
    png.height = image.height;
    png.format = PNG_FORMAT_RGB;
    png_alloc_size_t size = 0; // first call: the size the PNG needs
    int ok = png_image_write_to_memory(&png, nullptr, &size, 0, image.rgb.data(), 0, nullptr);
    std::string bytes(ok ? size : 0, '\0');
    if (ok) ok = png_image_write_to_memory(&png, bytes.data(), &size, 0, image.rgb.data(), 0, nullptr);
    const std::string message = png.message;
    png_image_free(&png);
    if (!ok) fail(what, "cannot encode PNG: " + message);
    bytes.resize(size);
    return bytes;
}

RgbImage cropScaled(const RgbImage& image, std::uint32_t x, std::uint32_t y, std::uint32_t width,
                    std::uint32_t height, std::uint32_t scale) {
    if (scale == 0 || width == 0 || height == 0 || x + width > image.width || y + height > image.height) {
        std::ostringstream problem;
        problem << "cropScaled: a window of " << width << "x" << height << " at (" << x << ", " << y
                << ") scaled by " << scale << " does not fit an image of " << image.width << "x"
                << image.height;
        throw std::invalid_argument(problem.str());
    }
    RgbImage out{width * scale, height * scale,
                 std::vector<std::uint8_t>(std::size_t{width} * height * scale * scale * 3)};
    for (std::uint32_t row = 0; row < out.height; ++row)
        for (std::uint32_t column = 0; column < out.width; ++column) {
            const std::size_t from = ((std::size_t{y} + row / scale) * image.width + x + column / scale) * 3;
            const std::size_t to = (std::size_t{row} * out.width + column) * 3;
            for (std::size_t c = 0; c < 3; ++c) out.rgb[to + c] = image.rgb[from + c];
        }
    return out;
}

RgbImage readRgbPng(const std::string& path) {
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&png, path.c_str())) {
        const std::string message = png.message;
        png_image_free(&png);
        fail(path, "cannot read PNG: " + message);
    }
    png.format = PNG_FORMAT_RGB;
    if (auto problem = capture::checkDimensions(png.width, png.height)) {
        png_image_free(&png);
        fail(path, *problem);
    }
    RgbImage image{png.width, png.height, std::vector<std::uint8_t>(PNG_IMAGE_SIZE(png))};
    const int ok = png_image_finish_read(&png, nullptr, image.rgb.data(), 0, nullptr);
    const std::string message = png.message;
    png_image_free(&png);
    if (!ok) fail(path, "cannot read PNG: " + message);
    return image;
}

void writeExr(const std::string& path, const Image& image, const std::vector<std::string>& channelNames) {
    checkImage(path, image);
    if (channelNames.size() != image.channels)
        fail(path, std::to_string(channelNames.size()) + " channel names for an image of " +
                       std::to_string(image.channels) + " channels");
    if (image.channels > capture::kMaxChannels)
        fail(path, "at most " + std::to_string(capture::kMaxChannels) + " channels, got " +
                       std::to_string(image.channels));
    std::set<std::string> unique;
    for (const std::string& name : channelNames) {
        if (name.empty()) fail(path, "empty channel name");
        if (!unique.insert(name).second) fail(path, "channel name '" + name + "' appears twice");
    }

    writeAtomically(path, [&](const std::string& partial) {
        capture::translateErrors(path, "cannot write OpenEXR file", [&] {
            Imf::Header header(static_cast<int>(image.width), static_cast<int>(image.height));
            header.compression() = Imf::ZIP_COMPRESSION;
            Imf::FrameBuffer frameBuffer;
            for (std::uint32_t c = 0; c < image.channels; ++c) {
                header.channels().insert(channelNames[c], Imf::Channel(Imf::FLOAT));
                frameBuffer.insert(channelNames[c], floatSlice(image.pixels.data(), c, image));
            }
            Imf::OutputFile file(partial.c_str(), header);
            file.setFrameBuffer(frameBuffer);
            file.writePixels(static_cast<int>(image.height));
        });
    });
}

Image readExr(const std::string& path, std::vector<std::string>* channelNames) {
    // readExrHeader refuses missing, non-EXR, multi-part, deep and oversized files, and
    // windows not at (0,0), before OpenEXR allocates anything from the header's claims;
    // checkPixelData refuses a file too short for the pixel data it declares before the image
    // is allocated, so what a file makes the reader allocate is bounded by its size.
    capture::ExrSize size;
    capture::ExrLayout layout;
    const Imf::Header header = capture::readExrHeader(path, size, &layout);
    capture::checkPixelData(path, header, layout);

    std::vector<std::string> names;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
        if (it.channel().xSampling != 1 || it.channel().ySampling != 1)
            capture::fail(path, std::string("subsampled channel '") + it.name() + "' is not supported");
        names.emplace_back(it.name());
    }
    if (names.empty()) capture::fail(path, "the file has no channels");
    if (names.size() > capture::kMaxChannels)
        capture::fail(path, std::to_string(names.size()) + " channels, more than the limit of " +
                                std::to_string(capture::kMaxChannels));
    const std::uint64_t samples = std::uint64_t{size.width} * size.height * names.size();
    if (samples > capture::kMaxSamples)
        capture::fail(path, std::to_string(samples) + " samples, more than the limit of " +
                                std::to_string(capture::kMaxSamples));
    std::sort(names.begin(), names.end(), channelOrder);

    Image image;
    image.width = size.width;
    image.height = size.height;
    image.channels = static_cast<std::uint32_t>(names.size());
    image.pixels.assign(static_cast<std::size_t>(samples), 0.0f);
    capture::translateErrors(path, "cannot read pixel data", [&] {
        Imf::InputFile file(path.c_str());
        Imf::FrameBuffer frameBuffer;
        for (std::uint32_t c = 0; c < image.channels; ++c)
            frameBuffer.insert(names[c], floatSlice(image.pixels.data(), c, image));
        file.setFrameBuffer(frameBuffer);
        file.readPixels(0, static_cast<int>(image.height) - 1);
    });
    if (channelNames != nullptr) *channelNames = std::move(names);
    return image;
}

} // namespace glint::report
