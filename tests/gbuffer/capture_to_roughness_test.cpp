// The whole path once: a capture file on disk, read by the capture library, its material
// layer uploaded, roughness extracted by the Vulkan pass, read back and compared with the
// CPU reference applied to the values the file holds.
#include "gbuffer/roughness_runner.h"
#include "reference/roughness_reference.h"
#include "support/gpu_test_context.h"

#include <capture/frame_io.h>
#include <capture/sample_frame.h>
#include <replay/replay_session.h>

#include <catch2/catch.hpp>

#include <cfloat>
#include <filesystem>

using namespace glint;

TEST_CASE("roughness from a capture file's material layer matches the CPU reference", "[gbuffer][e2e]") {
    const std::filesystem::path dir = std::filesystem::path(GLINT_TEST_OUTPUT_DIR) / "capture_to_roughness";
    std::filesystem::create_directories(dir);
    const std::filesystem::path file = dir / "frame.exr";
    capture::writeFrame(file, capture::makeSampleFrame(37, 23, 1));

    const capture::Frame frame = capture::readFrame(file);
    const capture::Layer* material = capture::findLayer(frame, frame.roughness.layer);
    REQUIRE(material != nullptr);
    const int channel = capture::channelIndex(material->channels, frame.roughness.channel);
    REQUIRE(channel >= 0);
    REQUIRE(material->channels.size() <= 4);

    // The pass reads RGBA; unused channels are zero.
    const std::size_t pixels = std::size_t{frame.width} * frame.height;
    const std::size_t stride = material->channels.size();
    std::vector<float> rgba(pixels * 4, 0.0f);
    for (std::size_t p = 0; p < pixels; ++p)
        for (std::size_t c = 0; c < stride; ++c) rgba[p * 4 + c] = material->pixels[p * stride + c];

    RoughnessExtractionDesc desc;
    desc.size = {frame.width, frame.height};
    desc.materialChannel = static_cast<uint32_t>(channel);
    desc.inputIsPerceptual = frame.roughness.perceptual;
    const test::RoughnessRun run = test::runRoughnessExtraction(test::testContext(), rgba, desc);

    const std::vector<float> expected = reference::extractRoughness(
        material->pixels, stride, static_cast<std::size_t>(channel), frame.roughness.perceptual);
    REQUIRE(run.alpha.size() == expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        INFO("pixel " << i);
        if (expected[i] < FLT_MIN && run.alpha[i] == 0.0f) continue; // denormals may flush
        REQUIRE(run.alpha[i] == expected[i]);
    }
    // The sample varies roughness across the image; a constant output would mean the wrong channel.
    CHECK(*std::max_element(expected.begin(), expected.end()) >
          *std::min_element(expected.begin(), expected.end()));
    if (test::testContext().device.timestamps) CHECK(run.dispatchMs >= 0.0);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("the roughness effect replayed through its descriptor matches the CPU reference",
          "[gbuffer][e2e]") {
    const std::filesystem::path dir = std::filesystem::path(GLINT_TEST_OUTPUT_DIR) / "roughness_effect";
    std::filesystem::create_directories(dir);
    const std::filesystem::path file = dir / "frame.exr";
    capture::writeFrame(file, capture::makeSampleFrame(29, 17, 1));
    const capture::Frame frame = capture::readFrame(file);
    const capture::Layer* material = capture::findLayer(frame, frame.roughness.layer);
    REQUIRE(material != nullptr);
    const int channel = capture::channelIndex(material->channels, frame.roughness.channel);
    REQUIRE(channel >= 0);

    replay::SessionOptions options;
    options.effects = {"roughness"};
    const capture::Environment environment;
    replay::Session session(test::testContext(), frame, environment, options);
    const replay::FrameResult result = session.run(frame);
    const replay::NamedImage* alpha = result.find("roughness/alpha");
    REQUIRE(alpha != nullptr);
    CHECK(alpha->pass == "roughness/extract_roughness");
    REQUIRE(alpha->image.channels == 1);

    const std::vector<float> expected =
        reference::extractRoughness(material->pixels, material->channels.size(),
                                    static_cast<std::size_t>(channel), frame.roughness.perceptual);
    REQUIRE(alpha->image.pixels.size() == expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        INFO("pixel " << i);
        if (expected[i] < FLT_MIN && alpha->image.pixels[i] == 0.0f) continue; // denormals may flush
        REQUIRE(alpha->image.pixels[i] == expected[i]);
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
