// Argument checks every plan<Effect> function shares, so the limits and the error format
// are written once.
#pragma once

#include "glint/glint_types.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace glint::core {

// The largest render size any effect accepts in each dimension.
inline constexpr std::uint32_t kMaxExtent = 16384;

constexpr bool validExtent(Extent2D size) {
    return size.width > 0 && size.height > 0 && size.width <= kMaxExtent && size.height <= kMaxExtent;
}

// Sets *error (when given) to "<effect>: <message>" and returns Result::InvalidArgument.
Result invalidArgument(std::string* error, std::string_view effect, const std::string& message);

} // namespace glint::core
