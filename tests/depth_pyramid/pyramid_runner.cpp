#include "depth_pyramid/pyramid_runner.h"

#include <gpu/gpu_transfer.h>

#include <catch2/catch.hpp>

#include <cstring>
#include <span>
#include <string>

namespace glint::test {

namespace {
constexpr const char* kPyramid = "depth_pyramid";
constexpr const char* kCounter = "depth_pyramid_counter";
} // namespace

PyramidRunner::PyramidRunner(gpu::Context& context, const DepthPyramidDesc& desc)
    : context_(context), desc_(desc) {
    std::string error;
    INFO(error);
    REQUIRE(planDepthPyramid(desc, plan_, &error) == Result::Ok);
    const vk::Device& device = context.device;
    executor_ = vk::createExecutor(device);
    depth_ = vk::createImage2D(device, desc.size.width, desc.size.height, VK_FORMAT_R32_SFLOAT);
    for (const ImageDesc& image : plan_.images) {
        REQUIRE(image.name == kPyramid);
        pyramid_ = vk::createImage2D(device, image.width, image.height, vk::toVkFormat(image.format),
                                     image.mipLevels);
    }
    for (const BufferDesc& buffer : plan_.buffers) {
        REQUIRE(buffer.name == kCounter);
        counter_ = vk::createBuffer(device, buffer.size, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                    vk::MemoryUse::DeviceLocal);
    }
    REQUIRE(pyramid_.image != VK_NULL_HANDLE);
}

PyramidRunner::~PyramidRunner() {
    const vk::Device& device = context_.device;
    vk::destroyExecutor(executor_);
    vk::destroyBuffer(device, counter_);
    vk::destroyImage(device, pyramid_);
    vk::destroyImage(device, depth_);
}

reference::Pyramid PyramidRunner::build(const std::vector<float>& depth,
                                        std::optional<std::uint32_t> counterBefore) {
    REQUIRE(depth.size() == static_cast<std::size_t>(desc_.size.width) * desc_.size.height);
    gpu::uploadImage(context_, depth_, depth, 1);
    VkClearColorValue nan{};
    for (std::uint32_t& channel : nan.uint32) channel = 0x7FC00000u;
    gpu::clearImage(context_, pyramid_, nan);
    if (counterBefore) {
        REQUIRE(hasCounter());
        const std::uint32_t value = *counterBefore;
        gpu::uploadBuffer(context_, counter_, std::span<const std::uint32_t>(&value, 1));
    }

    vk::ResourceTable resources;
    resources.images = {{"depth", &depth_}, {kPyramid, &pyramid_}};
    if (hasCounter()) resources.buffers = {{kCounter, &counter_}};
    gpu::submitAndWait(context_,
                       [&](VkCommandBuffer cmd) { vk::recordPlan(executor_, cmd, plan_, resources); });
    vk::resetExecutor(executor_);

    reference::Pyramid pyramid;
    pyramid.channels = vk::formatChannelCount(pyramid_.format);
    for (std::uint32_t level = 0; level < pyramid_.mipLevels; ++level) {
        reference::PyramidLevel& out = pyramid.levels.emplace_back();
        out.width = gpu::mipWidth(pyramid_, level);
        out.height = gpu::mipHeight(pyramid_, level);
        out.texels = gpu::readbackImage(context_, pyramid_, level);
    }
    return pyramid;
}

std::uint32_t PyramidRunner::readCounter() const {
    REQUIRE(hasCounter());
    const std::vector<std::byte> bytes = gpu::readbackBuffer(context_, counter_, 0, 4);
    std::uint32_t value = 0;
    std::memcpy(&value, bytes.data(), sizeof value);
    return value;
}

void checkPyramid(const std::vector<float>& depth, const DepthPyramidDesc& desc,
                  const reference::Pyramid& actual) {
    const auto& size = desc.size;
    const reference::Pyramid expected = reference::buildDepthPyramid(
        depth, size.width, size.height, desc.depth, desc.channels, desc.levelCount);
    INFO(describe(desc));
    CHECK(reference::compareBits(expected, actual) == "");
    CHECK(reference::checkDepthPyramid(depth, size.width, size.height, desc.depth,
                                       static_cast<std::uint32_t>(expected.levels.size()), actual) == "");
}

std::string describe(const DepthPyramidDesc& desc) {
    return std::to_string(desc.size.width) + "x" + std::to_string(desc.size.height) +
           (desc.depth == DepthConvention::Reversed ? " reversed" : " standard") +
           (desc.channels == DepthPyramidChannels::Closest ? " closest" : " closest+farthest") +
           " levelCount " + std::to_string(desc.levelCount);
}

} // namespace glint::test
