// Per-format encode/decode. Conversions follow the Vulkan spec's rules for the GPU's own
// float<->normalized conversions so that a value uploaded here matches one a shader writes.
#include <gpu/gpu_texel_format.h>

#include <gpu/gpu_half.h>

#include "glint/vulkan/vk_resources.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace glint::gpu {

namespace {

enum class ChannelKind { None, Float32, Float16, Unorm8, Srgb8 };

ChannelKind channelKind(VkFormat format) {
    switch (format) {
    case VK_FORMAT_R32_SFLOAT:
    case VK_FORMAT_R32G32_SFLOAT:
    case VK_FORMAT_R32G32B32A32_SFLOAT:
        return ChannelKind::Float32;
    case VK_FORMAT_R16_SFLOAT:
    case VK_FORMAT_R16G16_SFLOAT:
    case VK_FORMAT_R16G16B16A16_SFLOAT:
        return ChannelKind::Float16;
    case VK_FORMAT_R8_UNORM:
    case VK_FORMAT_R8G8_UNORM:
    case VK_FORMAT_R8G8B8A8_UNORM:
        return ChannelKind::Unorm8;
    case VK_FORMAT_R8G8B8A8_SRGB:
        return ChannelKind::Srgb8;
    default:
        return ChannelKind::None;
    }
}

ChannelKind requireConvertible(VkFormat format, const char* function) {
    ChannelKind kind = channelKind(format);
    if (kind == ChannelKind::None) {
        throw std::invalid_argument(std::string(function) + ": VkFormat " +
                                    std::to_string(static_cast<int>(format)) +
                                    " has no float conversion (use the byte variants)");
    }
    return kind;
}

} // namespace

bool hasFloatConversion(VkFormat format) {
    return channelKind(format) != ChannelKind::None;
}

uint8_t floatToUnorm8(float value) {
    // Negated comparison so NaN takes the first branch and becomes 0.
    if (!(value > 0.0f)) return 0;
    if (value >= 1.0f) return 255;
    return static_cast<uint8_t>(std::floor(value * 255.0f + 0.5f));
}

float unorm8ToFloat(uint8_t value) {
    return static_cast<float>(value) / 255.0f;
}

float linearToSrgb(float linear) {
    if (!(linear > 0.0f)) return 0.0f;
    if (linear >= 1.0f) return 1.0f;
    if (linear <= 0.0031308f) return linear * 12.92f;
    return 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

float srgbToLinear(float encoded) {
    if (encoded <= 0.04045f) return encoded / 12.92f;
    return std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

void encodeTexels(VkFormat format, std::span<const float> source, uint32_t channels,
                  std::span<std::byte> destination) {
    const ChannelKind kind = requireConvertible(format, "glint::gpu::encodeTexels");
    const uint32_t formatChannels = vk::formatChannelCount(format);
    if (channels == 0 || channels > formatChannels) {
        throw std::invalid_argument("glint::gpu::encodeTexels: " + std::to_string(channels) +
                                    " source channels for a format with " + std::to_string(formatChannels));
    }
    if (source.size() % channels != 0) {
        throw std::invalid_argument("glint::gpu::encodeTexels: source size is not a whole number of texels");
    }
    const size_t texels = source.size() / channels;
    const size_t texelSize = vk::formatTexelSize(format);
    if (destination.size() != texels * texelSize) {
        throw std::invalid_argument("glint::gpu::encodeTexels: destination holds " +
                                    std::to_string(destination.size()) + " bytes, " +
                                    std::to_string(texels * texelSize) + " needed");
    }

    for (size_t texel = 0; texel < texels; ++texel) {
        std::byte* out = destination.data() + texel * texelSize;
        for (uint32_t c = 0; c < formatChannels; ++c) {
            const bool isAlpha = formatChannels == 4 && c == 3;
            const float value = c < channels ? source[texel * channels + c] : (isAlpha ? 1.0f : 0.0f);
            switch (kind) {
            case ChannelKind::Float32:
                std::memcpy(out + c * 4, &value, 4);
                break;
            case ChannelKind::Float16: {
                const uint16_t half = floatToHalf(value);
                std::memcpy(out + c * 2, &half, 2);
                break;
            }
            case ChannelKind::Unorm8:
                out[c] = std::byte{floatToUnorm8(value)};
                break;
            case ChannelKind::Srgb8:
                // Alpha is linear in sRGB formats; only colour channels are encoded.
                out[c] = std::byte{floatToUnorm8(isAlpha ? value : linearToSrgb(value))};
                break;
            case ChannelKind::None:
                break;
            }
        }
    }
}

void decodeTexels(VkFormat format, std::span<const std::byte> source, std::span<float> destination) {
    const ChannelKind kind = requireConvertible(format, "glint::gpu::decodeTexels");
    const uint32_t formatChannels = vk::formatChannelCount(format);
    const size_t texelSize = vk::formatTexelSize(format);
    if (source.size() % texelSize != 0 || destination.size() != source.size() / texelSize * formatChannels) {
        throw std::invalid_argument("glint::gpu::decodeTexels: source and destination sizes disagree");
    }

    const size_t texels = source.size() / texelSize;
    for (size_t texel = 0; texel < texels; ++texel) {
        const std::byte* in = source.data() + texel * texelSize;
        float* out = destination.data() + texel * formatChannels;
        for (uint32_t c = 0; c < formatChannels; ++c) {
            const bool isAlpha = formatChannels == 4 && c == 3;
            switch (kind) {
            case ChannelKind::Float32:
                std::memcpy(&out[c], in + c * 4, 4);
                break;
            case ChannelKind::Float16: {
                uint16_t half = 0;
                std::memcpy(&half, in + c * 2, 2);
                out[c] = halfToFloat(half);
                break;
            }
            case ChannelKind::Unorm8:
                out[c] = unorm8ToFloat(std::to_integer<uint8_t>(in[c]));
                break;
            case ChannelKind::Srgb8: {
                const float encoded = unorm8ToFloat(std::to_integer<uint8_t>(in[c]));
                out[c] = isAlpha ? encoded : srgbToLinear(encoded);
                break;
            }
            case ChannelKind::None:
                break;
            }
        }
    }
}

} // namespace glint::gpu
