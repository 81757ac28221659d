// Staging copies with explicit barriers. Every transfer (a single call or a batch) is one
// submitAndWait; the staging buffers live only as long as the call or the batch.
#include <gpu/gpu_transfer.h>

#include <gpu/gpu_texel_format.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

namespace glint::gpu {

namespace {

constexpr VkAccessFlags kAnyAccess = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;

// Destroys its buffer on every path out of a transfer, exceptions included.
struct StagingBuffer {
    const vk::Device& device;
    vk::Buffer buffer;
    StagingBuffer(const vk::Device& d, VkDeviceSize size, VkBufferUsageFlags usage, vk::MemoryUse use)
        : device(d), buffer(vk::createBuffer(d, size, usage, use)) {}
    ~StagingBuffer() { vk::destroyBuffer(device, buffer); }
    StagingBuffer(const StagingBuffer&) = delete;
    StagingBuffer& operator=(const StagingBuffer&) = delete;
};

void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags srcStage, VkAccessFlags srcAccess,
                   VkPipelineStageFlags dstStage, VkAccessFlags dstAccess) {
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = srcAccess;
    barrier.dstAccessMask = dstAccess;
    vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

struct ImageBarrier {
    VkImageLayout oldLayout;
    VkImageLayout newLayout;
    VkPipelineStageFlags srcStage;
    VkAccessFlags srcAccess;
    VkPipelineStageFlags dstStage;
    VkAccessFlags dstAccess;
};

void imageBarrier(VkCommandBuffer cmd, const vk::Image& image, uint32_t baseMip, uint32_t mipCount,
                  const ImageBarrier& b) {
    VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    barrier.srcAccessMask = b.srcAccess;
    barrier.dstAccessMask = b.dstAccess;
    barrier.oldLayout = b.oldLayout;
    barrier.newLayout = b.newLayout;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image.image;
    barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, baseMip, mipCount, 0, 1};
    vkCmdPipelineBarrier(cmd, b.srcStage, b.dstStage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

VkDeviceSize mipByteSize(const vk::Image& image, uint32_t mip, const char* function) {
    if (mip >= image.mipLevels) {
        throw std::invalid_argument(std::string(function) + ": mip " + std::to_string(mip) +
                                    " of an image with " + std::to_string(image.mipLevels) + " levels");
    }
    const uint32_t texelSize = vk::formatTexelSize(image.format);
    if (texelSize == 0) {
        throw std::invalid_argument(std::string(function) + ": VkFormat " +
                                    std::to_string(static_cast<int>(image.format)) +
                                    " is not a harness format");
    }
    return VkDeviceSize{mipWidth(image, mip)} * mipHeight(image, mip) * texelSize;
}

// One whole mip, tightly packed in the buffer from `offset`.
VkBufferImageCopy mipCopyRegion(const vk::Image& image, uint32_t mip, VkDeviceSize offset) {
    VkBufferImageCopy region{};
    region.bufferOffset = offset;
    region.bufferRowLength = 0; // tightly packed
    region.bufferImageHeight = 0;
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, mip, 0, 1};
    region.imageExtent = {mipWidth(image, mip), mipHeight(image, mip), 1};
    return region;
}

void checkRange(const vk::Buffer& buffer, VkDeviceSize offset, VkDeviceSize size, const char* function) {
    if (offset > buffer.size || size > buffer.size - offset) {
        throw std::invalid_argument(std::string(function) + ": bytes [" + std::to_string(offset) + ", " +
                                    std::to_string(offset + size) + ") outside a buffer of " +
                                    std::to_string(buffer.size));
    }
}

// Makes the device's writes to mapped memory visible to the host. Waiting on a fence alone
// does not: the spec requires a barrier to the host domain before the signal.
void makeDeviceWritesHostVisible(const Context& context) {
    submitAndWait(context, [](VkCommandBuffer cmd) {
        memoryBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_MEMORY_WRITE_BIT,
                      VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
    });
}

} // namespace

uint32_t mipWidth(const vk::Image& image, uint32_t mip) {
    return std::max(1u, image.width >> mip);
}
uint32_t mipHeight(const vk::Image& image, uint32_t mip) {
    return std::max(1u, image.height >> mip);
}

void uploadBuffer(const Context& context, const vk::Buffer& buffer, std::span<const std::byte> data,
                  VkDeviceSize offset) {
    checkRange(buffer, offset, data.size(), "glint::gpu::uploadBuffer");
    if (data.empty()) return;
    const vk::Device& device = context.device;
    if (buffer.mapped) {
        // Host writes before a vkQueueSubmit are visible to it without a barrier.
        std::memcpy(static_cast<std::byte*>(buffer.mapped) + offset, data.data(), data.size());
        vk::flushBuffer(device, buffer);
        return;
    }
    StagingBuffer staging(device, data.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, vk::MemoryUse::Upload);
    std::memcpy(staging.buffer.mapped, data.data(), data.size());
    vk::flushBuffer(device, staging.buffer);
    submitAndWait(context, [&](VkCommandBuffer cmd) {
        memoryBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_MEMORY_WRITE_BIT,
                      VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
        const VkBufferCopy region{0, offset, data.size()};
        vkCmdCopyBuffer(cmd, staging.buffer.buffer, buffer.buffer, 1, &region);
        memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, kAnyAccess);
    });
}

std::vector<std::byte> readbackBuffer(const Context& context, const vk::Buffer& buffer, VkDeviceSize offset,
                                      VkDeviceSize size) {
    if (size == VK_WHOLE_SIZE) size = offset <= buffer.size ? buffer.size - offset : 0;
    checkRange(buffer, offset, size, "glint::gpu::readbackBuffer");
    std::vector<std::byte> result(size);
    if (size == 0) return result;
    const vk::Device& device = context.device;
    if (buffer.mapped) {
        makeDeviceWritesHostVisible(context);
        vk::invalidateBuffer(device, buffer);
        std::memcpy(result.data(), static_cast<const std::byte*>(buffer.mapped) + offset, size);
        return result;
    }
    StagingBuffer staging(device, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUse::Readback);
    submitAndWait(context, [&](VkCommandBuffer cmd) {
        memoryBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_MEMORY_WRITE_BIT,
                      VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
        const VkBufferCopy region{offset, 0, size};
        vkCmdCopyBuffer(cmd, buffer.buffer, staging.buffer.buffer, 1, &region);
        // To the host for the staging buffer, and an execution dependency so that later
        // writes to `buffer` wait for this read.
        memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_HOST_BIT | VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                      VK_ACCESS_HOST_READ_BIT);
    });
    vk::invalidateBuffer(device, staging.buffer);
    std::memcpy(result.data(), staging.buffer.mapped, size);
    return result;
}

void uploadImageBytes(const Context& context, const vk::Image& image, std::span<const std::byte> texels,
                      uint32_t mip) {
    TransferBatch batch(context);
    batch.uploadImageBytes(image, texels, mip);
    batch.submit();
}

std::vector<std::byte> readbackImageBytes(const Context& context, const vk::Image& image, uint32_t mip) {
    TransferBatch batch(context);
    const std::size_t ticket = batch.readbackImage(image, mip);
    batch.submit();
    return batch.bytes(ticket);
}

void uploadImage(const Context& context, const vk::Image& image, std::span<const float> texels,
                 uint32_t channels, uint32_t mip) {
    TransferBatch batch(context);
    batch.uploadImage(image, texels, channels, mip);
    batch.submit();
}

std::vector<float> readbackImage(const Context& context, const vk::Image& image, uint32_t mip) {
    TransferBatch batch(context);
    const std::size_t ticket = batch.readbackImage(image, mip);
    batch.submit();
    return batch.floats(ticket);
}

void clearImage(const Context& context, const vk::Image& image, const VkClearColorValue& value) {
    submitAndWait(context, [&](VkCommandBuffer cmd) {
        imageBarrier(cmd, image, 0, image.mipLevels,
                     {VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                      VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_MEMORY_WRITE_BIT,
                      VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT});
        const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, image.mipLevels, 0, 1};
        vkCmdClearColorImage(cmd, image.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &value, 1, &range);
        imageBarrier(cmd, image, 0, image.mipLevels,
                     {VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                      VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, kAnyAccess});
    });
}

TransferBatch::TransferBatch(const Context& context) : context_(context) {}

TransferBatch::~TransferBatch() {
    if (uploadStaging_.buffer) vk::destroyBuffer(context_.device, uploadStaging_);
    if (readbackStaging_.buffer) vk::destroyBuffer(context_.device, readbackStaging_);
}

namespace {
// Copy offsets in a staging buffer: a multiple of every harness texel size (at most 16 bytes).
VkDeviceSize alignedOffset(VkDeviceSize offset) {
    return (offset + 15) & ~VkDeviceSize{15};
}
} // namespace

void TransferBatch::uploadImageBytes(const vk::Image& image, std::span<const std::byte> texels,
                                     uint32_t mip) {
    if (submitted_) throw std::logic_error("glint::gpu::TransferBatch: upload after submit");
    const VkDeviceSize size = mipByteSize(image, mip, "glint::gpu::uploadImageBytes");
    if (texels.size() != size) {
        throw std::invalid_argument("glint::gpu::uploadImageBytes: " + std::to_string(texels.size()) +
                                    " bytes for a mip of " + std::to_string(size));
    }
    for (const Upload& u : uploads_)
        if (u.image == &image && u.mip == mip)
            throw std::logic_error("glint::gpu::TransferBatch: mip " + std::to_string(mip) +
                                   " uploaded twice in one batch");
    const VkDeviceSize offset = alignedOffset(uploadBytes_.size());
    uploadBytes_.resize(offset + size);
    std::memcpy(uploadBytes_.data() + offset, texels.data(), size);
    uploads_.push_back({&image, mip, offset});
}

void TransferBatch::uploadImage(const vk::Image& image, std::span<const float> texels, uint32_t channels,
                                uint32_t mip) {
    const VkDeviceSize size = mipByteSize(image, mip, "glint::gpu::uploadImage");
    const size_t texelCount = size_t{mipWidth(image, mip)} * mipHeight(image, mip);
    if (channels == 0 || texels.size() != texelCount * channels) {
        throw std::invalid_argument("glint::gpu::uploadImage: " + std::to_string(texels.size()) +
                                    " floats for " + std::to_string(texelCount) + " texels of " +
                                    std::to_string(channels) + " channels");
    }
    std::vector<std::byte> bytes(size);
    encodeTexels(image.format, texels, channels, bytes);
    uploadImageBytes(image, bytes, mip);
}

std::size_t TransferBatch::readbackImage(const vk::Image& image, uint32_t mip) {
    if (submitted_) throw std::logic_error("glint::gpu::TransferBatch: readback after submit");
    const VkDeviceSize size = mipByteSize(image, mip, "glint::gpu::readbackImageBytes");
    const VkDeviceSize offset = alignedOffset(readbackSize_);
    readbacks_.push_back({&image, mip, offset, size});
    readbackSize_ = offset + size;
    return readbacks_.size() - 1;
}

void TransferBatch::submit() {
    if (submitted_) throw std::logic_error("glint::gpu::TransferBatch: submitted twice");
    submitted_ = true;
    if (uploads_.empty() && readbacks_.empty()) return;
    const vk::Device& device = context_.device;
    if (!uploads_.empty()) {
        uploadStaging_ = vk::createBuffer(device, uploadBytes_.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                          vk::MemoryUse::Upload);
        std::memcpy(uploadStaging_.mapped, uploadBytes_.data(), uploadBytes_.size());
        vk::flushBuffer(device, uploadStaging_);
    }
    if (!readbacks_.empty())
        readbackStaging_ = vk::createBuffer(device, readbackSize_, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                            vk::MemoryUse::Readback);
    submitAndWait(context_, [&](VkCommandBuffer cmd) {
        for (const Upload& u : uploads_) {
            // From UNDEFINED: the whole mip is overwritten, so its old layout and contents do not
            // matter, and the upload works on new and used images alike.
            imageBarrier(cmd, *u.image, u.mip, 1,
                         {VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                          VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_MEMORY_WRITE_BIT,
                          VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT});
            const VkBufferImageCopy region = mipCopyRegion(*u.image, u.mip, u.offset);
            vkCmdCopyBufferToImage(cmd, uploadStaging_.buffer, u.image->image,
                                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
            imageBarrier(cmd, *u.image, u.mip, 1,
                         {VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                          VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                          VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, kAnyAccess});
        }
        for (const Readback& r : readbacks_) {
            imageBarrier(cmd, *r.image, r.mip, 1,
                         {VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL,
                          VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_MEMORY_WRITE_BIT,
                          VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT});
            const VkBufferImageCopy region = mipCopyRegion(*r.image, r.mip, r.offset);
            vkCmdCopyImageToBuffer(cmd, r.image->image, VK_IMAGE_LAYOUT_GENERAL, readbackStaging_.buffer, 1,
                                   &region);
            // Later writes to the image must wait for this read (an execution dependency suffices).
            imageBarrier(cmd, *r.image, r.mip, 1,
                         {VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                          VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0});
        }
        if (!readbacks_.empty())
            memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                          VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
    });
    if (!readbacks_.empty()) vk::invalidateBuffer(device, readbackStaging_);
}

std::vector<std::byte> TransferBatch::bytes(std::size_t ticket) const {
    if (!submitted_ || ticket >= readbacks_.size())
        throw std::logic_error("glint::gpu::TransferBatch: no readback " + std::to_string(ticket) + " yet");
    const Readback& r = readbacks_[ticket];
    const std::byte* first = static_cast<const std::byte*>(readbackStaging_.mapped) + r.offset;
    return std::vector<std::byte>(first, first + r.size);
}

std::vector<float> TransferBatch::floats(std::size_t ticket) const {
    const vk::Image& image = *readbacks_.at(ticket).image;
    if (!hasFloatConversion(image.format)) {
        throw std::invalid_argument("glint::gpu::readbackImage: VkFormat " +
                                    std::to_string(static_cast<int>(image.format)) +
                                    " has no float conversion (use readbackImageBytes)");
    }
    const std::vector<std::byte> raw = bytes(ticket);
    std::vector<float> result(raw.size() / vk::formatTexelSize(image.format) *
                              vk::formatChannelCount(image.format));
    decodeTexels(image.format, raw, result);
    return result;
}

} // namespace glint::gpu
