// The simulator's embedded SPIR-V (harness/shaders, group "harness"), generated at build
// time by glint_embed_shaders. Give findShader to vk::Executor::findShader.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace glint::scene {

std::span<const std::uint32_t> findShader(std::string_view name);
std::vector<std::string_view> shaderNames();

} // namespace glint::scene
