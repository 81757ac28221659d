// Files that are not readable captures at all: missing, not OpenEXR, truncated, corrupt.
// Each gives one CaptureError line naming the file; none may crash (ASan/UBSan build).
#include "capture/capture_test_support.h"

#include <capture/frame_io.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfMultiPartOutputFile.h>
#include <OpenEXR/ImfPartType.h>
#include <catch2/catch.hpp>

#include <set>

using namespace glint::capture;

namespace {
void requireRejected(const std::filesystem::path& file, const std::string& fragment) {
    const std::string frame = test::captureErrorOf([&] { (void)readFrame(file); });
    INFO(frame);
    CHECK(test::isOneLine(frame));
    CHECK(frame.find(file.filename().string()) != std::string::npos);
    CHECK(frame.find(fragment) != std::string::npos);
    const std::string header = test::captureErrorOf([&] { (void)readFrameHeader(file); });
    INFO(header);
    CHECK(header == frame);
}
} // namespace

TEST_CASE("a nonexistent file is rejected with one line naming the file", "[capture]") {
    const auto dir = test::freshTestDir("malformed_nonexistent");
    requireRejected(dir / "frame_0007.exr", "does not exist");
}

TEST_CASE("a directory is rejected as not a regular file", "[capture]") {
    const auto dir = test::freshTestDir("malformed_directory");
    std::filesystem::create_directories(dir / "frame.exr");
    requireRejected(dir / "frame.exr", "not a regular file");
}

TEST_CASE("files that are not OpenEXR are rejected, whatever their length", "[capture]") {
    const auto dir = test::freshTestDir("malformed_not_exr");
    test::writeBytes(dir / "empty.exr", "");
    requireRejected(dir / "empty.exr", "not an OpenEXR file");
    test::writeBytes(dir / "short.exr", "v/1");
    requireRejected(dir / "short.exr", "not an OpenEXR file");
    test::writeBytes(dir / "text.exr", "this is a text file pretending to be an image\n");
    requireRejected(dir / "text.exr", "not an OpenEXR file");
    test::writeBytes(dir / "png.exr", std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16));
    requireRejected(dir / "png.exr", "not an OpenEXR file");
}

TEST_CASE("an OpenEXR file without glint attributes is rejected as not a glint capture", "[capture]") {
    const auto dir = test::freshTestDir("malformed_plain_exr");
    Imf::Header header(8, 8);
    header.channels().insert("R", Imf::Channel(Imf::HALF));
    test::writeZeroExr(dir / "plain.exr", header);
    requireRejected(dir / "plain.exr", "missing attribute 'glint.formatVersion' (not a glint frame capture)");
}

TEST_CASE("a multi-part OpenEXR file is rejected", "[capture]") {
    const auto dir = test::freshTestDir("malformed_multipart");
    std::vector<Imf::Header> headers(2, Imf::Header(4, 4));
    for (std::size_t i = 0; i < headers.size(); ++i) {
        headers[i].setName("part" + std::to_string(i));
        headers[i].setType(Imf::SCANLINEIMAGE);
        headers[i].channels().insert("depth.Z", Imf::Channel(Imf::FLOAT));
    }
    { Imf::MultiPartOutputFile out((dir / "multi.exr").c_str(), headers.data(), 2); }
    requireRejected(dir / "multi.exr", "multi-part");
}

TEST_CASE("a truncated file is rejected with one line naming the file at every truncation point",
          "[capture]") {
    const auto dir = test::freshTestDir("malformed_truncated");
    const auto valid = dir / "valid.exr";
    writeFrame(valid, test::makeFullFrame(40, 37)); // several ZIP chunks of 16 scanlines
    const std::string bytes = test::readBytes(valid);
    REQUIRE(bytes.size() > 2000);

    std::set<std::size_t> cuts{0, 3, 4, 7, 8, 9, 12, 40, 100, 333, bytes.size() - 1, bytes.size() - 8};
    for (std::size_t cut = 0; cut < bytes.size(); cut += bytes.size() / 97 + 1) cuts.insert(cut);
    const auto file = dir / "frame_0003.exr";
    std::size_t headerStillReadable = 0;
    for (std::size_t cut : cuts) {
        INFO("truncated to " << cut << " of " << bytes.size() << " bytes");
        test::writeBytes(file, bytes.substr(0, cut));
        const std::string message = test::captureErrorOf([&] { (void)readFrame(file); });
        INFO(message);
        CHECK(test::isOneLine(message));
        CHECK(message.rfind(file.string() + ": ", 0) == 0);
        const std::string header = test::captureErrorOf([&] { (void)readFrameHeader(file); });
        if (header == "NO ERROR")
            ++headerStillReadable; // cut after the header: only pixels are lost
        else
            CHECK((test::isOneLine(header) && header.find("frame_0003.exr") != std::string::npos));
    }
    CHECK(headerStillReadable > 0); // the sweep reached the pixel data
}

TEST_CASE("a file with corrupted bytes never crashes the reader", "[capture]") {
    const auto dir = test::freshTestDir("malformed_corrupt");
    const auto valid = dir / "valid.exr";
    writeFrame(valid, test::makeFullFrame(24, 20));
    const std::string bytes = test::readBytes(valid);
    const auto file = dir / "corrupt.exr";
    std::size_t rejected = 0, tried = 0;
    for (std::size_t at = 8; at < bytes.size(); at += bytes.size() / 61 + 1) {
        std::string corrupt = bytes;
        for (std::size_t i = at; i < std::min(at + 4, corrupt.size()); ++i)
            corrupt[i] = static_cast<char>(~corrupt[i]);
        test::writeBytes(file, corrupt);
        const std::string message = test::captureErrorOf([&] { (void)readFrame(file); });
        ++tried;
        if (message == "NO ERROR") continue; // damage OpenEXR cannot detect loads as different samples
        INFO(message);
        CHECK(message.rfind("OTHER EXCEPTION", 0) != 0);
        CHECK(test::isOneLine(message));
        CHECK(message.find("corrupt.exr") != std::string::npos);
        ++rejected;
    }
    CHECK(rejected > tried / 4);
}
