#include "capture/exr_file.h"

#include "capture/frame_validation.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfStdIO.h>
#include <OpenEXR/ImfTileDescription.h>
#include <OpenEXR/ImfVersion.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>
#include <system_error>
#include <vector>

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

// The file read at explicit offsets; a read that would pass the end of the file fails
// instead of reading, so no size taken from the file is trusted before it is compared
// with the bytes that are really there. Small reads (the header walk reads names byte by
// byte) are served from one cached block.
class FileReader {
  public:
    FileReader(const std::filesystem::path& file, std::uint64_t bytes) : bytes_(bytes) {
        in_.open(file, std::ios::binary);
        if (!in_) fail(file, "cannot open the file");
    }

    std::uint64_t size() const { return bytes_; }
    std::uint64_t left(std::uint64_t offset) const { return offset < bytes_ ? bytes_ - offset : 0; }

    bool read(std::uint64_t offset, void* out, std::size_t n) {
        if (n > left(offset)) return false;
        if (n > kBlock / 2) return readFile(offset, out, n);
        if (offset < blockStart_ || offset + n > blockStart_ + block_.size()) {
            block_.resize(static_cast<std::size_t>(std::min<std::uint64_t>(kBlock, left(offset))));
            if (!readFile(offset, block_.data(), block_.size())) {
                block_.clear();
                return false;
            }
            blockStart_ = offset;
        }
        std::memcpy(out, block_.data() + (offset - blockStart_), n);
        return true;
    }

    // OpenEXR files are little-endian.
    std::optional<std::int32_t> int32(std::uint64_t offset) {
        std::array<unsigned char, 4> b{};
        if (!read(offset, b.data(), b.size())) return std::nullopt;
        std::uint32_t v = 0;
        for (std::size_t i = 0; i < 4; ++i) v |= std::uint32_t{b[i]} << (8 * i);
        return static_cast<std::int32_t>(v);
    }

  private:
    static constexpr std::size_t kBlock = 4096;

    bool readFile(std::uint64_t offset, void* out, std::size_t n) {
        in_.clear();
        in_.seekg(static_cast<std::streamoff>(offset));
        in_.read(static_cast<char*>(out), static_cast<std::streamsize>(n));
        return in_.gcount() == static_cast<std::streamsize>(n);
    }

    std::ifstream in_;
    std::uint64_t bytes_ = 0;
    std::vector<char> block_;
    std::uint64_t blockStart_ = 0;
};

std::uint64_t readUint64(const unsigned char* b) {
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < 8; ++i) v |= std::uint64_t{b[i]} << (8 * i);
    return v;
}

// ---- header walk -------------------------------------------------------------------------

// The value size of every attribute type OpenEXR 3.1 reads with a fixed length whatever its
// size field says; a different size would make OpenEXR's reading and ours part ways.
std::optional<std::int32_t> fixedValueSize(std::string_view type) {
    struct Fixed {
        std::string_view type;
        std::int32_t size;
    };
    static constexpr std::array<Fixed, 24> kFixed{{
        {"box2f", 16},      {"box2i", 16},    {"chromaticities", 32},
        {"compression", 1}, {"double", 8},    {"deepImageState", 1},
        {"envmap", 1},      {"float", 4},     {"int", 4},
        {"keycode", 28},    {"lineOrder", 1}, {"m33d", 72},
        {"m33f", 36},       {"m44d", 128},    {"m44f", 64},
        {"rational", 8},    {"tiledesc", 9},  {"timecode", 8},
        {"v2d", 16},        {"v2f", 8},       {"v2i", 8},
        {"v3d", 24},        {"v3f", 12},      {"v3i", 12},
    }};
    for (const Fixed& f : kFixed)
        if (f.type == type) return f.size;
    return std::nullopt;
}

struct HeaderWalk {
    const std::filesystem::path& file;
    FileReader& reader;
    std::uint64_t at = 8; // after the magic number and version field

    [[noreturn]] void truncated(const std::string& where) const {
        fail(file, "file is truncated inside its header (" + where + ")");
    }

    // A name as OpenEXR reads it: at most 255 characters and the terminating NUL. `what`
    // and `owner` say which name it is ("type of attribute 'x'"), for messages only.
    std::string name(const char* what, const std::string& owner = {}) {
        auto describe = [&] { return std::string(what) + (owner.empty() ? "" : " '" + owner + "'"); };
        std::string text;
        for (;;) {
            char c = 0;
            if (!reader.read(at, &c, 1)) truncated(describe());
            ++at;
            if (c == '\0') return text;
            if (text.size() == 255)
                fail(file, describe() + " '" + text.substr(0, 40) + "...' is longer than 255 characters");
            text.push_back(c);
        }
    }

    // The bytes Imf::ChannelList's reader takes: entries of a name and 16 bytes, up to an
    // empty name. It reads until that end marker whatever the attribute's size says.
    std::uint64_t channelListBytes(const std::string& attribute) {
        const std::uint64_t start = at;
        for (;;) {
            const std::string channel = name("channel name in attribute", attribute);
            if (channel.empty()) break;
            if (reader.left(at) < 16) truncated("channel '" + channel + "'");
            at += 16;
        }
        const std::uint64_t bytes = at - start;
        at = start;
        return bytes;
    }

    // Walks every attribute up to the end-of-header marker; returns the offset after it.
    std::uint64_t run() {
        for (;;) {
            const std::string attribute = name("attribute name");
            if (attribute.empty()) return at;
            const std::string type = name("type of attribute", attribute);
            const std::optional<std::int32_t> size = reader.int32(at);
            if (!size) truncated("size of attribute '" + attribute + "'");
            at += 4;
            auto what = [&] { return "attribute '" + attribute + "' (" + type + ")"; };
            if (*size < 0) fail(file, what() + " has a negative size (" + std::to_string(*size) + ")");
            const auto bytes = static_cast<std::uint64_t>(*size);
            if (bytes > reader.left(at))
                fail(file, what() + " declares " + std::to_string(bytes) + " bytes but only " +
                               std::to_string(reader.left(at)) + " remain in the file");
            if (type == "chlist") {
                const std::uint64_t used = channelListBytes(attribute);
                if (used != bytes)
                    fail(file, what() + " declares " + std::to_string(bytes) +
                                   " bytes but its channels take " + std::to_string(used));
            } else if (const std::optional<std::int32_t> fixed = fixedValueSize(type);
                       fixed && *fixed != *size) {
                fail(file, what() + " has size " + std::to_string(bytes) + "; a " + type + " value takes " +
                               std::to_string(*fixed) + " bytes");
            } else if (type == "floatvector" && bytes % 4 != 0) {
                fail(file, what() + " has size " + std::to_string(bytes) + ", not a whole number of floats");
            }
            at += bytes;
        }
    }
};

// ---- pixel data --------------------------------------------------------------------------

int linesPerChunk(Imf::Compression c) {
    switch (c) {
    case Imf::NO_COMPRESSION:
    case Imf::RLE_COMPRESSION:
    case Imf::ZIPS_COMPRESSION:
        return 1;
    case Imf::ZIP_COMPRESSION:
    case Imf::PXR24_COMPRESSION:
        return 16;
    case Imf::PIZ_COMPRESSION:
    case Imf::B44_COMPRESSION:
    case Imf::B44A_COMPRESSION:
    case Imf::DWAA_COMPRESSION:
        return 32;
    case Imf::DWAB_COMPRESSION:
        return 256;
    default:
        return 0;
    }
}

const char* compressionName(Imf::Compression c) {
    switch (c) {
    case Imf::NO_COMPRESSION:
        return "no";
    case Imf::RLE_COMPRESSION:
        return "RLE";
    case Imf::ZIPS_COMPRESSION:
        return "ZIPS";
    case Imf::ZIP_COMPRESSION:
        return "ZIP";
    case Imf::PIZ_COMPRESSION:
        return "PIZ";
    case Imf::PXR24_COMPRESSION:
        return "PXR24";
    case Imf::B44_COMPRESSION:
        return "B44";
    case Imf::B44A_COMPRESSION:
        return "B44A";
    case Imf::DWAA_COMPRESSION:
        return "DWAA";
    case Imf::DWAB_COMPRESSION:
        return "DWAB";
    default:
        return "unknown";
    }
}

std::uint64_t sampleBytes(Imf::PixelType type) {
    switch (type) {
    case Imf::HALF:
        return 2;
    case Imf::FLOAT:
    case Imf::UINT:
        return 4;
    default:
        return 0;
    }
}

// One channel as the file stores it: bytes of one sampled row and the row sampling.
struct StoredChannel {
    std::uint64_t rowBytes = 0;
    std::uint64_t ySampling = 1;
};

// Scanlines whose index is a multiple of `sampling` among [y0, y1] (y0 >= 0).
std::uint64_t sampledRows(std::uint64_t y0, std::uint64_t y1, std::uint64_t sampling) {
    return y1 / sampling - (y0 + sampling - 1) / sampling + 1;
}

struct PixelCheck {
    const std::filesystem::path& file;
    const Imf::Header& header;
    const ExrLayout& layout;
    FileReader reader;
    std::uint64_t width = 0, height = 0;
    Imf::Compression compression = Imf::NO_COMPRESSION;
    std::vector<StoredChannel> channels;
    std::uint64_t pixelBytes = 0; // one sample of every channel

    PixelCheck(const std::filesystem::path& f, const Imf::Header& h, const ExrLayout& l)
        : file(f), header(h), layout(l), reader(f, l.fileBytes) {
        const Imath::Box2i& dw = header.dataWindow();
        width = static_cast<std::uint64_t>(std::int64_t{dw.max.x} - dw.min.x + 1);
        height = static_cast<std::uint64_t>(std::int64_t{dw.max.y} - dw.min.y + 1);
        compression = header.compression();
        for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
            const Imf::Channel& c = it.channel();
            const std::uint64_t bytes = sampleBytes(c.type);
            if (bytes == 0) fail(file, "channel '" + std::string(it.name()) + "' has an unknown pixel type");
            // Header::sanityCheck has made both samplings positive divisors of the window.
            channels.push_back({bytes * (width / static_cast<std::uint64_t>(c.xSampling)),
                                static_cast<std::uint64_t>(c.ySampling)});
            pixelBytes += bytes;
        }
    }

    std::string chunkText(std::uint64_t i, std::uint64_t count) const {
        return "chunk " + std::to_string(i) + " of " + std::to_string(count);
    }

    // Reads the offset table of `count` chunks, each entry checked to point inside the file.
    std::vector<std::uint64_t> offsetTable(std::uint64_t count, std::uint64_t chunkHeaderBytes) {
        const std::uint64_t tableStart = layout.headerEnd;
        if (count > reader.left(tableStart) / 8)
            fail(file, "file is truncated or incomplete: its offset table of " + std::to_string(count) +
                           " chunks does not fit in the " + std::to_string(layout.fileBytes) + "-byte file");
        std::vector<unsigned char> bytes(static_cast<std::size_t>(count * 8));
        if (!reader.read(tableStart, bytes.data(), bytes.size()))
            fail(file, "cannot read the chunk offset table");
        const std::uint64_t dataStart = tableStart + count * 8;
        std::vector<std::uint64_t> offsets(static_cast<std::size_t>(count));
        for (std::size_t i = 0; i < offsets.size(); ++i) {
            offsets[i] = readUint64(bytes.data() + 8 * i);
            if (offsets[i] == 0)
                fail(file, "file is truncated or incomplete: " + chunkText(i, count) + " was never written");
            if (offsets[i] < dataStart || reader.left(offsets[i]) < chunkHeaderBytes)
                fail(file, "file is truncated or incomplete: " + chunkText(i, count) + " starts at byte " +
                               std::to_string(offsets[i]) + ", outside the pixel data of the " +
                               std::to_string(layout.fileBytes) + "-byte file");
        }
        return offsets;
    }

    // The stored size of a chunk, after its `headerInts` leading ints, checked against the
    // bytes left in the file and against the `raw` bytes it decodes to.
    void checkStoredSize(std::uint64_t offset, std::uint64_t headerInts, std::uint64_t raw,
                         const std::string& chunk) {
        const std::uint64_t sizeAt = offset + 4 * headerInts;
        const std::optional<std::int32_t> stored = reader.int32(sizeAt);
        if (!stored) fail(file, "file is truncated or incomplete: " + chunk + " is cut short");
        if (*stored < 0) fail(file, chunk + " has a negative size (" + std::to_string(*stored) + ")");
        const auto bytes = static_cast<std::uint64_t>(*stored);
        if (bytes > reader.left(sizeAt + 4))
            fail(file, "file is truncated or incomplete: " + chunk + " declares " + std::to_string(bytes) +
                           " bytes but only " + std::to_string(reader.left(sizeAt + 4)) +
                           " remain in the file");
        if (compression == Imf::NO_COMPRESSION) {
            if (bytes != raw)
                fail(file, "uncompressed " + chunk + " stores " + std::to_string(bytes) + " bytes; its " +
                               std::to_string(width) + "-pixel-wide data needs exactly " +
                               std::to_string(raw));
            return;
        }
        const std::uint64_t ratio = maxCompressionRatio(compression);
        if (raw > ratio * bytes)
            fail(file, chunk + " stores " + std::to_string(bytes) + " bytes, too few for the " +
                           std::to_string(raw) + " bytes it must decode to: " + compressionName(compression) +
                           " compression reaches at most " + std::to_string(ratio) + ":1");
    }

    void scanlines() {
        const auto lines = static_cast<std::uint64_t>(linesPerChunk(compression));
        if (lines == 0)
            fail(file, "unknown compression method " + std::to_string(static_cast<int>(compression)));
        const std::uint64_t count = (height + lines - 1) / lines;
        const std::vector<std::uint64_t> offsets = offsetTable(count, 8);
        for (std::uint64_t i = 0; i < count; ++i) {
            const std::uint64_t y0 = i * lines, y1 = std::min(height, y0 + lines) - 1;
            const std::string chunk =
                chunkText(i, count) + " (scanlines " + std::to_string(y0) + "-" + std::to_string(y1) + ")";
            const std::uint64_t offset = offsets[static_cast<std::size_t>(i)];
            const std::optional<std::int32_t> y = reader.int32(offset);
            if (!y) fail(file, "file is truncated or incomplete: " + chunk + " is cut short");
            if (*y < 0 || static_cast<std::uint64_t>(*y) != y0)
                fail(file, chunk + " is labelled as starting at scanline " + std::to_string(*y));
            std::uint64_t raw = 0;
            for (const StoredChannel& c : channels) raw += c.rowBytes * sampledRows(y0, y1, c.ySampling);
            checkStoredSize(offset, 1, raw, chunk);
        }
    }

    // Levels of a tiled file in the offset table's order: OpenEXR's level sizes and counts.
    static std::uint64_t levelSize(std::uint64_t size, std::uint64_t level, Imf::LevelRoundingMode mode) {
        const std::uint64_t d = std::uint64_t{1} << level;
        const std::uint64_t s = mode == Imf::ROUND_UP ? (size + d - 1) / d : size / d;
        return std::max<std::uint64_t>(s, 1);
    }
    static std::uint64_t levelCount(std::uint64_t size, Imf::LevelRoundingMode mode) {
        std::uint64_t log = 0;
        while ((std::uint64_t{1} << (log + 1)) <= size) ++log; // floor(log2(size))
        if (mode == Imf::ROUND_UP && (std::uint64_t{1} << log) < size) ++log;
        return log + 1;
    }

    void tiles() {
        const Imf::TileDescription& td = header.tileDescription();
        const std::uint64_t tx = td.xSize, ty = td.ySize; // positive: Header::sanityCheck
        // OpenEXR allocates tile buffers of whole tiles and, reading scanlines, a tile row
        // per channel, whatever the image size; those must be no larger than what the image
        // itself needs (or small).
        constexpr std::uint64_t kSmallBuffers = 32u << 20;
        const std::uint64_t allowed = std::max(kSmallBuffers, 2 * width * height * pixelBytes);
        if (tx * ty * pixelBytes > allowed || ty * width * 4 * channels.size() > allowed)
            fail(file, "tile size " + std::to_string(tx) + "x" + std::to_string(ty) + " is too large for a " +
                           std::to_string(width) + "x" + std::to_string(height) + " image");

        if (td.mode != Imf::ONE_LEVEL && td.mode != Imf::MIPMAP_LEVELS && td.mode != Imf::RIPMAP_LEVELS)
            fail(file, "unknown tile level mode " + std::to_string(static_cast<int>(td.mode)));
        auto tilesOf = [&](std::uint64_t lx, std::uint64_t ly) {
            const std::uint64_t w = levelSize(width, lx, td.roundingMode);
            const std::uint64_t h = levelSize(height, ly, td.roundingMode);
            return ((w + tx - 1) / tx) * ((h + ty - 1) / ty);
        };
        // Chunks of every level, as TileOffsets lays them out: (l, l) for mipmaps, every
        // (lx, ly) for ripmaps.
        std::uint64_t count = 0;
        if (td.mode == Imf::MIPMAP_LEVELS) {
            const std::uint64_t levels = levelCount(std::max(width, height), td.roundingMode);
            for (std::uint64_t l = 0; l < levels; ++l) count += tilesOf(l, l);
        } else {
            const bool rip = td.mode == Imf::RIPMAP_LEVELS;
            const std::uint64_t xLevels = rip ? levelCount(width, td.roundingMode) : 1;
            const std::uint64_t yLevels = rip ? levelCount(height, td.roundingMode) : 1;
            for (std::uint64_t ly = 0; ly < yLevels; ++ly)
                for (std::uint64_t lx = 0; lx < xLevels; ++lx) count += tilesOf(lx, ly);
        }
        const std::vector<std::uint64_t> offsets = offsetTable(count, 20);

        // Level 0 comes first, its tiles row by row; only level 0 is read.
        const std::uint64_t across = (width + tx - 1) / tx, down = (height + ty - 1) / ty;
        for (std::uint64_t i = 0; i < across * down; ++i) {
            const std::uint64_t dx = i % across, dy = i / across;
            const std::string chunk = chunkText(i, count) + " (tile " + std::to_string(dx) + "," +
                                      std::to_string(dy) + " of level 0)";
            const std::uint64_t offset = offsets[static_cast<std::size_t>(i)];
            std::array<std::int32_t, 4> coords{};
            for (std::size_t k = 0; k < coords.size(); ++k) {
                const std::optional<std::int32_t> v = reader.int32(offset + 4 * k);
                if (!v) fail(file, "file is truncated or incomplete: " + chunk + " is cut short");
                coords[k] = *v;
            }
            if (coords[0] < 0 || coords[1] < 0 || static_cast<std::uint64_t>(coords[0]) != dx ||
                static_cast<std::uint64_t>(coords[1]) != dy || coords[2] != 0 || coords[3] != 0)
                fail(file, chunk + " is labelled as tile " + std::to_string(coords[0]) + "," +
                               std::to_string(coords[1]) + " of level " + std::to_string(coords[2]) + "," +
                               std::to_string(coords[3]));
            const std::uint64_t w = std::min(tx, width - dx * tx), h = std::min(ty, height - dy * ty);
            checkStoredSize(offset, 4, w * h * pixelBytes, chunk);
        }
    }
};
} // namespace

std::uint64_t maxCompressionRatio(Imf::Compression compression) {
    // Upper bounds of uncompressed / stored bytes per chunk, from how each codec encodes
    // (OpenEXR stores a chunk uncompressed when compressing would not make it smaller):
    //   RLE: a run of at most 128 equal bytes takes 2 bytes.                         64
    //   ZIP(S): deflate codes a 258-byte match in no fewer than 2 bits.            1032
    //   PIZ: Huffman codes of >= 1 bit, a run of <= 256 values in >= 10 bits.  ~410 -> 512
    //   PXR24: deflate over FLOAT samples cut to 3 bytes (4/3 of deflate's).   1376 -> 1400
    //   B44(A): a 4x4 block of HALF (32 bytes) in no fewer than 3 bytes.        10.7 -> 12
    //   DWAA/DWAB: run-length then deflate (64 x 1032 = 66048); a DCT block of 64 FLOAT
    //   samples (256 bytes) needs at least its deflated 2-byte DC value (132096) and
    //   its Huffman-coded end-of-block mark.                                       2^18
    // Measured with all-zero chunks (the most compressible data) 4096 samples wide:
    // RLE 63.5, ZIP 946, PIZ 400, PXR24 1231, B44A 10.7, DWAB 23302.
    switch (compression) {
    case Imf::NO_COMPRESSION:
        return 1;
    case Imf::RLE_COMPRESSION:
        return 64;
    case Imf::ZIPS_COMPRESSION:
    case Imf::ZIP_COMPRESSION:
        return 1032;
    case Imf::PIZ_COMPRESSION:
        return 512;
    case Imf::PXR24_COMPRESSION:
        return 1400;
    case Imf::B44_COMPRESSION:
    case Imf::B44A_COMPRESSION:
        return 12;
    case Imf::DWAA_COMPRESSION:
    case Imf::DWAB_COMPRESSION:
        return std::uint64_t{1} << 18;
    default:
        return 1;
    }
}

Imf::Header readExrHeader(const std::filesystem::path& file, ExrSize& size, ExrLayout* layout) {
    std::error_code ec;
    const auto status = std::filesystem::status(file, ec);
    if (!std::filesystem::exists(status)) fail(file, "file does not exist");
    if (!std::filesystem::is_regular_file(status)) fail(file, "not a regular file");
    const std::uintmax_t bytes = std::filesystem::file_size(file, ec);
    if (ec) fail(file, "cannot determine the file size: " + ec.message());
    if (bytes < 8)
        fail(file, "not an OpenEXR file (" + std::to_string(bytes) + " bytes, shorter than the preamble)");

    ExrLayout found;
    found.fileBytes = bytes;
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
        // OpenEXR allocates each attribute value at the size its field states before it
        // reads a byte of it; walk the sizes against the file first.
        FileReader reader(file, bytes);
        found.headerEnd = HeaderWalk{file, reader}.run();
        found.tiled = Imf::isTiled(version);
        int readVersion = version;
        header.readFrom(stream, readVersion);
    });
    checkWindows(header, file, size);
    translateErrors(file, "invalid OpenEXR header", [&] { header.sanityCheck(found.tiled); });
    if (layout) *layout = found;
    return header;
}

void checkPixelData(const std::filesystem::path& file, const Imf::Header& header, const ExrLayout& layout) {
    PixelCheck check(file, header, layout);
    if (layout.tiled)
        check.tiles();
    else
        check.scanlines();
}

} // namespace glint::capture
