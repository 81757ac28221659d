// The spelling of every enumeration in file attributes, the manifest and `glint info`.
// Parsing is exact (case-sensitive): a misspelt value is a malformed file, not a default.
#pragma once

#include "capture/capture_frame.h"

#include <optional>
#include <string_view>

namespace glint::capture {

std::string_view toString(DepthConvention v); // "standard" | "reversed" | "reversed_infinite"
std::string_view toString(NormalEncoding v);  // "world_unit" | "world_unorm" | "octahedral"
std::string_view toString(MotionUnits v);     // "uv" | "pixels" | "ndc"
std::string_view toString(SampleType v);      // "HALF" | "FLOAT"

std::optional<DepthConvention> parseDepthConvention(std::string_view s);
std::optional<NormalEncoding> parseNormalEncoding(std::string_view s);
std::optional<MotionUnits> parseMotionUnits(std::string_view s);

} // namespace glint::capture
