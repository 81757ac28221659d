// The reflections effect on Vulkan: create / dispatch / destroy around glint::planSssr
// (docs/sssr.md, "Host API"). create allocates every resource the effect owns (the plan's
// images and buffers, the blue-noise source, the BRDF table and a zero variance history when
// the application has none); the first dispatch records their initialization (layouts,
// zeroed counters, table uploads) ahead of the passes, so create needs no queue.
#pragma once

#include "glint/glint_reflections_denoiser.h"
#include "glint/glint_sssr.h"
#include "vulkan/vk_executor.h"

#include <map>
#include <string>

namespace glint::vk {

// The application's images, all in VK_IMAGE_LAYOUT_GENERAL and written before the dispatch.
struct SssrInputs {
    const Image* depth = nullptr;
    const Image* normals = nullptr;
    const Image* material = nullptr;
    const Image* color = nullptr;
    const Image* motion = nullptr;
    const Image* environment = nullptr;
    const Image* varianceHistory = nullptr;     // optional: a zero image is used without one
    const Image* baseColorMetallic = nullptr;   // with desc.composite
    const Image* compositeReflection = nullptr; // with desc.composite when it names an outside image
};

struct SssrEffect {
    const Device* device = nullptr;
    SssrDesc desc; // the creation desc: size and permutation-changing options are fixed
    std::map<std::string, Image> images;
    std::map<std::string, Buffer> buffers;
    Buffer staging; // the tables, copied on the first dispatch
    bool initialized = false;
};

Result createSssr(const Device& device, const SssrDesc& desc, SssrEffect& effect, std::string* error);

// Records one frame. `frame` may change per frame everything but the size and the options
// that change resources (thicknessAware, debugOutput, halfPrecisionStorage, storeRays,
// composite, denoise); frameIndex, camera and thresholds are read from it. The denoiser's
// ratio-estimator path needs the effect created with storeRays. With `denoiser` (the effect
// created with denoise), the reflections denoiser runs after the intersection and overwrites
// "sssr_radiance" with the denoised result; its variance is next frame's TVGT history. A plan that does not
// match its shaders (a bug, not an input error) returns Unsupported with the executor's message.
Result dispatchSssr(SssrEffect& effect, Executor& executor, VkCommandBuffer cmd, const SssrDesc& frame,
                    const SssrInputs& inputs, const PassHooks& hooks, std::string* error,
                    const ReflectionsDenoiserDesc* denoiser = nullptr);

void destroySssr(SssrEffect& effect);

} // namespace glint::vk
