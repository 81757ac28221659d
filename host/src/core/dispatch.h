// Dispatch sizing and constant packing: plain arithmetic, unit-tested without a GPU.
#pragma once

#include "glint/glint_pass.h"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

namespace glint::core {

// Vulkan guarantees at least 65535 groups per dimension (maxComputeWorkGroupCount).
inline constexpr std::uint32_t kMaxGroupsPerDimension = 65535;

constexpr std::uint32_t divideRoundUp(std::uint32_t value, std::uint32_t divisor) {
    return value / divisor + (value % divisor != 0 ? 1u : 0u);
}

// Groups covering a width x height x depth grid of threads with the given group size. Every
// thread of the grid gets an invocation; the shader discards the overhang.
DirectDispatch gridFor(std::uint32_t width, std::uint32_t height, std::uint32_t depth,
                       const std::uint32_t groupSize[3]);

// Copies a constants struct shared with HLSL (glint_<effect>_constants.h) into a pass. The
// struct is the single definition of the layout; static_asserts in its header pin it.
template <typename Constants> std::vector<std::byte> packConstants(const Constants& constants) {
    static_assert(std::is_trivially_copyable_v<Constants>);
    static_assert(sizeof(Constants) % 16 == 0, "constant blocks are whole 16-byte registers");
    std::vector<std::byte> bytes(sizeof(Constants));
    std::memcpy(bytes.data(), &constants, sizeof(Constants));
    return bytes;
}

} // namespace glint::core
