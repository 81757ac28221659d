// CPU conversion between float texels and the bytes of the image formats the harness uploads
// and reads back. Kept apart from the transfer code so it can be tested without a device.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <span>

namespace glint::gpu {

// True for the formats encodeTexels/decodeTexels handle: R/RG/RGBA 32F and 16F, R/RG/RGBA8
// UNORM and RGBA8 SRGB. Integer formats go through the byte variants of the transfer API.
bool hasFloatConversion(VkFormat format);

// Writes source.size() / channels texels into destination (formatTexelSize bytes each).
// channels may be fewer than the format's: missing colour channels become 0, missing alpha 1.
// More channels than the format has is an error, because silently dropping data hides bugs.
// Conversions: 32F copied; 16F rounded to nearest even (Inf/NaN kept); UNORM8 clamped to
// [0, 1] (NaN -> 0) and rounded to nearest; SRGB8 takes linear values and encodes them.
// Throws std::invalid_argument on an unsupported format or mismatched sizes.
void encodeTexels(VkFormat format, std::span<const float> source, uint32_t channels,
                  std::span<std::byte> destination);

// The inverse: destination receives formatChannelCount(format) floats per texel (SRGB8 decoded
// to linear).
void decodeTexels(VkFormat format, std::span<const std::byte> source, std::span<float> destination);

uint8_t floatToUnorm8(float value);
float unorm8ToFloat(uint8_t value);
float linearToSrgb(float linear);
float srgbToLinear(float encoded);

} // namespace glint::gpu
