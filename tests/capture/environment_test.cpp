#include "capture/capture_test_support.h"

#include <capture/environment_io.h>
#include <capture/frame_io.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <catch2/catch.hpp>

using namespace glint::capture;

namespace {
Environment gradient(EnvironmentLayout layout, std::uint32_t w, std::uint32_t h) {
    Environment env{layout, w, h, std::vector<float>(std::size_t{w} * h * 3), 0};
    for (std::size_t i = 0; i < env.rgb.size(); ++i)
        env.rgb[i] = 0.001f * static_cast<float>(i) + 1e5f * (i % 7 == 0);
    return env;
}
} // namespace

TEST_CASE("lat-long and cube environment maps round trip exactly, values beyond the half range included",
          "[capture]") {
    const auto dir = test::freshTestDir("environment_round_trip");
    for (const Environment& env :
         {gradient(EnvironmentLayout::LatLong, 16, 8), gradient(EnvironmentLayout::Cube, 4, 24)}) {
        writeEnvironment(dir / "env.exr", env);
        const Environment read = readEnvironment(dir / "env.exr");
        CHECK(read.layout == env.layout);
        CHECK(read.width == env.width);
        CHECK(read.height == env.height);
        CHECK(read.rgb == env.rgb);
        CHECK(read.nonFinite == 0);
        CHECK(Imf::hasEnvmap(test::exrHeaderOf(dir / "env.exr")));
        CHECK_THAT(test::captureErrorOf([&] { (void)readFrame(dir / "env.exr"); }),
                   Catch::Contains("env.exr: this is an environment map, not a frame capture"));
    }
}

TEST_CASE("a cube map that is not W x 6W is refused on write and on read", "[capture]") {
    const auto dir = test::freshTestDir("environment_cube_shape");
    const Environment bad = gradient(EnvironmentLayout::Cube, 4, 20);
    CHECK_THAT(test::captureErrorOf([&] { writeEnvironment(dir / "cube.exr", bad); }),
               Catch::Contains("cube.exr: cube environment map is 4x20; a cube map must be W x 6W"));
    Imf::Header header(4, 20);
    Imf::addEnvmap(header, Imf::ENVMAP_CUBE);
    for (const char* c : {"R", "G", "B"}) header.channels().insert(c, Imf::Channel(Imf::HALF));
    test::writeZeroExr(dir / "cube.exr", header);
    const std::string message = test::captureErrorOf([&] { (void)readEnvironment(dir / "cube.exr"); });
    CHECK(test::isOneLine(message));
    CHECK_THAT(message, Catch::Contains("must be W x 6W"));
}

TEST_CASE("an environment map without the envmap attribute or an RGB channel is rejected", "[capture]") {
    const auto dir = test::freshTestDir("environment_malformed");
    Imf::Header header(8, 4);
    for (const char* c : {"R", "G", "B"}) header.channels().insert(c, Imf::Channel(Imf::HALF));
    test::writeZeroExr(dir / "no_envmap.exr", header);
    CHECK_THAT(test::captureErrorOf([&] { (void)readEnvironment(dir / "no_envmap.exr"); }),
               Catch::Contains("no_envmap.exr: missing attribute 'envmap'"));
    Imf::addEnvmap(header, Imf::ENVMAP_LATLONG);
    test::writeZeroExr(dir / "no_blue.exr", test::withoutChannel(header, "B"));
    CHECK_THAT(test::captureErrorOf([&] { (void)readEnvironment(dir / "no_blue.exr"); }),
               Catch::Contains("no_blue.exr: environment map lacks channel 'B'"));
    test::writeZeroExr(dir / "half.exr", header); // HALF is accepted on read
    CHECK(readEnvironment(dir / "half.exr").rgb.size() == 8 * 4 * 3);
}
