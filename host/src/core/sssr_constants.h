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

// A pass of `pipeline` with the SSSR entries' group shape and constants binding.
Pass sssrPass(const char* name, std::string pipeline, std::uint32_t groupX, std::uint32_t groupY,
              const std::vector<std::byte>& constants);
// SSSR classification's G-buffer reads (the variance history under `varianceHistory`) and its
// roughness, radiance and confidence writes; the intersection's reads and its radiance and
// confidence read-writes. Each entry adds its own lists and counters.
std::vector<ResourceUse> sssrClassifyUses(const std::string& varianceHistory);
std::vector<ResourceUse> sssrIntersectUses();
// The blue-noise pass, which also turns `counters` (SSSR's four-word layout first) into
// `arguments`; with `tiles` (8x8 tiles of the frame), it also compacts "sssr_ray_scratch" into
// "sssr_ray_list" (the pass "compact_noise_args").
Pass sssrBlueNoisePass(const std::vector<std::byte>& constants, const std::string& counters,
                       const std::string& arguments, std::uint32_t tiles = 0);

// SSSR's composite: "color" + the reflection image desc.compositeReflection x split-sum specular,
// into "composite" (RGBA32F); reads "sssr_brdf_lut" and "base_color_metallic".
Pass sssrCompositePass(const SssrDesc& desc, const std::vector<std::byte>& constants);

shaders::GLINT_SssrConstants makeSssrConstants(const SssrDesc& desc, const Matrix4& viewFromClip,
                                               const Matrix4& worldFromView);

} // namespace glint::core
