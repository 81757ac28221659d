// glint public API: basic types shared by every effect.
#pragma once

#include <cstdint>

namespace glint {

// Result codes of the public API. Internal code may throw; nothing throws across it.
enum class Result : std::int32_t {
    Ok = 0,
    InvalidArgument = 1, // a desc field is out of range; the message says which
    Unsupported = 2,     // the device or build lacks something the request needs
    DeviceError = 3,     // a Vulkan call failed
};

const char* resultName(Result result);

struct Extent2D {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
};

} // namespace glint
