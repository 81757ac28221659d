// Moving data between the CPU and glint's buffers and images, synchronously: every call (and
// every TransferBatch::submit) records one command buffer, submits it and waits (submitAndWait),
// so the data is on the GPU (or in the returned vector) when it returns. Meant for tests and
// tools, not frame loops.
//
// Image layout convention: the harness keeps every image that a pass reads or writes in
// VK_IMAGE_LAYOUT_GENERAL (legal for storage, sampled and transfer use alike), so no code
// has to track layouts.
//   - uploadImage* and clearImage leave the mip levels they write in GENERAL. They overwrite
//     whole mips and therefore ignore (discard) the previous layout and contents.
//   - readbackImage* expects the mip in GENERAL and leaves it there.
//   - A freshly created image is UNDEFINED; an output image that no pass is guaranteed to
//     cover completely should be cleared first (which also moves it to GENERAL).
// Synchronization is by pipeline barriers, not by the fence wait: each call opens with a
// barrier after all earlier work on the queue and closes with one before all later work, so
// it may sit between any two dispatches (synchronization validation agrees).
// Mapped (Upload/Readback) buffers are read and written through their mapping; the caller
// must not have GPU work on them in flight, which holds whenever work went through
// submitAndWait.
#pragma once

#include <gpu/gpu_context.h>

#include "glint/vulkan/vk_resources.h"

#include <cstddef>
#include <span>
#include <vector>

namespace glint::gpu {

// Writes data at `offset` into any buffer: through its mapping for Upload/Readback buffers,
// through a staging buffer and vkCmdCopyBuffer for device-local ones.
void uploadBuffer(const Context& context, const vk::Buffer& buffer, std::span<const std::byte> data,
                  VkDeviceSize offset = 0);
// size == VK_WHOLE_SIZE reads from offset to the end.
std::vector<std::byte> readbackBuffer(const Context& context, const vk::Buffer& buffer,
                                      VkDeviceSize offset = 0, VkDeviceSize size = VK_WHOLE_SIZE);

template <typename T>
void uploadBuffer(const Context& context, const vk::Buffer& buffer, std::span<const T> values,
                  VkDeviceSize offset = 0) {
    uploadBuffer(context, buffer, std::as_bytes(values), offset);
}

// One mip level as tightly packed rows of texels in the image's own format
// (mipWidth * mipHeight * formatTexelSize bytes).
void uploadImageBytes(const Context& context, const vk::Image& image, std::span<const std::byte> texels,
                      uint32_t mip = 0);
std::vector<std::byte> readbackImageBytes(const Context& context, const vk::Image& image, uint32_t mip = 0);

// One mip level from floats with `channels` values per texel, converted on the CPU to the
// image's format as described by encodeTexels (gpu_texel_format.h): 16F rounded to nearest
// even, UNORM8 clamped and rounded, fewer channels than the format padded with 0 (alpha 1).
void uploadImage(const Context& context, const vk::Image& image, std::span<const float> texels,
                 uint32_t channels, uint32_t mip = 0);
// One mip level as floats, formatChannelCount(image.format) per texel.
std::vector<float> readbackImage(const Context& context, const vk::Image& image, uint32_t mip = 0);

// Fills every mip with `value` (in the format's own terms: floats for float and UNORM formats,
// uint32 for UINT formats) and leaves the whole image in GENERAL.
void clearImage(const Context& context, const vk::Image& image, const VkClearColorValue& value);

// Image transfers gathered into one submission: a frame's inputs, or every output an effect
// wrote, cost one vkQueueSubmit and two staging buffers instead of one of each per image.
// Uploads are encoded and copied aside when queued (the caller's texels may go at once) and
// reach their images on submit(); readbacks are copied on submit(), after the batch's uploads,
// and are read with bytes()/floats() once it returned. Layouts and barriers as above. A mip may
// be uploaded once per batch. The single-image calls above are batches of one.
class TransferBatch {
  public:
    explicit TransferBatch(const Context& context);
    ~TransferBatch();
    TransferBatch(const TransferBatch&) = delete;
    TransferBatch& operator=(const TransferBatch&) = delete;

    void uploadImageBytes(const vk::Image& image, std::span<const std::byte> texels, uint32_t mip = 0);
    void uploadImage(const vk::Image& image, std::span<const float> texels, uint32_t channels,
                     uint32_t mip = 0);
    // A ticket for bytes() or floats() after submit().
    std::size_t readbackImage(const vk::Image& image, uint32_t mip = 0);
    // Records, submits and waits; a batch is submitted once. With nothing queued, submits nothing.
    void submit();
    std::vector<std::byte> bytes(std::size_t ticket) const;
    // formatChannelCount(image.format) floats per texel.
    std::vector<float> floats(std::size_t ticket) const;

  private:
    struct Upload {
        const vk::Image* image;
        uint32_t mip;
        VkDeviceSize offset;
    };
    struct Readback {
        const vk::Image* image;
        uint32_t mip;
        VkDeviceSize offset, size;
    };
    const Context& context_;
    std::vector<std::byte> uploadBytes_; // each upload's texels at its offset
    std::vector<Upload> uploads_;
    std::vector<Readback> readbacks_;
    VkDeviceSize readbackSize_ = 0;
    vk::Buffer uploadStaging_, readbackStaging_;
    bool submitted_ = false;
};

uint32_t mipWidth(const vk::Image& image, uint32_t mip);
uint32_t mipHeight(const vk::Image& image, uint32_t mip);

} // namespace glint::gpu
