// Images for previews and reports: 8-bit PNG previews of float data (tonemapped colour, grey
// scalars, heat maps, category colours) and plain single-layer FLOAT OpenEXR files.
//
// Errors are std::runtime_error (CaptureError, a runtime_error, for readExr) whose what() is
// one line "<path>: <problem>", as everywhere in the harness.
#pragma once

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace glint::report {

// Interleaved samples, row-major, pixel (0,0) at the top left:
// pixels[(y * width + x) * channels + c]. A valid image has width, height and channels > 0
// and pixels.size() == width * height * channels.
struct Image {
    std::uint32_t width = 0, height = 0, channels = 0;
    std::vector<float> pixels;
};

// HDR colour: each channel is scaled by `exposure` (a linear factor, 1 = as captured),
// negatives clamp to 0, then the Reinhard curve x / (1 + x), then the sRGB OETF.
struct Tonemap {
    float exposure = 1.0f;
};
// Scalar data (depth, confidence, motion): (v - min) / (max - min) clamped to [0, 1], written
// linearly (no sRGB curve: the grey level is the data, not a colour). Needs min < max.
struct Linear {
    float min = 0.0f, max = 1.0f;
};
// Scalar 0..max through a viridis-like ramp (dark blue, green, yellow); values <= 0 get the
// first colour, values >= max the last. Needs max > 0. The scalar of a pixel is its value
// (1 channel), the length of (R,G) (2 channels, e.g. motion) or Rec. 709 luminance (3/4).
struct Heat {
    float max = 1.0f;
};
// Integer classes in channel 0 (other channels ignored), rounded to the nearest integer:
// class k >= 0 gets categoryColor(k), negative classes white.
struct Categories {};

using PngMapping = std::variant<Tonemap, Linear, Heat, Categories>;

struct Rgb8 {
    std::uint8_t r = 0, g = 0, b = 0;
    friend bool operator==(const Rgb8&, const Rgb8&) = default;
};

// Written for any pixel whose mapped samples include a NaN or an infinity, with every
// mapping: no ramp or category colour is magenta, so such pixels stand out.
inline constexpr Rgb8 kNonFiniteColor{255, 0, 255};

// The fixed colour of class k >= 0 (the palette repeats past its end; class 0 is black).
Rgb8 categoryColor(std::uint64_t k);
// The heat ramp at t in [0, 1] (clamped), before quantisation to 8 bits.
void heatRamp(float t, float& r, float& g, float& b);

// Writes an 8-bit RGB PNG. Channel use: 1 channel gives grey (Tonemap, Linear) or the ramp
// (Heat); 2 channels map to R and G with B = 0 (Tonemap, Linear); 3 or 4 channels map to RGB
// and alpha is ignored (a preview with transparency would hide what it shows).
void writePng(const std::string& path, const Image& image, PngMapping mapping);

// The pixels writePng would write: interleaved 8-bit RGB, row-major from the top left.
// `what` names the image in the one-line error a bad image or mapping throws.
std::vector<std::uint8_t> mapToRgb8(const std::string& what, const Image& image, PngMapping mapping);

// 8-bit RGB pixels, interleaved, row-major from the top left (screenshots, previews read back).
struct RgbImage {
    std::uint32_t width = 0, height = 0;
    std::vector<std::uint8_t> rgb;
};
// Writes `rgb` (width * height * 3 bytes) as an 8-bit RGB PNG.
void writeRgbPng(const std::string& path, std::uint32_t width, std::uint32_t height,
                 const std::vector<std::uint8_t>& rgb);
// Reads any PNG as 8-bit RGB (alpha dropped, grey expanded).
RgbImage readRgbPng(const std::string& path);
// `image` as the bytes of an 8-bit RGB PNG file; `what` names it in the one-line error.
std::string encodeRgbPng(const std::string& what, const RgbImage& image);
// The `width` x `height` window of `image` at (x, y), every pixel repeated `scale` times in
// both directions (nearest filtering). The window must lie inside the image and scale >= 1.
RgbImage cropScaled(const RgbImage& image, std::uint32_t x, std::uint32_t y, std::uint32_t width,
                    std::uint32_t height, std::uint32_t scale);

// Writes a single-part scanline OpenEXR file with one FLOAT channel per image channel, named
// by channelNames (in the image's interleaved order; OpenEXR itself stores them sorted),
// ZIP-compressed (lossless). The file appears under its name only once it is complete.
void writeExr(const std::string& path, const Image& image, const std::vector<std::string>& channelNames);

// Reads a single-part flat OpenEXR file, any channels and sample types (converted to float),
// in the order R, G, B, A (those present), then every other channel by name (byte order).
// The names in that order go to *channelNames when it is not null.
Image readExr(const std::string& path, std::vector<std::string>* channelNames = nullptr);

} // namespace glint::report
