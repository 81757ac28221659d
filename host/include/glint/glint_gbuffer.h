// glint public API: G-buffer preparation passes shared by the effects.
//
// Roughness extraction reads one channel of the application's material texture and writes
// GGX alpha (alpha = perceptualRoughness^2), converting exactly once so that no later pass
// has to know how the engine stores roughness (docs/conventions.md §4).
#pragma once

#include "glint/glint_pass.h"
#include "glint/glint_types.h"

#include <string>

namespace glint {

struct RoughnessExtractionDesc {
    Extent2D size;                     // render size in pixels, 1..16384 each
    std::uint32_t materialChannel = 0; // 0..3: which channel of the material texture holds roughness
    bool inputIsPerceptual = true;     // true: the channel holds r, square it; false: it holds alpha
    bool halfPrecisionOutput = false;  // write R16F instead of R32F (the fp16 permutation)
};

// Resources the plan refers to: "material" (read, any float/unorm RGBA texture) and
// "roughness" (written, R32F or R16F as chosen above, storage image).
Result planRoughnessExtraction(const RoughnessExtractionDesc& desc, EffectPlan& plan, std::string* error);

} // namespace glint
