// The validation rules of capture format v1, shared by the reader and the writer so that
// every file glint writes is one it accepts, and every file it accepts satisfies the same
// contract. Each check returns the first problem as one line of text (without the file
// name; the caller adds it) or nothing when the frame is valid.
#pragma once

#include "capture/capture_frame.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace glint::capture {

// Limits checked against the header before any pixel memory is allocated.
inline constexpr std::uint32_t kMaxDimension = 16384;
inline constexpr std::uint64_t kMaxPixels = std::uint64_t{1} << 26;  // 8192 x 8192
inline constexpr std::uint64_t kMaxSamples = std::uint64_t{1} << 29; // pixels x channels (2 GiB of float)
inline constexpr std::size_t kMaxChannels = 64;

bool isKnownEffect(std::string_view effect); // "reflections" | "shadows" | "depth_pyramid"

// Dimensions against the limits above.
std::optional<std::string> checkDimensions(std::uint64_t width, std::uint64_t height);

// Camera: finite matrices, invertible projection, near/far consistent with the convention.
std::optional<std::string> checkCamera(const Camera& camera);

// Everything the header can tell: version, size, camera, effects, layer and channel names,
// storage types, the layers and channels each declared effect requires.
std::optional<std::string> checkHeader(const FrameHeader& header);

// checkHeader plus the pixel buffer sizes (for frames built in memory before writing).
std::optional<std::string> checkFrame(const Frame& frame);

} // namespace glint::capture
