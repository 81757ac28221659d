// SSSR's desc checks and constants, shared by the SSSR plan and the hybrid plan (which runs the
// SSSR per-pixel decision and traversal with the same constants).
#pragma once

#include "core/camera.h"
#include "glint/glint_sssr.h"
#include "glint/sssr/glint_sssr_constants.h"

#include <string>

namespace glint::core {

// Empty when `desc` is valid, else one line saying what is wrong.
std::string checkSssrDesc(const SssrDesc& desc);

shaders::GLINT_SssrConstants makeSssrConstants(const SssrDesc& desc, const Matrix4& viewFromClip,
                                               const Matrix4& worldFromView);

} // namespace glint::core
