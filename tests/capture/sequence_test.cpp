#include "capture/capture_test_support.h"

#include <capture/frame_io.h>
#include <capture/sample_frame.h>
#include <capture/sequence_io.h>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

using namespace glint::capture;

namespace {
std::vector<Frame> sampleFrames(std::uint32_t count, std::uint32_t w = 16, std::uint32_t h = 12) {
    std::vector<Frame> frames;
    for (std::uint32_t i = 0; i < count; ++i) frames.push_back(makeSampleFrame(w, h, i));
    return frames;
}

std::string sequenceError(const std::filesystem::path& path) {
    const std::string message = test::captureErrorOf([&] { (void)readSequence(path); });
    CHECK(test::isOneLine(message));
    return message;
}
} // namespace

TEST_CASE("a written sequence reads back with its manifest, headers and lazily loaded frames", "[capture]") {
    const auto dir = test::freshTestDir("sequence_round_trip") / "seq";
    const std::vector<Frame> frames = sampleFrames(3);
    const Environment env = makeSampleEnvironment(8, 4);
    writeSequence(dir, frames, 24.0, &env);

    const nlohmann::json manifest = nlohmann::json::parse(test::readBytes(dir / "manifest.json"));
    CHECK(manifest["format"] == "glint-sequence");
    CHECK(manifest["version"] == 1);
    CHECK(manifest["frames"] == nlohmann::json({"frame_0000.exr", "frame_0001.exr", "frame_0002.exr"}));
    CHECK(manifest["frameRate"] == 24.0);
    CHECK(manifest["environment"] == "environment.exr");

    const Sequence seq = readSequence(dir);
    CHECK(seq.frameRate == 24.0);
    REQUIRE(seq.frameFiles.size() == 3);
    REQUIRE(seq.headers.size() == 3);
    CHECK(seq.headers[2].frameIndex == 2);
    CHECK(seq.headers[1].width == 16);
    const Frame second = loadFrame(seq, 1);
    CHECK(findLayer(second, "depth")->pixels == findLayer(frames[1], "depth")->pixels);
    const auto environment = loadEnvironment(seq);
    REQUIRE(environment.has_value());
    CHECK(environment->rgb == env.rgb);
    // The manifest itself may be given instead of its folder.
    CHECK(readSequence(dir / "manifest.json").frameFiles == seq.frameFiles);
}

TEST_CASE("a sequence without an environment map has none", "[capture]") {
    const auto dir = test::freshTestDir("sequence_no_environment");
    writeSequence(dir, sampleFrames(1), 30.0);
    const Sequence seq = readSequence(dir);
    CHECK(seq.environment.empty());
    CHECK_FALSE(loadEnvironment(seq).has_value());
}

TEST_CASE("a manifest referencing a missing frame is rejected naming the frame", "[capture]") {
    const auto dir = test::freshTestDir("sequence_missing_frame");
    writeSequence(dir, sampleFrames(3), 30.0);
    std::filesystem::remove(dir / "frame_0001.exr");
    const std::string message = sequenceError(dir);
    CHECK_THAT(message, Catch::Contains("manifest.json: frame 'frame_0001.exr' does not exist"));
}

TEST_CASE("frames of different sizes in one sequence are rejected", "[capture]") {
    const auto dir = test::freshTestDir("sequence_mismatched_sizes");
    writeSequence(dir, sampleFrames(2), 30.0);
    writeFrame(dir / "frame_0001.exr", makeSampleFrame(8, 6, 1));
    CHECK_THAT(sequenceError(dir),
               Catch::Contains("frame_0001.exr: size 8x6 differs from the sequence's 16x12"));

    std::vector<Frame> mixed = sampleFrames(1);
    mixed.push_back(makeSampleFrame(8, 6, 1));
    const auto other = test::freshTestDir("sequence_mismatched_sizes_write");
    CHECK_THAT(test::captureErrorOf([&] { writeSequence(other, mixed, 30.0); }), Catch::Contains("differs"));
    CHECK_FALSE(std::filesystem::exists(other / "manifest.json"));
}

TEST_CASE("a malformed or invalid manifest is rejected with one line naming it", "[capture]") {
    const auto dir = test::freshTestDir("sequence_bad_manifest");
    writeSequence(dir, sampleFrames(1), 30.0);
    const auto manifest = dir / "manifest.json";
    struct Case {
        std::string text, expected;
    };
    const std::vector<Case> cases{
        {"{\"format\": \"glint-sequence\", \"version\": 1,\n \"frames\": [\"frame_0000.exr\"",
         "malformed JSON"},
        {"", "malformed JSON"},
        {"[1, 2]", "must be a JSON object"},
        {R"({"format": "other", "version": 1, "frames": ["frame_0000.exr"], "frameRate": 30})",
         "key 'format'"},
        {R"({"format": "glint-sequence", "version": 2, "frames": ["frame_0000.exr"], "frameRate": 30})",
         "unsupported manifest version 2"},
        {R"({"format": "glint-sequence", "version": 1, "frames": "frame_0000.exr", "frameRate": 30})",
         "key 'frames' must be a non-empty array"},
        {R"({"format": "glint-sequence", "version": 1, "frames": [], "frameRate": 30})", "non-empty array"},
        {R"({"format": "glint-sequence", "version": 1, "frames": [7], "frameRate": 30})", "only strings"},
        {R"({"format": "glint-sequence", "version": 1, "frames": ["frame_0000.exr"]})", "key 'frameRate'"},
        {R"({"format": "glint-sequence", "version": 1, "frames": ["frame_0000.exr"], "frameRate": -1})",
         "positive number"},
        {R"({"format": "glint-sequence", "version": 1, "frames": ["../frame_0000.exr"], "frameRate": 30})",
         "not a relative path inside the sequence folder"},
        {R"({"format": "glint-sequence", "version": 1, "frames": ["frame_0000.exr", "frame_0000.exr"], "frameRate": 30})",
         "listed twice"},
        {R"({"format": "glint-sequence", "version": 1, "frames": ["frame_0000.exr"], "frameRate": 30, "environment": "sky.exr"})",
         "environment 'sky.exr' does not exist"},
    };
    for (const Case& c : cases) {
        INFO(c.text);
        test::writeBytes(manifest, c.text);
        const std::string message = sequenceError(dir);
        CHECK_THAT(message, Catch::StartsWith(manifest.string() + ": "));
        CHECK_THAT(message, Catch::Contains(c.expected));
    }
}

TEST_CASE("JSON errors in a manifest read without the JSON library's exception codes", "[capture]") {
    const auto dir = test::freshTestDir("sequence_json_words");
    writeSequence(dir, sampleFrames(1), 30.0);
    const auto manifest = dir / "manifest.json";
    // A number beyond the largest double (about 1.8e308) is named with its line.
    test::writeBytes(manifest,
                     "{\"format\": \"glint-sequence\", \"version\": 1,\n\"frames\": [\"frame_0000.exr\"],\n"
                     "\"frameRate\": 1e999}");
    CHECK(sequenceError(dir) ==
          manifest.string() +
              ": malformed JSON: line 3: the number 1e999 is too large for a double (beyond 1.8e308)");
    test::writeBytes(manifest, "{\"frameRate\": -2e400}");
    CHECK(sequenceError(dir) ==
          manifest.string() + ": malformed JSON: line 1: the number -2e400 is too large for a double (beyond "
                              "1.8e308)");
    // Syntax errors keep the library's position and description, without its code.
    test::writeBytes(manifest, "{\"format\": nope}");
    const std::string syntax = sequenceError(dir);
    CHECK_THAT(syntax, Catch::StartsWith(manifest.string() + ": malformed JSON: line 1, column "));
    CHECK_THAT(syntax, !Catch::Contains("json.exception"));
    CHECK_THAT(syntax, !Catch::Contains("parse error at"));
}

TEST_CASE("a folder without a manifest is rejected", "[capture]") {
    const auto dir = test::freshTestDir("sequence_no_manifest");
    CHECK_THAT(sequenceError(dir), Catch::Contains("manifest.json: file does not exist"));
}

TEST_CASE("a broken frame inside a sequence is reported with the frame's own file name", "[capture]") {
    const auto dir = test::freshTestDir("sequence_broken_frame");
    writeSequence(dir, sampleFrames(2), 30.0);
    test::writeBytes(dir / "frame_0001.exr", "garbage, not an image");
    CHECK_THAT(sequenceError(dir), Catch::Contains("frame_0001.exr: not an OpenEXR file"));
}
