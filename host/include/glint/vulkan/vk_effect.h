// Any effect on Vulkan: create / dispatch / destroy around an EffectPlan (glint_pass.h), the
// same three calls for every effect (plans come from the planners of each effect's header, or
// from an effect descriptor, glint_effect.h).
//
// create allocates every image and buffer the plan owns and stages their initial contents
// (tables declared through ImageDesc::initialTexels; everything else zero). The first dispatch
// records that initialization (layouts to GENERAL, clears, table copies) ahead of the passes,
// so create needs no queue. Owned resources persist from frame to frame: they hold the
// histories. Each later frame's plan must declare the same resources (the settings that change
// them need a new instance).
#pragma once

#include "glint/glint_pass.h"
#include "glint/glint_types.h"
#include "glint/vulkan/vk_executor.h"

#include <map>
#include <string>

namespace glint::vk {

struct EffectInstance {
    const Device* device = nullptr;
    std::string effect;
    std::vector<ImageDesc> imageDescs; // as created, to check later plans against
    std::vector<BufferDesc> bufferDescs;
    std::map<std::string, Image> images;
    std::map<std::string, Buffer> buffers;
    Buffer staging; // initial texels, copied on the first dispatch
    bool initialized = false;
};

Result createEffect(const Device& device, const EffectPlan& plan, EffectInstance& effect, std::string* error);

// Records one frame of `plan`. `inputs` holds the application's images and buffers by the
// plan's names, all in VK_IMAGE_LAYOUT_GENERAL and written before the command buffer reaches
// the plan. InvalidArgument when the plan's resources differ from the created ones or an input
// is missing; Unsupported with the executor's message when the plan does not match its shaders
// (a bug, not an input error).
Result dispatchEffect(EffectInstance& effect, Executor& executor, VkCommandBuffer cmd, const EffectPlan& plan,
                      const ResourceTable& inputs, const PassHooks& hooks, std::string* error);

// Records the initialization that the first dispatch would record (layouts to GENERAL, clears,
// table copies) now, so that the application may overwrite an owned resource (e.g. seed a
// history) before the first frame; the first dispatch then skips it. Nothing once initialized.
void initializeEffect(EffectInstance& effect, VkCommandBuffer cmd);

void destroyEffect(EffectInstance& effect);

} // namespace glint::vk
