// Captures whose channels break the format: missing layers and channels, wrong types,
// subsampling, channels outside any layer.
#include "capture/capture_test_support.h"

#include <capture/frame_io.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfStringVectorAttribute.h>
#include <catch2/catch.hpp>

using namespace glint::capture;

namespace {
Imf::Header validHeader(const std::filesystem::path& dir) {
    return test::validFrameHeader(dir, 8, 4);
}

std::string rejection(const std::filesystem::path& file, const Imf::Header& header) {
    return test::rejectionOf(file, header);
}

void setEffects(Imf::Header& header, std::vector<std::string> effects) {
    header.insert("glint.effects", Imf::StringVectorAttribute(std::move(effects)));
}
} // namespace

TEST_CASE("a layer required by a declared effect is named when missing", "[capture]") {
    const auto dir = test::freshTestDir("layers_missing");
    const Imf::Header valid = validHeader(dir);
    struct Case {
        std::string effect, channel, layer;
    };
    for (const Case& c : {Case{"reflections", "color.R", "color"}, Case{"reflections", "depth.Z", "depth"},
                          Case{"shadows", "shadow.Y", "shadow"}, Case{"shadows", "motion.X", "motion"},
                          Case{"depth_pyramid", "depth.Z", "depth"}}) {
        INFO(c.effect << " without " << c.layer);
        // Drop every channel of the layer so that the layer itself is gone.
        Imf::Header header = valid;
        for (auto it = valid.channels().begin(); it != valid.channels().end(); ++it) {
            const std::string name = it.name();
            if (name.rfind(c.layer + ".", 0) == 0) header = test::withoutChannel(header, name);
        }
        setEffects(header, {c.effect});
        if (c.effect != "reflections") header.insert("glint.roughnessSource", Imf::StringAttribute(""));
        CHECK_THAT(rejection(dir / "frame_0003.exr", header),
                   Catch::Contains("missing layer '" + c.layer + "' required by effect '" + c.effect + "'"));
    }
}

TEST_CASE("the roughness source is required by reflections and must exist", "[capture]") {
    const auto dir = test::freshTestDir("layers_roughness_source");
    Imf::Header header = validHeader(dir);
    header.insert("glint.roughnessSource", Imf::StringAttribute("material.W"));
    CHECK_THAT(rejection(dir / "channel.exr", header), Catch::Contains("layer 'material' lacks channel 'W'"));
    header.insert("glint.roughnessSource", Imf::StringAttribute("gbuffer.R"));
    CHECK_THAT(rejection(dir / "layer.exr", header),
               Catch::Contains("missing layer 'gbuffer' (roughness source)"));
    header.insert("glint.roughnessSource", Imf::StringAttribute(""));
    CHECK_THAT(rejection(dir / "none.exr", header), Catch::Contains("no roughness source declared"));
}

TEST_CASE("a missing channel of a present layer is named", "[capture]") {
    const auto dir = test::freshTestDir("layers_missing_channel");
    const Imf::Header valid = validHeader(dir);
    CHECK_THAT(rejection(dir / "normal.exr", test::withoutChannel(valid, "normal.Z")),
               Catch::Contains("layer 'normal' lacks channel 'Z'"));
    CHECK_THAT(rejection(dir / "motion.exr", test::withoutChannel(valid, "motion.Y")),
               Catch::Contains("layer 'motion' lacks channel 'Y'"));
    CHECK_THAT(rejection(dir / "color.exr", test::withoutChannel(valid, "color.G")),
               Catch::Contains("layer 'color' lacks channel 'G'"));
}

TEST_CASE("an integer channel is rejected where float samples are needed", "[capture]") {
    const auto dir = test::freshTestDir("layers_uint");
    Imf::Header header = validHeader(dir);
    header.channels().findChannel("depth.Z")->type = Imf::UINT;
    CHECK_THAT(rejection(dir / "uint.exr", header),
               Catch::Contains("channel 'depth.Z' has type UINT; capture channels must be HALF or FLOAT"));
}

TEST_CASE("depth and motion stored as HALF are rejected", "[capture]") {
    const auto dir = test::freshTestDir("layers_half_depth");
    Imf::Header header = validHeader(dir);
    header.channels().findChannel("depth.Z")->type = Imf::HALF;
    CHECK_THAT(rejection(dir / "depth.exr", header),
               Catch::Contains("layer 'depth' is stored as HALF; depth and motion must be FLOAT"));
    header = validHeader(dir);
    header.channels().findChannel("motion.X")->type = Imf::HALF;
    header.channels().findChannel("motion.Y")->type = Imf::HALF;
    CHECK_THAT(rejection(dir / "motion.exr", header), Catch::Contains("layer 'motion' is stored as HALF"));
}

TEST_CASE("a layer mixing HALF and FLOAT channels is rejected", "[capture]") {
    const auto dir = test::freshTestDir("layers_mixed");
    Imf::Header header = validHeader(dir);
    header.channels().findChannel("color.G")->type = Imf::FLOAT;
    CHECK_THAT(rejection(dir / "mixed.exr", header), Catch::Contains("layer 'color' mixes HALF and FLOAT"));
}

TEST_CASE("a subsampled channel is rejected", "[capture]") {
    const auto dir = test::freshTestDir("layers_subsampled");
    Imf::Header header = validHeader(dir);
    Imf::Channel* channel = header.channels().findChannel("shadow.Y");
    channel->xSampling = 2;
    channel->ySampling = 2;
    CHECK_THAT(rejection(dir / "subsampled.exr", header),
               Catch::Contains("channel 'shadow.Y' is subsampled (2x2)"));
}

TEST_CASE("a channel outside any layer is rejected", "[capture]") {
    const auto dir = test::freshTestDir("layers_no_prefix");
    Imf::Header header = validHeader(dir);
    header.channels().insert("Y", Imf::Channel(Imf::HALF));
    CHECK_THAT(rejection(dir / "bare.exr", header),
               Catch::Contains("channel 'Y' is not named <layer>.<channel>"));
}

TEST_CASE("writeFrame refuses an invalid frame, names the output file and leaves no file behind",
          "[capture]") {
    const auto dir = test::freshTestDir("layers_write_refused");
    const auto file = dir / "frame_0000.exr";
    Frame missingDepth = test::makeFullFrame(4, 4);
    std::erase_if(missingDepth.layers, [](const Layer& l) { return l.name == "depth"; });
    CHECK_THAT(test::captureErrorOf([&] { writeFrame(file, missingDepth); }),
               Catch::Contains("frame_0000.exr: missing layer 'depth' required by effect 'reflections'"));

    Frame shortBuffer = test::makeFullFrame(4, 4);
    findLayer(shortBuffer, "normal")->pixels.pop_back();
    CHECK_THAT(test::captureErrorOf([&] { writeFrame(file, shortBuffer); }),
               Catch::Contains("layer 'normal' holds 47 samples, expected 48"));

    Frame halfDepth = test::makeFullFrame(4, 4);
    findLayer(halfDepth, "depth")->storage = SampleType::Half;
    CHECK_THAT(test::captureErrorOf([&] { writeFrame(file, halfDepth); }), Catch::Contains("must be FLOAT"));

    Frame unknownEffect = test::makeFullFrame(4, 4);
    unknownEffect.effects.push_back("ambient_occlusion");
    CHECK_THAT(test::captureErrorOf([&] { writeFrame(file, unknownEffect); }),
               Catch::Contains("unknown effect 'ambient_occlusion'"));
    CHECK_FALSE(std::filesystem::exists(file));
    CHECK(std::filesystem::is_empty(dir));
}
