// glint public API: the reflections effect, composed.
//
// SSSR (glint_sssr.h) and, when asked for, the reflections denoiser (glint_reflections_denoiser.h)
// in one plan, joined by resource name: the denoiser's passes go between the intersection and
// the composite and overwrite "sssr_radiance" with the denoised result, so the composite
// applies it; SSSR's "sssr_variance_history" is the variance the denoiser resolved last frame
// (a zero 1x1 image without the denoiser). The tables SSSR reads ("sssr_blue_noise_source", and
// "sssr_brdf_lut" with the composite) are owned images with their texels declared in the plan.
// The plan names its outputs and counters (glint_effect.h).
#pragma once

#include "glint/glint_pass.h"
#include "glint/glint_reflections_denoiser.h"
#include "glint/glint_sssr.h"

#include <string>

namespace glint {

// `denoiser` is null, or the denoiser's desc for this frame (sssr.denoise must then be true, and
// sssr.storeRays true for the ratio-estimator path).
Result planReflections(const SssrDesc& sssr, const ReflectionsDenoiserDesc* denoiser, EffectPlan& plan,
                       std::string* error);

} // namespace glint
