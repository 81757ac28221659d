// Float <-> texel byte conversion on the CPU, checked against values worked out by hand.
#include <gpu/gpu_half.h>
#include <gpu/gpu_texel_format.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <vector>

using namespace glint::gpu;

TEST_CASE("float to unorm8 rounds to nearest and clamps, NaN becoming 0", "[texel]") {
    CHECK(floatToUnorm8(0.0f) == 0);
    CHECK(floatToUnorm8(1.0f) == 255);
    CHECK(floatToUnorm8(0.5f) == 128); // 127.5 rounds up
    CHECK(floatToUnorm8(0.25f) == 64); // 63.75
    CHECK(floatToUnorm8(1.0f / 255.0f) == 1);
    CHECK(floatToUnorm8(0.49f / 255.0f) == 0);
    CHECK(floatToUnorm8(-3.0f) == 0);
    CHECK(floatToUnorm8(7.0f) == 255);
    CHECK(floatToUnorm8(std::numeric_limits<float>::quiet_NaN()) == 0);
    CHECK(floatToUnorm8(std::numeric_limits<float>::infinity()) == 255);
    for (int value = 0; value < 256; ++value) {
        CHECK(floatToUnorm8(unorm8ToFloat(static_cast<uint8_t>(value))) == value);
    }
}

TEST_CASE("sRGB encoding matches the standard transfer function", "[texel]") {
    CHECK(linearToSrgb(0.0f) == 0.0f);
    CHECK(linearToSrgb(1.0f) == 1.0f);
    CHECK(linearToSrgb(0.5f) == Approx(0.735357f).margin(1e-5));
    CHECK(floatToUnorm8(linearToSrgb(0.5f)) == 188);
    CHECK(linearToSrgb(0.001f) == Approx(0.01292f).margin(1e-6)); // the linear segment
    for (float encoded : {0.0f, 0.02f, 0.2f, 0.5f, 0.9f, 1.0f}) {
        CHECK(linearToSrgb(srgbToLinear(encoded)) == Approx(encoded).margin(1e-6));
    }
}

TEST_CASE("encoding RGBA16F from two channels pads blue with 0 and alpha with 1", "[texel]") {
    const std::vector<float> source = {1.0f, -2.0f, 0.5f, 65504.0f};
    std::vector<std::byte> bytes(2 * 8);
    encodeTexels(VK_FORMAT_R16G16B16A16_SFLOAT, source, 2, bytes);
    std::vector<uint16_t> halves(8);
    std::memcpy(halves.data(), bytes.data(), bytes.size());
    CHECK(halves == std::vector<uint16_t>{0x3c00, 0xc000, 0x0000, 0x3c00, 0x3800, 0x7bff, 0x0000, 0x3c00});

    std::vector<float> decoded(8);
    decodeTexels(VK_FORMAT_R16G16B16A16_SFLOAT, bytes, decoded);
    CHECK(decoded == std::vector<float>{1.0f, -2.0f, 0.0f, 1.0f, 0.5f, 65504.0f, 0.0f, 1.0f});
}

TEST_CASE("encoding R32F copies floats bit for bit, NaN and infinity included", "[texel]") {
    const std::vector<float> source = {1.5f, -0.0f, std::numeric_limits<float>::infinity(),
                                       std::numeric_limits<float>::quiet_NaN()};
    std::vector<std::byte> bytes(16);
    encodeTexels(VK_FORMAT_R32_SFLOAT, source, 1, bytes);
    CHECK(std::memcmp(bytes.data(), source.data(), 16) == 0);
}

TEST_CASE("sRGB alpha stays linear while colour is encoded", "[texel]") {
    const std::vector<float> source = {0.5f, 0.5f, 0.5f, 0.5f};
    std::vector<std::byte> bytes(4);
    encodeTexels(VK_FORMAT_R8G8B8A8_SRGB, source, 4, bytes);
    CHECK(std::to_integer<int>(bytes[0]) == 188);
    CHECK(std::to_integer<int>(bytes[3]) == 128);
}

TEST_CASE("texel conversion rejects unsupported formats, extra channels and wrong sizes", "[texel]") {
    const std::vector<float> four(4, 0.0f);
    std::vector<std::byte> bytes(4);
    CHECK_THROWS_AS(encodeTexels(VK_FORMAT_R32_UINT, four, 1, bytes), std::invalid_argument);
    CHECK_THROWS_AS(encodeTexels(VK_FORMAT_R8_UNORM, four, 2, bytes), std::invalid_argument);
    CHECK_THROWS_AS(encodeTexels(VK_FORMAT_R8_UNORM, four, 1, std::span<std::byte>(bytes).first(3)),
                    std::invalid_argument);
    CHECK_FALSE(hasFloatConversion(VK_FORMAT_R32G32_UINT));
    CHECK(hasFloatConversion(VK_FORMAT_R16G16_SFLOAT));
}
