// Environment maps of a capture sequence: one OpenEXR file with channels R, G, B (no layer
// prefix, as OpenEXR environment maps conventionally have them) and the standard `envmap`
// attribute saying lat-long or cube (docs/capture-format.md, "Environment maps").
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

namespace glint::capture {

enum class EnvironmentLayout {
    LatLong, // OpenEXR ENVMAP_LATLONG: u = longitude, v = latitude, +y up at the top row
    Cube,    // OpenEXR ENVMAP_CUBE: width x (6 * width), faces +X,-X,+Y,-Y,+Z,-Z top to bottom
};

struct Environment {
    EnvironmentLayout layout = EnvironmentLayout::LatLong;
    std::uint32_t width = 0, height = 0;
    std::vector<float> rgb;    // interleaved R,G,B, row-major, origin top-left
    std::size_t nonFinite = 0; // counted on read
};

// Reads R, G, B (HALF or FLOAT) of an environment map; other channels are ignored. A file
// without the `envmap` attribute is an error, or, when `unmarked` is given, of that layout
// (renders of other tools, which do not write the attribute).
Environment readEnvironment(const std::filesystem::path& file,
                            std::optional<EnvironmentLayout> unmarked = std::nullopt);
// Writes R, G, B as FLOAT (environment radiance easily exceeds the HALF range), ZIP.
void writeEnvironment(const std::filesystem::path& file, const Environment& environment);

} // namespace glint::capture
