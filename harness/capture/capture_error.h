// The one error type of the capture library.
//
// what() is always a single line "<file>: <problem>", so that a tool can print it as is
// and a user sees which file is bad and why without a stack of nested messages.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace glint::capture {

struct CaptureError : std::runtime_error {
    CaptureError(const std::filesystem::path& file, std::string_view problem);
};

[[noreturn]] void fail(const std::filesystem::path& file, std::string_view problem);

// Newlines and other control characters become spaces, runs of spaces collapse, and the
// result is trimmed: third-party messages (OpenEXR, nlohmann::json) may span lines.
std::string oneLine(std::string_view text);

} // namespace glint::capture
