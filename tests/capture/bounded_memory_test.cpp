// Memory a file makes the readers allocate is bounded by what the file can hold (issue 24):
// attribute sizes are checked against the bytes left before OpenEXR reads a value, and the
// pixel data a header declares against the chunk table and chunk sizes before any layer is
// allocated. Each hostile file is a few KB; each rejection must be one line naming the file
// and the problem, with the peak resident size of the process barely moving (a 2 GiB
// zero-fill, the old behaviour, shows as gigabytes there, with or without ASan).
//
// The files are edited at the byte level, so this test walks the OpenEXR layout itself
// (magic, version, attributes up to an empty name, the offset table, chunks of
// y/size/data) rather than asking the reader under test where things are.
#include "capture/capture_test_support.h"

#include <capture/channel_map.h>
#include <capture/environment_io.h>
#include <capture/frame_io.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfStringVectorAttribute.h>
#include <OpenEXR/ImfTiledOutputFile.h>
#include <catch2/catch.hpp>

#include <cstring>
#include <fstream>

using namespace glint::capture;
namespace fs = std::filesystem;

namespace {
constexpr std::uint64_t kMiB = 1u << 20;

// VmHWM (peak resident set) of this process, in bytes.
std::uint64_t peakResidentBytes() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("VmHWM:", 0) == 0) return std::stoull(line.substr(6)) * 1024;
    return 0;
}

// Runs `read` and returns its CaptureError message; checks that it is one line naming the
// file and that the peak resident size grew by less than 64 MiB meanwhile. Writing "5" to
// clear_refs resets VmHWM to the current resident size first (Linux >= 4.0), so earlier
// tests' peaks cannot hide an allocation.
std::string boundedRejection(const fs::path& file, const std::function<void()>& read) {
    { std::ofstream("/proc/self/clear_refs") << "5"; }
    const std::uint64_t before = peakResidentBytes();
    const std::string message = test::captureErrorOf(read);
    const std::uint64_t after = peakResidentBytes();
    INFO(message);
    CHECK(test::isOneLine(message));
    CHECK(message.rfind(file.string() + ": ", 0) == 0);
    CHECK(before > 0);
    CHECK(after - before < 64 * kMiB);
    return message;
}

std::uint32_t le32(const std::string& b, std::size_t at) {
    std::uint32_t v = 0;
    for (std::size_t i = 0; i < 4; ++i) v |= std::uint32_t{static_cast<unsigned char>(b[at + i])} << (8 * i);
    return v;
}
std::uint64_t le64(const std::string& b, std::size_t at) {
    return le32(b, at) | (std::uint64_t{le32(b, at + 4)} << 32);
}
void put32(std::string& b, std::size_t at, std::uint32_t v) {
    for (std::size_t i = 0; i < 4; ++i) b[at + i] = static_cast<char>((v >> (8 * i)) & 0xff);
}
void put64(std::string& b, std::size_t at, std::uint64_t v) {
    put32(b, at, static_cast<std::uint32_t>(v));
    put32(b, at + 4, static_cast<std::uint32_t>(v >> 32));
}
std::string bytes32(std::uint32_t v) {
    std::string b(4, '\0');
    put32(b, 0, v);
    return b;
}
std::string bytes64(std::uint64_t v) {
    std::string b(8, '\0');
    put64(b, 0, v);
    return b;
}

struct Attribute {
    std::string name, type;
    std::size_t sizeAt = 0; // offset of the size field; the value follows it
};

// The attributes of a single-part file and the offset just past the header.
std::vector<Attribute> attributesOf(const std::string& b, std::size_t& headerEnd) {
    std::vector<Attribute> out;
    std::size_t at = 8;
    auto name = [&] {
        const std::size_t end = b.find('\0', at);
        REQUIRE(end != std::string::npos);
        std::string text = b.substr(at, end - at);
        at = end + 1;
        return text;
    };
    for (;;) {
        Attribute a;
        a.name = name();
        if (a.name.empty()) break;
        a.type = name();
        a.sizeAt = at;
        at += 4 + le32(b, at);
        out.push_back(a);
    }
    headerEnd = at;
    return out;
}

Attribute attributeNamed(const std::string& b, const std::string& name) {
    std::size_t end = 0;
    for (const Attribute& a : attributesOf(b, end))
        if (a.name == name) return a;
    FAIL("no attribute " << name);
    return {};
}

std::size_t headerEndOf(const std::string& b) {
    std::size_t end = 0;
    (void)attributesOf(b, end);
    return end;
}

// A valid header of the given size with exactly the 8 channels depth.Z, color.RGBA and
// normal.XYZ (24 bytes per pixel) declaring depth_pyramid.
Imf::Header eightChannelHeader(const fs::path& dir, int width, int height, Imf::Compression compression) {
    Imf::Header header = test::validFrameHeader(dir, 16, 8);
    header.dataWindow() = Imath::Box2i({0, 0}, {width - 1, height - 1});
    header.displayWindow() = header.dataWindow();
    header.compression() = compression;
    header.channels() = Imf::ChannelList();
    header.channels().insert("depth.Z", Imf::Channel(Imf::FLOAT));
    for (const char* c : {"color.R", "color.G", "color.B", "color.A"})
        header.channels().insert(c, Imf::Channel(Imf::HALF));
    for (const char* c : {"normal.X", "normal.Y", "normal.Z"})
        header.channels().insert(c, Imf::Channel(Imf::FLOAT));
    header.insert("glint.effects", Imf::StringVectorAttribute({"depth_pyramid"}));
    header.insert("glint.roughnessSource", Imf::StringAttribute(""));
    return header;
}

// The preamble and `header` only, as bytes.
std::string headerOnlyBytes(const fs::path& scratch, const Imf::Header& header) {
    test::writeHeaderOnlyExr(scratch, header);
    return test::readBytes(scratch);
}

// `header`, a complete offset table and `chunks` scanline chunks of `chunkBytes` bytes each
// (labelled with the right first scanline): every structure is in place but the chunks
// hold far less than the scanlines they claim.
std::string starvedScanlineFile(const fs::path& scratch, const Imf::Header& header, std::uint32_t chunks,
                                std::uint32_t linesPerChunk, std::uint32_t chunkBytes) {
    std::string b = headerOnlyBytes(scratch, header);
    const std::uint64_t dataStart = b.size() + 8ull * chunks;
    for (std::uint32_t i = 0; i < chunks; ++i) b += bytes64(dataStart + std::uint64_t{i} * (8 + chunkBytes));
    for (std::uint32_t i = 0; i < chunks; ++i)
        b += bytes32(i * linesPerChunk) + bytes32(chunkBytes) + std::string(chunkBytes, '\x5a');
    return b;
}

// Locations in a valid single-part scanline file written by OpenEXR.
struct ScanlineLayout {
    std::size_t tableAt = 0;
    std::vector<std::uint64_t> offsets;
};
ScanlineLayout scanlineLayout(const std::string& b, std::size_t chunks) {
    ScanlineLayout l;
    l.tableAt = headerEndOf(b);
    for (std::size_t i = 0; i < chunks; ++i) l.offsets.push_back(le64(b, l.tableAt + 8 * i));
    return l;
}

void writeZeroEnvironment(const fs::path& file, int width, int height, Imf::Compression compression,
                          Imf::LineOrder order = Imf::INCREASING_Y, bool subsampledExtra = false) {
    Imf::Header header(width, height);
    header.compression() = compression;
    header.lineOrder() = order;
    Imf::addEnvmap(header, Imf::ENVMAP_LATLONG);
    for (const char* c : {"R", "G", "B"}) header.channels().insert(c, Imf::Channel(Imf::FLOAT));
    if (subsampledExtra) header.channels().insert("Y", Imf::Channel(Imf::HALF, 2, 2));
    test::writeZeroExr(file, header);
}

void writeZeroTiledEnvironment(const fs::path& file, int width, int height, Imf::TileDescription tiles) {
    Imf::Header header(width, height);
    header.compression() = Imf::ZIP_COMPRESSION;
    header.setTileDescription(tiles);
    Imf::addEnvmap(header, Imf::ENVMAP_LATLONG);
    for (const char* c : {"R", "G", "B"}) header.channels().insert(c, Imf::Channel(Imf::HALF));
    Imf::TiledOutputFile out(file.c_str(), header);
    out.setFrameBuffer(Imf::FrameBuffer{}); // zeros
    for (int ly = 0; ly < out.numYLevels(); ++ly)
        for (int lx = 0; lx < out.numXLevels(); ++lx) {
            if (tiles.mode == Imf::MIPMAP_LEVELS && lx != ly) continue;
            out.writeTiles(0, out.numXTiles(lx) - 1, 0, out.numYTiles(ly) - 1, lx, ly);
        }
}
} // namespace

TEST_CASE("a string attribute whose size field says 0x7fffffff is rejected before it is read",
          "[capture][bounded]") {
    const auto dir = test::freshTestDir("bounded_string_attribute");
    Imf::Header header = test::validFrameHeader(dir, 16, 8);
    header.insert("glint.comment", Imf::StringAttribute("a short note"));
    const fs::path valid = dir / "valid.exr";
    test::writeZeroExr(valid, header);
    std::string b = test::readBytes(valid);
    REQUIRE(b.size() < 8000); // a few KB, like the file of the issue
    put32(b, attributeNamed(b, "glint.comment").sizeAt, 0x7fffffffu);
    const fs::path file = dir / "frame_0000.exr";
    test::writeBytes(file, b);

    const std::string expected = "attribute 'glint.comment' (string) declares 2147483647 bytes but only ";
    CHECK_THAT(boundedRejection(file, [&] { (void)readFrame(file); }), Catch::Contains(expected));
    CHECK_THAT(boundedRejection(file, [&] { (void)readFrameHeader(file); }), Catch::Contains(expected));
    CHECK_THAT(boundedRejection(file, [&] { (void)readEnvironment(file); }), Catch::Contains(expected));
    CHECK_THAT(boundedRejection(file, [&] { (void)readFrame(file); }), Catch::Contains("remain in the file"));
}

TEST_CASE("attribute sizes that OpenEXR would read differently from the file are rejected",
          "[capture][bounded]") {
    const auto dir = test::freshTestDir("bounded_attribute_sizes");
    const fs::path valid = dir / "valid.exr";
    test::writeZeroExr(valid, test::validFrameHeader(dir, 16, 8));
    const std::string good = test::readBytes(valid);
    const fs::path file = dir / "edited.exr";
    struct Case {
        const char* attribute;
        std::uint32_t size;
        const char* expected;
    };
    for (const Case& c : {
             Case{"glint.frameIndex", 0x40000000u,
                  "attribute 'glint.frameIndex' (int) declares 1073741824 bytes"},
             Case{"glint.frameIndex", 0u,
                  "attribute 'glint.frameIndex' (int) has size 0; a int value takes 4"},
             Case{"glint.near", 0xfffffff0u, "attribute 'glint.near' (double) has a negative size (-16)"},
             Case{"channels", 7u, "attribute 'channels' (chlist) declares 7 bytes but its channels take"},
             Case{"glint.effects", 0x7fffffffu,
                  "attribute 'glint.effects' (stringvector) declares 2147483647"},
         }) {
        INFO(c.attribute << " size " << c.size);
        std::string b = good;
        put32(b, attributeNamed(b, c.attribute).sizeAt, c.size);
        test::writeBytes(file, b);
        CHECK_THAT(boundedRejection(file, [&] { (void)readFrame(file); }), Catch::Contains(c.expected));
    }
    // A header cut inside an attribute name is truncated, not an unterminated name.
    const std::size_t cut = good.find("glint.near") + 4;
    test::writeBytes(file, good.substr(0, cut));
    CHECK_THAT(boundedRejection(file, [&] { (void)readFrameHeader(file); }),
               Catch::Contains("file is truncated inside its header"));
}

TEST_CASE("an 8192x8192 frame of 8 channels without pixel data is rejected before its layers are allocated",
          "[capture][bounded]") {
    const auto dir = test::freshTestDir("bounded_missing_pixels");
    const fs::path scratch = dir / "scratch.exr";
    const fs::path file = dir / "frame_0000.exr";
    const Imf::Header zip = eightChannelHeader(dir, 8192, 8192, Imf::ZIP_COMPRESSION);
    // The layers alone would be 8192 x 8192 x 8 floats = 2 GiB; the header is valid.
    REQUIRE(test::captureErrorOf([&] {
                test::writeHeaderOnlyExr(file, zip);
                (void)readFrameHeader(file);
            }) == "NO ERROR");

    SECTION("the header alone, without an offset table") {
        test::writeBytes(file, headerOnlyBytes(scratch, zip));
        REQUIRE(fs::file_size(file) < 8000);
        CHECK_THAT(boundedRejection(file, [&] { (void)readFrame(file); }),
                   Catch::Contains("file is truncated or incomplete: its offset table of 512 chunks does not "
                                   "fit in the"));
    }
    SECTION("an offset table of zeros (never written)") {
        test::writeBytes(file, headerOnlyBytes(scratch, zip) + std::string(512 * 8, '\0'));
        CHECK_THAT(boundedRejection(file, [&] { (void)readFrame(file); }),
                   Catch::Contains("file is truncated or incomplete: chunk 0 of 512 was never written"));
    }
    SECTION("every ZIP chunk present but 4 bytes long") {
        test::writeBytes(file, starvedScanlineFile(scratch, zip, 512, 16, 4));
        REQUIRE(fs::file_size(file) < 20000);
        // 16 lines x 8192 pixels x 24 bytes = 3 MiB per chunk; 4 bytes of deflate cannot hold it.
        CHECK_THAT(boundedRejection(file, [&] { (void)readFrame(file); }),
                   Catch::Contains("chunk 0 of 512 (scanlines 0-15) stores 4 bytes, too few for the 3145728 "
                                   "bytes it must decode to: ZIP compression reaches at most 1032:1"));
    }
    SECTION("uncompressed chunks shorter than their scanlines") {
        const Imf::Header none = eightChannelHeader(dir, 8192, 8192, Imf::NO_COMPRESSION);
        test::writeBytes(file, starvedScanlineFile(scratch, none, 8192, 1, 4));
        CHECK_THAT(boundedRejection(file, [&] { (void)readFrame(file); }),
                   Catch::Contains("uncompressed chunk 0 of 8192 (scanlines 0-0) stores 4 bytes; its "
                                   "8192-pixel-wide data needs exactly 196608"));
    }
    SECTION("the same through the environment and channel-map readers") {
        Imf::Header env(8192, 4096);
        env.compression() = Imf::PIZ_COMPRESSION;
        Imf::addEnvmap(env, Imf::ENVMAP_LATLONG);
        for (const char* c : {"R", "G", "B"}) env.channels().insert(c, Imf::Channel(Imf::FLOAT));
        test::writeBytes(file, starvedScanlineFile(scratch, env, 128, 32, 16));
        CHECK_THAT(boundedRejection(file, [&] { (void)readEnvironment(file); }),
                   Catch::Contains("chunk 0 of 128 (scanlines 0-31) stores 16 bytes, too few"));

        Imf::Header blender(8192, 8192);
        blender.compression() = Imf::DWAA_COMPRESSION;
        for (const char* c :
             {"ViewLayer.Combined.R", "ViewLayer.Combined.G", "ViewLayer.Combined.B", "ViewLayer.Combined.A",
              "ViewLayer.Depth.Z", "ViewLayer.Normal.X", "ViewLayer.Normal.Y", "ViewLayer.Normal.Z",
              "ViewLayer.roughness.X", "ViewLayer.Vector.X", "ViewLayer.Vector.Y"})
            blender.channels().insert(c, Imf::Channel(Imf::FLOAT));
        test::writeBytes(file, starvedScanlineFile(scratch, blender, 256, 32, 16));
        const ChannelMap map = loadChannelMap(std::string(GLINT_SOURCE_DIR) + "/harness/maps/blender.toml");
        CHECK_THAT(
            boundedRejection(file, [&] { (void)readMappedFrame(file.string(), map, 0); }),
            Catch::Contains("chunk 0 of 256 (scanlines 0-31) stores 16 bytes, too few for the 11534336 "
                            "bytes it must decode to: DWAA compression reaches at most 262144:1"));
    }
}

TEST_CASE("a chunk table entry or chunk that does not fit the file is named", "[capture][bounded]") {
    const auto dir = test::freshTestDir("bounded_chunks");
    const fs::path valid = dir / "valid.exr";
    writeFrame(valid, test::makeFullFrame(40, 37)); // ZIP: 3 chunks of 16 scanlines
    const std::string good = test::readBytes(valid);
    const ScanlineLayout layout = scanlineLayout(good, 3);
    const fs::path file = dir / "frame_0002.exr";
    auto rejected = [&](const std::string& bytes) {
        test::writeBytes(file, bytes);
        return boundedRejection(file, [&] { (void)readFrame(file); });
    };
    std::string b = good;
    put64(b, layout.tableAt + 8, good.size() + 100);
    CHECK_THAT(rejected(b),
               Catch::Contains("chunk 1 of 3 starts at byte " + std::to_string(good.size() + 100) +
                               ", outside the pixel data of the"));
    b = good;
    put64(b, layout.tableAt + 8, 0);
    CHECK_THAT(rejected(b), Catch::Contains("chunk 1 of 3 was never written"));
    b = good;
    put64(b, layout.tableAt + 8, layout.tableAt); // inside the table itself
    CHECK_THAT(rejected(b), Catch::Contains("chunk 1 of 3 starts at byte"));
    b = good;
    put32(b, static_cast<std::size_t>(layout.offsets[1]), 5);
    CHECK_THAT(rejected(b),
               Catch::Contains("chunk 1 of 3 (scanlines 16-31) is labelled as starting at scanline 5"));
    b = good;
    put32(b, static_cast<std::size_t>(layout.offsets[2]) + 4, 0x7ffffff0u);
    CHECK_THAT(rejected(b),
               Catch::Contains("chunk 2 of 3 (scanlines 32-36) declares 2147483632 bytes but only"));
    CHECK_THAT(rejected(good.substr(0, static_cast<std::size_t>(layout.offsets[2]) + 3)),
               Catch::Contains("file is truncated or incomplete: chunk 2 of 3 starts at byte"));
    CHECK(test::captureErrorOf([&] { (void)readFrame(valid); }) == "NO ERROR");
}

TEST_CASE("files at the best compression each method reaches are still read", "[capture][bounded]") {
    const auto dir = test::freshTestDir("bounded_best_compression");
    // All-zero samples compress the most; 1024 wide, 512 high: whole DWAB chunks of 256 lines.
    for (const Imf::Compression c :
         {Imf::NO_COMPRESSION, Imf::RLE_COMPRESSION, Imf::ZIPS_COMPRESSION, Imf::ZIP_COMPRESSION,
          Imf::PIZ_COMPRESSION, Imf::PXR24_COMPRESSION, Imf::B44_COMPRESSION, Imf::B44A_COMPRESSION,
          Imf::DWAA_COMPRESSION, Imf::DWAB_COMPRESSION}) {
        INFO("compression " << static_cast<int>(c));
        const fs::path file = dir / ("zero_" + std::to_string(static_cast<int>(c)) + ".exr");
        writeZeroEnvironment(file, 1024, 512, c);
        Environment env;
        REQUIRE(test::captureErrorOf([&] { env = readEnvironment(file); }) == "NO ERROR");
        CHECK(env.rgb.size() == 1024u * 512u * 3u);
        CHECK(std::all_of(env.rgb.begin(), env.rgb.end(), [](float v) { return v == 0.0f; }));
        // Frames too, with every layer kind and HALF and FLOAT storage.
        Imf::Header frame = test::validFrameHeader(dir, 48, 40);
        frame.compression() = c;
        test::writeZeroExr(dir / "frame.exr", frame);
        CHECK(test::captureErrorOf([&] { (void)readFrame(dir / "frame.exr"); }) == "NO ERROR");
    }
    SECTION("decreasing line order and a subsampled extra channel") {
        writeZeroEnvironment(dir / "decreasing.exr", 64, 40, Imf::ZIP_COMPRESSION, Imf::DECREASING_Y, true);
        CHECK(test::captureErrorOf([&] { (void)readEnvironment(dir / "decreasing.exr"); }) == "NO ERROR");
        writeZeroEnvironment(dir / "subsampled.exr", 64, 40, Imf::NO_COMPRESSION, Imf::INCREASING_Y, true);
        CHECK(test::captureErrorOf([&] { (void)readEnvironment(dir / "subsampled.exr"); }) == "NO ERROR");
    }
    SECTION("tiled files, one level, mipmaps and ripmaps, tiles larger than the image") {
        struct Tiled {
            int width, height;
            Imf::TileDescription tiles;
        };
        for (const Tiled& t :
             {Tiled{100, 60, Imf::TileDescription(32, 16, Imf::ONE_LEVEL)},
              Tiled{100, 60, Imf::TileDescription(32, 32, Imf::MIPMAP_LEVELS, Imf::ROUND_DOWN)},
              Tiled{100, 60, Imf::TileDescription(16, 16, Imf::MIPMAP_LEVELS, Imf::ROUND_UP)},
              Tiled{100, 60, Imf::TileDescription(16, 8, Imf::RIPMAP_LEVELS, Imf::ROUND_UP)},
              Tiled{10, 6, Imf::TileDescription(64, 64, Imf::ONE_LEVEL)}}) {
            INFO(t.width << "x" << t.height << " tiles " << t.tiles.xSize << "x" << t.tiles.ySize << " mode "
                         << t.tiles.mode);
            writeZeroTiledEnvironment(dir / "tiled.exr", t.width, t.height, t.tiles);
            CHECK(test::captureErrorOf([&] { (void)readEnvironment(dir / "tiled.exr"); }) == "NO ERROR");
        }
    }
}

TEST_CASE("tiles far larger than the image are rejected before OpenEXR allocates them",
          "[capture][bounded]") {
    const auto dir = test::freshTestDir("bounded_tiles");
    const fs::path file = dir / "environment.exr";
    Imf::Header header(4, 4);
    header.setTileDescription(Imf::TileDescription(8192, 8192, Imf::ONE_LEVEL));
    Imf::addEnvmap(header, Imf::ENVMAP_LATLONG);
    for (const char* c : {"R", "G", "B"}) header.channels().insert(c, Imf::Channel(Imf::FLOAT));
    std::string b = headerOnlyBytes(dir / "scratch.exr", header);
    b[5] = static_cast<char>(b[5] | 0x02); // version flags: single-part tiled
    b += bytes64(b.size() + 8) + bytes32(0) + bytes32(0) + bytes32(0) + bytes32(0) + bytes32(4) + "abcd";
    test::writeBytes(file, b);
    CHECK_THAT(boundedRejection(file, [&] { (void)readEnvironment(file); }),
               Catch::Contains("tile size 8192x8192 is too large for a 4x4 image"));
}
