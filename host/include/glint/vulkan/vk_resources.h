// Buffers and 2D images with their memory: plain structs, free functions, no allocator
// framework. Every create has a matching destroy that accepts an empty (null) object.
#pragma once

#include "glint/glint_pass.h"
#include "glint/vulkan/vk_device.h"

#include <cstdint>

namespace glint::vk {

enum class MemoryUse {
    DeviceLocal, // GPU only
    Upload,      // host-visible, coherent, mapped: CPU writes, GPU reads
    Readback,    // host-visible, mapped, prefer cached: GPU writes, CPU reads
};

struct Buffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize size = 0;
    void* mapped = nullptr; // non-null for Upload and Readback buffers
    bool coherent = true;
};

struct Image {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE; // all mips, for sampled/storage reads
    VkImageView mipViews[16] = {};     // one per mip, for storage writes
    VkFormat format = VK_FORMAT_UNDEFINED;
    uint32_t width = 0;
    uint32_t height = 0;
    uint32_t mipLevels = 1;
};

// usage gets TRANSFER_SRC|TRANSFER_DST added so every buffer can be uploaded and read back.
Buffer createBuffer(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use);
void destroyBuffer(const Device& device, Buffer& buffer);
// Makes host writes visible / device writes visible to the host for non-coherent memory.
void flushBuffer(const Device& device, const Buffer& buffer);
void invalidateBuffer(const Device& device, const Buffer& buffer);

// A 2D image in VK_IMAGE_LAYOUT_UNDEFINED with STORAGE|SAMPLED|TRANSFER_SRC|TRANSFER_DST usage
// (where the format supports them), device-local, with views as described above.
Image createImage2D(const Device& device, uint32_t width, uint32_t height, VkFormat format,
                    uint32_t mipLevels = 1);
void destroyImage(const Device& device, Image& image);

// The usage createImage2D gives `format` with optimal tiling: the subset of
// STORAGE|SAMPLED|TRANSFER_SRC|TRANSFER_DST that the device's format features allow (for
// example RGBA8 sRGB is never a storage format). 0 when the format cannot be sampled or stored.
VkImageUsageFlags supportedImageUsage(const Device& device, VkFormat format);

// Index of a memory type allowed by typeBits that has all `required` flags, preferring one that
// also has all `preferred` flags; UINT32_MAX when none qualifies.
uint32_t findMemoryType(const Device& device, uint32_t typeBits, VkMemoryPropertyFlags required,
                        VkMemoryPropertyFlags preferred = 0);

// Size in bytes of one texel of the formats the harness uses (R32F, RG32F, RGBA32F, R16F,
// RG16F, RGBA16F, R8/RGBA8 UNORM, R32_UINT, RG32_UINT); 0 for anything else.
uint32_t formatTexelSize(VkFormat format);
VkFormat toVkFormat(Format format);
uint32_t formatChannelCount(VkFormat format);

} // namespace glint::vk
