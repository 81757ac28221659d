// Buffer upload and readback through every memory kind.
#include "support/gpu_test_context.h"

#include <gpu/gpu_transfer.h>

#include <catch2/catch.hpp>

#include <cstring>
#include <numeric>
#include <stdexcept>
#include <vector>

using namespace glint;

namespace {

std::vector<uint32_t> pattern(size_t count, uint32_t seed) {
    std::vector<uint32_t> values(count);
    uint32_t state = seed;
    for (uint32_t& value : values) {
        state = state * 1664525u + 1013904223u;
        value = state;
    }
    return values;
}

std::vector<uint32_t> asWords(const std::vector<std::byte>& bytes) {
    std::vector<uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), words.size() * 4);
    return words;
}

void requireRoundTrip(vk::MemoryUse use) {
    const gpu::Context& context = test::testContext();
    const std::vector<uint32_t> values = pattern(1001, 7);
    vk::Buffer buffer =
        vk::createBuffer(context.device, values.size() * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, use);
    gpu::uploadBuffer(context, buffer, std::span<const uint32_t>(values));
    const std::vector<uint32_t> back = asWords(gpu::readbackBuffer(context, buffer));
    vk::destroyBuffer(context.device, buffer);
    CHECK(back == values);
}

} // namespace

TEST_CASE("a device-local buffer survives upload and readback", "[gpu]") {
    requireRoundTrip(vk::MemoryUse::DeviceLocal);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("an upload buffer survives upload and readback through its mapping", "[gpu]") {
    requireRoundTrip(vk::MemoryUse::Upload);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("a readback buffer survives upload and readback through its mapping", "[gpu]") {
    requireRoundTrip(vk::MemoryUse::Readback);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("an upload at an offset changes only those bytes and a ranged readback returns them", "[gpu]") {
    const gpu::Context& context = test::testContext();
    const std::vector<uint32_t> base = pattern(64, 1);
    const std::vector<uint32_t> patch = pattern(5, 2);
    vk::Buffer buffer = vk::createBuffer(context.device, 64 * 4, 0, vk::MemoryUse::DeviceLocal);
    gpu::uploadBuffer(context, buffer, std::span<const uint32_t>(base));
    gpu::uploadBuffer(context, buffer, std::span<const uint32_t>(patch), 12 * 4);

    std::vector<uint32_t> expected = base;
    std::copy(patch.begin(), patch.end(), expected.begin() + 12);
    CHECK(asWords(gpu::readbackBuffer(context, buffer)) == expected);
    CHECK(asWords(gpu::readbackBuffer(context, buffer, 12 * 4, 5 * 4)) == patch);
    vk::destroyBuffer(context.device, buffer);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("buffer transfers outside the buffer and empty buffers are rejected before Vulkan sees them",
          "[gpu]") {
    const gpu::Context& context = test::testContext();
    CHECK_THROWS_AS(vk::createBuffer(context.device, 0, 0, vk::MemoryUse::DeviceLocal),
                    std::invalid_argument);
    vk::Buffer buffer = vk::createBuffer(context.device, 16, 0, vk::MemoryUse::DeviceLocal);
    const std::vector<uint32_t> five(5, 1u);
    CHECK_THROWS_AS(gpu::uploadBuffer(context, buffer, std::span<const uint32_t>(five)),
                    std::invalid_argument);
    CHECK_THROWS_AS(gpu::readbackBuffer(context, buffer, 8, 16), std::invalid_argument);
    vk::destroyBuffer(context.device, buffer);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("destroying an empty buffer or image is a no-op", "[gpu]") {
    const gpu::Context& context = test::testContext();
    vk::Buffer buffer;
    vk::Image image;
    vk::destroyBuffer(context.device, buffer);
    vk::destroyImage(context.device, image);
    CHECK(buffer.buffer == VK_NULL_HANDLE);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
