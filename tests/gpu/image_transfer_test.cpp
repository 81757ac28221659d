// 2D image upload and readback, per format, at an odd size and on every mip level. Values are
// chosen to be exactly representable in the format, so a round trip must be bit-exact.
#include "support/gpu_test_context.h"

#include <gpu/gpu_texel_format.h>
#include <gpu/gpu_transfer.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <vector>

using namespace glint;

namespace {

constexpr uint32_t kWidth = 13;
constexpr uint32_t kHeight = 7;
constexpr uint32_t kMips = 3; // 13x7, 6x3, 3x1

bool isUnorm(VkFormat format) {
    return format == VK_FORMAT_R8_UNORM || format == VK_FORMAT_R8G8_UNORM ||
           format == VK_FORMAT_R8G8B8A8_UNORM;
}

// Multiples of 1/16 below 2048 are exact in half and float; k/255 is exact in UNORM8.
std::vector<float> exactValues(VkFormat format, size_t count, uint32_t mip) {
    std::vector<float> values(count);
    for (size_t i = 0; i < count; ++i) {
        const auto k = static_cast<int>((i * 37 + mip * 101) % 256);
        values[i] = isUnorm(format) ? static_cast<float>(k) / 255.0f : static_cast<float>(k - 128) / 16.0f;
    }
    return values;
}

void requireRoundTripOnEveryMip(VkFormat format) {
    const gpu::Context& context = test::testContext();
    vk::Image image = vk::createImage2D(context.device, kWidth, kHeight, format, kMips);
    const uint32_t channels = vk::formatChannelCount(format);
    std::vector<std::vector<float>> uploaded;
    for (uint32_t mip = 0; mip < kMips; ++mip) {
        const size_t texels = size_t{gpu::mipWidth(image, mip)} * gpu::mipHeight(image, mip);
        uploaded.push_back(exactValues(format, texels * channels, mip));
        gpu::uploadImage(context, image, uploaded.back(), channels, mip);
    }
    // Read back only after every mip was written, so a copy that strayed into another mip shows.
    for (uint32_t mip = 0; mip < kMips; ++mip) {
        INFO("mip " << mip);
        CHECK(gpu::readbackImage(context, image, mip) == uploaded[mip]);
    }
    vk::destroyImage(context.device, image);
}

} // namespace

TEST_CASE("an R32F image survives upload and readback at an odd size on every mip", "[gpu]") {
    requireRoundTripOnEveryMip(VK_FORMAT_R32_SFLOAT);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("an RG16F image survives upload and readback at an odd size on every mip", "[gpu]") {
    requireRoundTripOnEveryMip(VK_FORMAT_R16G16_SFLOAT);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("an RGBA16F image survives upload and readback at an odd size on every mip", "[gpu]") {
    requireRoundTripOnEveryMip(VK_FORMAT_R16G16B16A16_SFLOAT);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("an RGBA32F image survives upload and readback at an odd size on every mip", "[gpu]") {
    requireRoundTripOnEveryMip(VK_FORMAT_R32G32B32A32_SFLOAT);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("an R8 UNORM image survives upload and readback at an odd size on every mip", "[gpu]") {
    requireRoundTripOnEveryMip(VK_FORMAT_R8_UNORM);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("an RGBA16F image rounds to half on upload and keeps infinities exactly", "[gpu]") {
    const gpu::Context& context = test::testContext();
    vk::Image image = vk::createImage2D(context.device, 2, 1, VK_FORMAT_R16G16B16A16_SFLOAT);
    const float inf = std::numeric_limits<float>::infinity();
    const std::vector<float> texels = {0.1f, 65504.0f, -inf, -0.0f, 1e6f, 1e-8f, 0.5f, 1.0f};
    gpu::uploadImage(context, image, texels, 4);
    const std::vector<float> back = gpu::readbackImage(context, image);
    // 0.1 is 0x2e66 in half; 1e6 overflows to infinity; 1e-8 is below half of the smallest
    // denormal (2^-24) and flushes to zero.
    CHECK(back == std::vector<float>{0.0999755859375f, 65504.0f, -inf, -0.0f, inf, 0.0f, 0.5f, 1.0f});
    CHECK(std::signbit(back[3]));
    vk::destroyImage(context.device, image);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("an R8 UNORM image clamps out-of-range and NaN values on upload", "[gpu]") {
    const gpu::Context& context = test::testContext();
    vk::Image image = vk::createImage2D(context.device, 4, 1, VK_FORMAT_R8_UNORM);
    const std::vector<float> texels = {-0.5f, 2.0f, std::numeric_limits<float>::quiet_NaN(), 0.5f};
    gpu::uploadImage(context, image, texels, 1);
    CHECK(gpu::readbackImage(context, image) == std::vector<float>{0.0f, 1.0f, 0.0f, 128.0f / 255.0f});
    vk::destroyImage(context.device, image);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("uploading two channels into an RGBA16F image fills blue with 0 and alpha with 1", "[gpu]") {
    const gpu::Context& context = test::testContext();
    vk::Image image = vk::createImage2D(context.device, 3, 1, VK_FORMAT_R16G16B16A16_SFLOAT);
    gpu::uploadImage(context, image, std::vector<float>{1, 2, 3, 4, 5, 6}, 2);
    CHECK(gpu::readbackImage(context, image) == std::vector<float>{1, 2, 0, 1, 3, 4, 0, 1, 5, 6, 0, 1});
    vk::destroyImage(context.device, image);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("an image can be uploaded again after it was read back", "[gpu]") {
    const gpu::Context& context = test::testContext();
    vk::Image image = vk::createImage2D(context.device, 5, 3, VK_FORMAT_R32_SFLOAT);
    const std::vector<float> first(15, 1.0f);
    const std::vector<float> second(15, 2.0f);
    gpu::uploadImage(context, image, first, 1);
    CHECK(gpu::readbackImage(context, image) == first);
    gpu::uploadImage(context, image, second, 1);
    CHECK(gpu::readbackImage(context, image) == second);
    vk::destroyImage(context.device, image);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("a transfer batch uploads and reads back several images and mips in one submission", "[gpu]") {
    const gpu::Context& context = test::testContext();
    // Formats of different texel sizes (4, 8 and 1 bytes), so the staging offsets must be aligned.
    vk::Image a = vk::createImage2D(context.device, kWidth, kHeight, VK_FORMAT_R32_SFLOAT, kMips);
    vk::Image b = vk::createImage2D(context.device, 5, 3, VK_FORMAT_R16G16B16A16_SFLOAT);
    vk::Image c = vk::createImage2D(context.device, 3, 3, VK_FORMAT_R8_UNORM);
    std::vector<std::vector<float>> expected;
    {
        gpu::TransferBatch batch(context);
        for (uint32_t mip = 0; mip < kMips; ++mip) {
            expected.push_back(exactValues(VK_FORMAT_R32_SFLOAT,
                                           size_t{gpu::mipWidth(a, mip)} * gpu::mipHeight(a, mip), mip));
            batch.uploadImage(a, expected.back(), 1, mip);
        }
        expected.push_back(exactValues(VK_FORMAT_R16G16B16A16_SFLOAT, 5 * 3 * 4, 7));
        batch.uploadImage(b, expected.back(), 4);
        expected.push_back(exactValues(VK_FORMAT_R8_UNORM, 3 * 3, 9));
        batch.uploadImage(c, expected.back(), 1);
        // A mip twice in one batch is refused (its two copies would race).
        CHECK_THROWS_AS(batch.uploadImage(c, expected.back(), 1), std::logic_error);
        // Readbacks in the same batch see its uploads.
        const std::size_t fromC = batch.readbackImage(c);
        const std::size_t fromA1 = batch.readbackImage(a, 1);
        CHECK_THROWS_AS(batch.floats(fromC), std::logic_error); // not submitted yet
        batch.submit();
        CHECK(batch.floats(fromC) == expected[kMips + 1]);
        CHECK(batch.floats(fromA1) == expected[1]);
        CHECK_THROWS_AS(batch.submit(), std::logic_error);
    }
    gpu::TransferBatch reads(context);
    std::vector<std::size_t> tickets;
    for (uint32_t mip = 0; mip < kMips; ++mip) tickets.push_back(reads.readbackImage(a, mip));
    tickets.push_back(reads.readbackImage(b));
    reads.submit();
    for (std::size_t i = 0; i < tickets.size(); ++i) {
        INFO("readback " << i);
        CHECK(reads.floats(tickets[i]) == expected[i]);
    }
    for (vk::Image* image : {&a, &b, &c}) vk::destroyImage(context.device, *image);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("clearing an image fills every mip and leaves it readable", "[gpu]") {
    const gpu::Context& context = test::testContext();
    vk::Image image = vk::createImage2D(context.device, kWidth, kHeight, VK_FORMAT_R32_SFLOAT, kMips);
    VkClearColorValue value{};
    value.float32[0] = 0.25f;
    gpu::clearImage(context, image, value);
    for (uint32_t mip = 0; mip < kMips; ++mip) {
        const size_t texels = size_t{gpu::mipWidth(image, mip)} * gpu::mipHeight(image, mip);
        CHECK(gpu::readbackImage(context, image, mip) == std::vector<float>(texels, 0.25f));
    }
    vk::destroyImage(context.device, image);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("an RGBA8 sRGB image gets only the usage its format supports", "[gpu]") {
    const gpu::Context& context = test::testContext();
    const VkImageUsageFlags usage = vk::supportedImageUsage(context.device, VK_FORMAT_R8G8B8A8_SRGB);
    CHECK((usage & VK_IMAGE_USAGE_SAMPLED_BIT) != 0);
    // If createImage2D asked for STORAGE regardless, the layer would report it here.
    vk::Image image = vk::createImage2D(context.device, 3, 2, VK_FORMAT_R8G8B8A8_SRGB);
    std::vector<float> linear(3 * 2 * 4);
    for (size_t i = 0; i < linear.size(); ++i) {
        linear[i] = gpu::srgbToLinear(static_cast<float>(i * 10) / 255.0f);
    }
    gpu::uploadImage(context, image, linear, 4);
    const std::vector<float> back = gpu::readbackImage(context, image);
    for (size_t i = 0; i < linear.size(); ++i) {
        const bool alpha = i % 4 == 3;
        // Alpha is stored linearly, so it comes back as the quantized linear value.
        const float expected = alpha ? static_cast<float>(gpu::floatToUnorm8(linear[i])) / 255.0f : linear[i];
        CHECK(back[i] == Approx(expected).margin(1e-6));
    }
    vk::destroyImage(context.device, image);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("image creation and transfers reject bad sizes, mips and formats up front", "[gpu]") {
    const gpu::Context& context = test::testContext();
    CHECK_THROWS_AS(vk::createImage2D(context.device, 13, 7, VK_FORMAT_R32_SFLOAT, 5), std::invalid_argument);
    CHECK_THROWS_AS(vk::createImage2D(context.device, 0, 7, VK_FORMAT_R32_SFLOAT), std::invalid_argument);
    vk::Image image = vk::createImage2D(context.device, 13, 7, VK_FORMAT_R32_SFLOAT, 4);
    CHECK(image.mipViews[3] != VK_NULL_HANDLE);
    CHECK(image.mipViews[4] == VK_NULL_HANDLE);
    CHECK_THROWS_AS(gpu::uploadImage(context, image, std::vector<float>(13 * 7 - 1), 1),
                    std::invalid_argument);
    CHECK_THROWS_AS(gpu::uploadImage(context, image, std::vector<float>(1), 1, 4), std::invalid_argument);
    CHECK_THROWS_AS(gpu::uploadImage(context, image, std::vector<float>(13 * 7 * 2), 2),
                    std::invalid_argument);
    vk::destroyImage(context.device, image);

    vk::Image integer = vk::createImage2D(context.device, 2, 2, VK_FORMAT_R32_UINT);
    CHECK_THROWS_AS(gpu::uploadImage(context, integer, std::vector<float>(4), 1), std::invalid_argument);
    const std::vector<uint32_t> words = {1, 2, 3, 0xffffffffu};
    gpu::uploadImageBytes(context, integer, std::as_bytes(std::span(words)));
    const std::vector<std::byte> back = gpu::readbackImageBytes(context, integer);
    REQUIRE(back.size() == 16);
    CHECK(std::memcmp(back.data(), words.data(), 16) == 0);
    vk::destroyImage(context.device, integer);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
