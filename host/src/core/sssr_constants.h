// SSSR's desc checks and constants, shared by the SSSR plan and the hybrid plan (which runs the
// SSSR per-pixel decision and traversal with the same constants).
#pragma once

#include "core/camera.h"
#include "glint/glint_sssr.h"
#include "glint/sssr/glint_sssr_constants.h"

#include <cstddef>
#include <string>
#include <vector>

namespace glint::core {

// Empty when `desc` is valid, else one line saying what is wrong.
std::string checkSssrDesc(const SssrDesc& desc);

// SSSR's composite: "color" + the reflection image desc.compositeReflection x split-sum specular,
// into "composite" (RGBA32F); reads "sssr_brdf_lut" and "base_color_metallic".
Pass sssrCompositePass(const SssrDesc& desc, const std::vector<std::byte>& constants);

shaders::GLINT_SssrConstants makeSssrConstants(const SssrDesc& desc, const Matrix4& viewFromClip,
                                               const Matrix4& worldFromView);

} // namespace glint::core
