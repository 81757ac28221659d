#include "capture/exr_file.h"

#include "capture/frame_validation.h"

#include <OpenEXR/ImfStdIO.h>
#include <OpenEXR/ImfVersion.h>

#include <array>
#include <cstdio>
#include <system_error>

namespace glint::capture {

namespace {
std::string windowText(const Imath::Box2i& box) {
    // snprintf rather than string concatenation: GCC 12 at -O3 reports a false -Wrestrict
    // (GCC bug 105329) on the chain of operator+ this would otherwise be.
    char text[96];
    std::snprintf(text, sizeof(text), "(%d,%d)-(%d,%d)", box.min.x, box.min.y, box.max.x, box.max.y);
    return text;
}

void checkWindows(const Imf::Header& header, const std::filesystem::path& file, ExrSize& size) {
    const Imath::Box2i& data = header.dataWindow();
    const Imath::Box2i& display = header.displayWindow();
    // Pixel (0,0) of every layer is the top-left pixel of the image: overscan and crop
    // windows would shift layers against the camera matrices, so they are refused.
    if (data.min.x != 0 || data.min.y != 0)
        fail(file, "data window " + windowText(data) + " does not start at (0,0)");
    if (data.min != display.min || data.max != display.max)
        fail(file, "data window " + windowText(data) + " differs from display window " + windowText(display));
    const std::int64_t w = std::int64_t{data.max.x} - data.min.x + 1;
    const std::int64_t h = std::int64_t{data.max.y} - data.min.y + 1;
    if (w <= 0 || h <= 0) fail(file, "data window " + windowText(data) + " is empty");
    if (auto problem = checkDimensions(static_cast<std::uint64_t>(w), static_cast<std::uint64_t>(h)))
        fail(file, *problem);
    size = {static_cast<std::uint32_t>(w), static_cast<std::uint32_t>(h)};
}
} // namespace

Imf::Header readExrHeader(const std::filesystem::path& file, ExrSize& size) {
    std::error_code ec;
    const auto status = std::filesystem::status(file, ec);
    if (!std::filesystem::exists(status)) fail(file, "file does not exist");
    if (!std::filesystem::is_regular_file(status)) fail(file, "not a regular file");
    const std::uintmax_t bytes = std::filesystem::file_size(file, ec);
    if (ec) fail(file, "cannot determine the file size: " + ec.message());
    if (bytes < 8)
        fail(file, "not an OpenEXR file (" + std::to_string(bytes) + " bytes, shorter than the preamble)");

    Imf::Header header;
    translateErrors(file, "cannot read OpenEXR header", [&] {
        Imf::StdIFStream stream(file.c_str());
        std::array<char, 8> start{};
        stream.read(start.data(), static_cast<int>(start.size()));
        if (!Imf::isImfMagic(start.data())) fail(file, "not an OpenEXR file (wrong magic number)");
        // The version field is a little-endian int: low byte version, upper bytes flags.
        std::uint32_t field = 0;
        for (std::size_t i = 0; i < 4; ++i)
            field |= std::uint32_t{static_cast<unsigned char>(start[4 + i])} << (8 * i);
        const int version = static_cast<int>(field);
        if (Imf::getVersion(version) != Imf::EXR_VERSION)
            fail(file, "unsupported OpenEXR file version " + std::to_string(Imf::getVersion(version)));
        if (!Imf::supportsFlags(Imf::getFlags(version))) fail(file, "unknown OpenEXR file flags");
        if (Imf::isMultiPart(version)) fail(file, "multi-part OpenEXR files are not glint captures");
        if (Imf::isNonImage(version)) fail(file, "deep OpenEXR files are not glint captures");
        int readVersion = version;
        header.readFrom(stream, readVersion);
    });
    checkWindows(header, file, size);
    return header;
}

} // namespace glint::capture
