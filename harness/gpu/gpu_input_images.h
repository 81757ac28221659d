// The application images an effect reads (glint_effect.h InputKind), one per kind, created on
// first upload and kept: several effects of one replay share them. Full inputs are 32-bit
// floats, so a test's CPU reference sees exactly what the GPU reads; compact inputs take the
// formats an engine would bind (16-bit normals, colour and motion, R16F roughness, R8
// visibility, RGBA8 base colour), for benchmarks.
#pragma once

#include <gpu/gpu_context.h>
#include <gpu/gpu_transfer.h>

#include "glint/glint_effect.h"
#include "glint/vulkan/vk_resources.h"

#include <map>
#include <vector>

namespace glint::gpu {

class InputImages {
  public:
    InputImages(const Context& context, Extent2D size, bool compact);
    ~InputImages();
    InputImages(const InputImages&) = delete;
    InputImages& operator=(const InputImages&) = delete;

    // W x H texels with `channels` floats each (Material: roughness in channel 0).
    void upload(InputKind kind, const std::vector<float>& texels, std::uint32_t channels);
    // The same, queued in `batch` (the image exists once this returns; its texels on submit).
    void upload(TransferBatch& batch, InputKind kind, const std::vector<float>& texels,
                std::uint32_t channels);
    // An RGBA lat-long map, level 0; the rest of the chain is box-filtered here.
    void uploadEnvironment(std::uint32_t width, std::uint32_t height, const std::vector<float>& rgba);
    const vk::Image* find(InputKind kind) const;

  private:
    const Context& context_;
    Extent2D size_;
    bool compact_ = false;
    std::map<InputKind, vk::Image> images_;
};

// Box-filtered mip chain of an RGBA lat-long map: levels[0] is the input.
std::vector<std::vector<float>> environmentMips(std::uint32_t width, std::uint32_t height,
                                                const std::vector<float>& rgba);

} // namespace glint::gpu
