#include "gpu/gpu_input_images.h"

#include "gpu/gpu_transfer.h"

#include <algorithm>
#include <stdexcept>

namespace glint::gpu {
namespace {

VkFormat formatFor(InputKind kind, bool compact) {
    switch (kind) {
    case InputKind::Depth:
    case InputKind::PreviousDepth:
        return VK_FORMAT_R32_SFLOAT;
    case InputKind::Normals:
    case InputKind::Color:
        return compact ? VK_FORMAT_R16G16B16A16_SFLOAT : VK_FORMAT_R32G32B32A32_SFLOAT;
    case InputKind::Material:
        return compact ? VK_FORMAT_R16_SFLOAT : VK_FORMAT_R32G32B32A32_SFLOAT;
    case InputKind::Motion:
        return compact ? VK_FORMAT_R16G16_SFLOAT : VK_FORMAT_R32G32_SFLOAT;
    case InputKind::BaseColorMetallic:
        return compact ? VK_FORMAT_R8G8B8A8_UNORM : VK_FORMAT_R32G32B32A32_SFLOAT;
    // 8-bit visibility: 0 or 1; NaN uploads as 0, shadowed, as the shader treats it.
    case InputKind::ShadowVisibility:
        return compact ? VK_FORMAT_R8_UNORM : VK_FORMAT_R32_SFLOAT;
    // A distance in scene units; < 0 marks unknown.
    case InputKind::ShadowBlockerDistance:
        return compact ? VK_FORMAT_R16_SFLOAT : VK_FORMAT_R32_SFLOAT;
    case InputKind::Environment:
        return VK_FORMAT_R32G32B32A32_SFLOAT;
    case InputKind::SceneGeometry: // buffers, not an image
    case InputKind::SceneAccelerationStructure:
        return VK_FORMAT_UNDEFINED;
    }
    return VK_FORMAT_UNDEFINED;
}

} // namespace

std::vector<std::vector<float>> environmentMips(std::uint32_t width, std::uint32_t height,
                                                const std::vector<float>& rgba) {
    std::vector<std::vector<float>> levels{rgba};
    std::uint32_t w = width, h = height;
    while (w > 1 || h > 1) {
        const std::uint32_t nw = std::max(1u, w / 2), nh = std::max(1u, h / 2);
        const std::vector<float>& src = levels.back();
        std::vector<float> dst(std::size_t{nw} * nh * 4, 0.0f);
        for (std::uint32_t y = 0; y < nh; ++y)
            for (std::uint32_t x = 0; x < nw; ++x)
                for (std::uint32_t c = 0; c < 4; ++c) {
                    float sum = 0.0f;
                    for (std::uint32_t dy = 0; dy < 2; ++dy)
                        for (std::uint32_t dx = 0; dx < 2; ++dx) {
                            const std::uint32_t sx = std::min(2 * x + dx, w - 1),
                                                sy = std::min(2 * y + dy, h - 1);
                            sum += src[(std::size_t{sy} * w + sx) * 4 + c];
                        }
                    dst[(std::size_t{y} * nw + x) * 4 + c] = 0.25f * sum;
                }
        levels.push_back(std::move(dst));
        w = nw;
        h = nh;
    }
    return levels;
}

InputImages::InputImages(const Context& context, Extent2D size, bool compact)
    : context_(context), size_(size), compact_(compact) {}

InputImages::~InputImages() {
    for (auto& [kind, image] : images_) vk::destroyImage(context_.device, image);
}

void InputImages::upload(InputKind kind, const std::vector<float>& texels, std::uint32_t channels) {
    TransferBatch batch(context_);
    upload(batch, kind, texels, channels);
    batch.submit();
}

void InputImages::upload(TransferBatch& batch, InputKind kind, const std::vector<float>& texels,
                         std::uint32_t channels) {
    const std::size_t pixels = std::size_t{size_.width} * size_.height;
    if (texels.size() != pixels * channels)
        throw std::runtime_error("input images: an input has " + std::to_string(texels.size()) +
                                 " values, not " + std::to_string(pixels * channels));
    vk::Image& image = images_[kind];
    if (image.image == VK_NULL_HANDLE)
        image = vk::createImage2D(context_.device, size_.width, size_.height, formatFor(kind, compact_));
    if (compact_ && kind == InputKind::Material) { // R16F: roughness only, from channel 0
        std::vector<float> roughness(pixels);
        for (std::size_t i = 0; i < pixels; ++i) roughness[i] = texels[i * channels];
        batch.uploadImage(image, roughness, 1);
        return;
    }
    batch.uploadImage(image, texels, channels);
}

void InputImages::uploadEnvironment(std::uint32_t width, std::uint32_t height,
                                    const std::vector<float>& rgba) {
    const auto levels = environmentMips(width, height, rgba);
    vk::Image& image = images_[InputKind::Environment];
    vk::destroyImage(context_.device, image);
    image = vk::createImage2D(context_.device, width, height, formatFor(InputKind::Environment, compact_),
                              static_cast<std::uint32_t>(levels.size()));
    clearImage(context_, image, VkClearColorValue{});
    for (std::size_t level = 0; level < levels.size(); ++level)
        uploadImage(context_, image, levels[level], 4, static_cast<std::uint32_t>(level));
}

const vk::Image* InputImages::find(InputKind kind) const {
    const auto found = images_.find(kind);
    return found == images_.end() || found->second.image == VK_NULL_HANDLE ? nullptr : &found->second;
}

} // namespace glint::gpu
