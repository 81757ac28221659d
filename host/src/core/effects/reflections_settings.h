// The reflections effect's settings and the descs it makes from them, shared with the hybrid
// effect (which traces, denoises and composites with the same SSSR and denoiser settings).
#pragma once

#include "glint/glint_effect.h"
#include "glint/glint_reflections_denoiser.h"
#include "glint/glint_settings.h"
#include "glint/glint_sssr.h"

#include <vector>

namespace glint::core {

std::vector<SettingDesc> reflectionsSettings();
// The application images SSSR, the denoiser and the composite read.
std::vector<InputDesc> reflectionsInputs();
SssrDesc sssrDesc(const FrameInfo& frame, const SettingValues& settings);
ReflectionsDenoiserDesc reflectionsDenoiserDesc(const FrameInfo& frame, const SettingValues& settings,
                                                const SssrDesc& sssr);
// How reflections are scored (against reference.reflection over the glossy pixels), previewed
// and shown in a report, with the tolerances of the float passes (everything after the
// intersection). The reflections and the hybrid share it; each adds its own study.
EffectEvaluation reflectionsEvaluation();

} // namespace glint::core
