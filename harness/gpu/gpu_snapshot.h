// A copy of one image taken in the middle of a recorded frame, for intermediates that a later
// pass overwrites in place (the denoiser writes over SSSR's radiance; resolve over the
// prefilter's variance). Record it from a vk::PassHooks callback.
#pragma once

#include <gpu/gpu_context.h>

#include "glint/vulkan/vk_resources.h"

namespace glint::gpu {

struct Snapshot {
    const Context& context;
    vk::Image image;

    // Level 0 of `format`, cleared to zero.
    Snapshot(const Context& context, std::uint32_t width, std::uint32_t height, VkFormat format);
    ~Snapshot();
    Snapshot(const Snapshot&) = delete;
    Snapshot& operator=(const Snapshot&) = delete;

    // Copies level 0 of `source` (same size and format, GENERAL layout) with the barriers that
    // order it after the previous dispatch's writes and before the next dispatch.
    void record(VkCommandBuffer cmd, const vk::Image& source) const;
};

} // namespace glint::gpu
