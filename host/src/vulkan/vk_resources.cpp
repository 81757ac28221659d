// Buffers and 2D images with dedicated allocations. glint allocates a handful of resources per
// effect, so one allocation per resource keeps ownership obvious and costs nothing measurable.
#include "glint/vulkan/vk_resources.h"

#include "glint/vulkan/vk_check.h"

#include <algorithm>
#include <bit>
#include <iterator>
#include <stdexcept>
#include <string>

namespace glint::vk {

namespace {

constexpr uint32_t kMaxMipViews = static_cast<uint32_t>(std::size(Image{}.mipViews));

VkDeviceSize roundUp(VkDeviceSize value, VkDeviceSize multiple) {
    return multiple == 0 ? value : (value + multiple - 1) / multiple * multiple;
}

// Mapped memory is allocated in whole non-coherent atoms so that flushing or invalidating the
// buffer's size rounded up to an atom always stays inside the allocation.
VkDeviceSize allocationSize(const Device& device, const VkMemoryRequirements& requirements, bool mapped) {
    if (!mapped) return requirements.size;
    return roundUp(requirements.size, device.properties.limits.nonCoherentAtomSize);
}

struct MemoryChoice {
    VkMemoryPropertyFlags required;
    VkMemoryPropertyFlags preferred;
};

MemoryChoice memoryChoice(MemoryUse use) {
    switch (use) {
    case MemoryUse::DeviceLocal:
        return {VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0};
    case MemoryUse::Upload:
        // Coherent so that CPU writes need no flush on almost every driver; flushBuffer still
        // handles the rare device that only offers non-coherent host-visible memory.
        return {VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT, VK_MEMORY_PROPERTY_HOST_COHERENT_BIT};
    case MemoryUse::Readback:
        // Cached memory makes CPU reads of results fast; uncached reads can be 10x slower.
        return {VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT,
                VK_MEMORY_PROPERTY_HOST_CACHED_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT};
    }
    return {0, 0};
}

// Device-local memory is a preference, not a requirement: a CPU device such as lavapipe may
// report it on every type, and an unusual driver may not report it at all.
uint32_t chooseMemoryType(const Device& device, uint32_t typeBits, MemoryUse use) {
    MemoryChoice choice = memoryChoice(use);
    uint32_t index = UINT32_MAX;
    if (use == MemoryUse::DeviceLocal) {
        index = findMemoryType(device, typeBits, 0, choice.required);
    } else {
        index = findMemoryType(device, typeBits, choice.required, choice.preferred);
    }
    if (index == UINT32_MAX) {
        throw VulkanError(VK_ERROR_OUT_OF_DEVICE_MEMORY,
                          "no Vulkan memory type fits memoryTypeBits 0x" + std::to_string(typeBits));
    }
    return index;
}

struct Allocation {
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkMemoryPropertyFlags flags = 0;
};

Allocation allocate(const Device& device, const VkMemoryRequirements& requirements, MemoryUse use) {
    VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    info.allocationSize = allocationSize(device, requirements, use != MemoryUse::DeviceLocal);
    info.memoryTypeIndex = chooseMemoryType(device, requirements.memoryTypeBits, use);
    Allocation allocation;
    allocation.flags = device.memory.memoryTypes[info.memoryTypeIndex].propertyFlags;
    GLINT_VK_CHECK(vkAllocateMemory(device.device, &info, nullptr, &allocation.memory));
    return allocation;
}

// Covers [0, size) rounded out to whole non-coherent atoms, which createBuffer guarantees to be
// inside the allocation.
VkMappedMemoryRange mappedRange(const Device& device, const Buffer& buffer) {
    VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE};
    range.memory = buffer.memory;
    range.offset = 0;
    range.size = roundUp(buffer.size, device.properties.limits.nonCoherentAtomSize);
    return range;
}

uint32_t maxMipLevels(uint32_t width, uint32_t height) {
    return static_cast<uint32_t>(std::bit_width(std::max(width, height)));
}

VkImageView createView(const Device& device, const Image& image, uint32_t baseMip, uint32_t mipCount) {
    VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    info.image = image.image;
    info.viewType = VK_IMAGE_VIEW_TYPE_2D;
    info.format = image.format;
    info.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, baseMip, mipCount, 0, 1};
    VkImageView view = VK_NULL_HANDLE;
    GLINT_VK_CHECK(vkCreateImageView(device.device, &info, nullptr, &view));
    return view;
}

} // namespace

uint32_t findMemoryType(const Device& device, uint32_t typeBits, VkMemoryPropertyFlags required,
                        VkMemoryPropertyFlags preferred) {
    uint32_t fallback = UINT32_MAX;
    for (uint32_t i = 0; i < device.memory.memoryTypeCount; ++i) {
        if ((typeBits & (1u << i)) == 0) continue;
        VkMemoryPropertyFlags flags = device.memory.memoryTypes[i].propertyFlags;
        if ((flags & required) != required) continue;
        if ((flags & preferred) == preferred) return i;
        if (fallback == UINT32_MAX) fallback = i;
    }
    return fallback;
}

Buffer createBuffer(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use) {
    if (size == 0) throw std::invalid_argument("glint::vk::createBuffer: size must be greater than 0");

    Buffer buffer;
    buffer.size = size;
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = usage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    GLINT_VK_CHECK(vkCreateBuffer(device.device, &info, nullptr, &buffer.buffer));
    try {
        VkMemoryRequirements requirements{};
        vkGetBufferMemoryRequirements(device.device, buffer.buffer, &requirements);
        Allocation allocation = allocate(device, requirements, use);
        buffer.memory = allocation.memory;
        GLINT_VK_CHECK(vkBindBufferMemory(device.device, buffer.buffer, buffer.memory, 0));
        if (use != MemoryUse::DeviceLocal) {
            buffer.coherent = (allocation.flags & VK_MEMORY_PROPERTY_HOST_COHERENT_BIT) != 0;
            GLINT_VK_CHECK(vkMapMemory(device.device, buffer.memory, 0, VK_WHOLE_SIZE, 0, &buffer.mapped));
        }
    } catch (...) {
        destroyBuffer(device, buffer);
        throw;
    }
    return buffer;
}

void destroyBuffer(const Device& device, Buffer& buffer) {
    // Freeing memory unmaps it implicitly, so no vkUnmapMemory is needed.
    if (buffer.buffer) vkDestroyBuffer(device.device, buffer.buffer, nullptr);
    if (buffer.memory) vkFreeMemory(device.device, buffer.memory, nullptr);
    buffer = Buffer{};
}

void flushBuffer(const Device& device, const Buffer& buffer) {
    if (!buffer.mapped || buffer.coherent) return;
    VkMappedMemoryRange range = mappedRange(device, buffer);
    GLINT_VK_CHECK(vkFlushMappedMemoryRanges(device.device, 1, &range));
}

void invalidateBuffer(const Device& device, const Buffer& buffer) {
    if (!buffer.mapped || buffer.coherent) return;
    VkMappedMemoryRange range = mappedRange(device, buffer);
    GLINT_VK_CHECK(vkInvalidateMappedMemoryRanges(device.device, 1, &range));
}

VkImageUsageFlags supportedImageUsage(const Device& device, VkFormat format) {
    VkFormatProperties properties{};
    vkGetPhysicalDeviceFormatProperties(device.physical, format, &properties);
    VkFormatFeatureFlags features = properties.optimalTilingFeatures;
    VkImageUsageFlags usage = 0;
    if (features & VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT) usage |= VK_IMAGE_USAGE_STORAGE_BIT;
    if (features & VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT) usage |= VK_IMAGE_USAGE_SAMPLED_BIT;
    if (usage == 0) return 0;
    if (features & VK_FORMAT_FEATURE_TRANSFER_SRC_BIT) usage |= VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    if (features & VK_FORMAT_FEATURE_TRANSFER_DST_BIT) usage |= VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    return usage;
}

Image createImage2D(const Device& device, uint32_t width, uint32_t height, VkFormat format,
                    uint32_t mipLevels) {
    if (width == 0 || height == 0) {
        throw std::invalid_argument("glint::vk::createImage2D: width and height must be greater than 0");
    }
    uint32_t mipLimit = std::min(maxMipLevels(width, height), kMaxMipViews);
    if (mipLevels == 0 || mipLevels > mipLimit) {
        throw std::invalid_argument("glint::vk::createImage2D: " + std::to_string(mipLevels) +
                                    " mip levels requested for a " + std::to_string(width) + "x" +
                                    std::to_string(height) + " image (1 to " + std::to_string(mipLimit) +
                                    " allowed)");
    }
    VkImageUsageFlags usage = supportedImageUsage(device, format);
    if (usage == 0) {
        throw VulkanError(VK_ERROR_FORMAT_NOT_SUPPORTED, "glint::vk::createImage2D: VkFormat " +
                                                             std::to_string(static_cast<int>(format)) +
                                                             " can be neither sampled nor stored");
    }

    Image image;
    image.format = format;
    image.width = width;
    image.height = height;
    image.mipLevels = mipLevels;

    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {width, height, 1};
    info.mipLevels = mipLevels;
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    GLINT_VK_CHECK(vkCreateImage(device.device, &info, nullptr, &image.image));
    try {
        VkMemoryRequirements requirements{};
        vkGetImageMemoryRequirements(device.device, image.image, &requirements);
        image.memory = allocate(device, requirements, MemoryUse::DeviceLocal).memory;
        GLINT_VK_CHECK(vkBindImageMemory(device.device, image.image, image.memory, 0));
        image.view = createView(device, image, 0, mipLevels);
        for (uint32_t mip = 0; mip < mipLevels; ++mip)
            image.mipViews[mip] = createView(device, image, mip, 1);
    } catch (...) {
        destroyImage(device, image);
        throw;
    }
    return image;
}

void destroyImage(const Device& device, Image& image) {
    for (VkImageView view : image.mipViews) {
        if (view) vkDestroyImageView(device.device, view, nullptr);
    }
    if (image.view) vkDestroyImageView(device.device, image.view, nullptr);
    if (image.image) vkDestroyImage(device.device, image.image, nullptr);
    if (image.memory) vkFreeMemory(device.device, image.memory, nullptr);
    image = Image{};
}

uint32_t formatTexelSize(VkFormat format) {
    switch (format) {
    case VK_FORMAT_R8_UNORM:
        return 1;
    case VK_FORMAT_R8G8_UNORM:
        return 2;
    case VK_FORMAT_R16_SFLOAT:
        return 2;
    case VK_FORMAT_R8G8B8A8_UNORM:
        return 4;
    case VK_FORMAT_R8G8B8A8_SRGB:
        return 4;
    case VK_FORMAT_R16G16_SFLOAT:
        return 4;
    case VK_FORMAT_R32_SFLOAT:
        return 4;
    case VK_FORMAT_R32_UINT:
        return 4;
    case VK_FORMAT_R16G16B16A16_SFLOAT:
        return 8;
    case VK_FORMAT_R32G32_SFLOAT:
        return 8;
    case VK_FORMAT_R32G32_UINT:
        return 8;
    case VK_FORMAT_R32G32B32A32_SFLOAT:
        return 16;
    case VK_FORMAT_R32G32B32A32_UINT:
        return 16;
    default:
        return 0;
    }
}

uint32_t formatChannelCount(VkFormat format) {
    switch (format) {
    case VK_FORMAT_R8_UNORM:
    case VK_FORMAT_R16_SFLOAT:
    case VK_FORMAT_R32_SFLOAT:
    case VK_FORMAT_R32_UINT:
        return 1;
    case VK_FORMAT_R8G8_UNORM:
    case VK_FORMAT_R16G16_SFLOAT:
    case VK_FORMAT_R32G32_SFLOAT:
    case VK_FORMAT_R32G32_UINT:
        return 2;
    case VK_FORMAT_R8G8B8A8_UNORM:
    case VK_FORMAT_R8G8B8A8_SRGB:
    case VK_FORMAT_R16G16B16A16_SFLOAT:
    case VK_FORMAT_R32G32B32A32_SFLOAT:
    case VK_FORMAT_R32G32B32A32_UINT:
        return 4;
    default:
        return 0;
    }
}

VkFormat toVkFormat(Format format) {
    switch (format) {
    case Format::R32Float:
        return VK_FORMAT_R32_SFLOAT;
    case Format::RG32Float:
        return VK_FORMAT_R32G32_SFLOAT;
    case Format::RGBA32Float:
        return VK_FORMAT_R32G32B32A32_SFLOAT;
    case Format::R16Float:
        return VK_FORMAT_R16_SFLOAT;
    case Format::RG16Float:
        return VK_FORMAT_R16G16_SFLOAT;
    case Format::RGBA16Float:
        return VK_FORMAT_R16G16B16A16_SFLOAT;
    case Format::R8Unorm:
        return VK_FORMAT_R8_UNORM;
    case Format::RGBA8Unorm:
        return VK_FORMAT_R8G8B8A8_UNORM;
    case Format::R32Uint:
        return VK_FORMAT_R32_UINT;
    }
    return VK_FORMAT_UNDEFINED;
}

} // namespace glint::vk
