#include "capture/enum_names.h"

#include <array>
#include <utility>

namespace glint::capture {

namespace {
constexpr std::array<std::pair<DepthConvention, std::string_view>, 3> kDepth{{
    {DepthConvention::Standard, "standard"},
    {DepthConvention::Reversed, "reversed"},
    {DepthConvention::ReversedInfinite, "reversed_infinite"},
}};
constexpr std::array<std::pair<NormalEncoding, std::string_view>, 3> kNormal{{
    {NormalEncoding::WorldUnit, "world_unit"},
    {NormalEncoding::WorldUnorm, "world_unorm"},
    {NormalEncoding::Octahedral, "octahedral"},
}};
constexpr std::array<std::pair<MotionUnits, std::string_view>, 3> kMotion{{
    {MotionUnits::Uv, "uv"},
    {MotionUnits::Pixels, "pixels"},
    {MotionUnits::Ndc, "ndc"},
}};

template <typename E, std::size_t N>
std::string_view nameOf(const std::array<std::pair<E, std::string_view>, N>& table, E v) {
    for (const auto& [value, name] : table)
        if (value == v) return name;
    return "?";
}

template <typename E, std::size_t N>
std::optional<E> valueOf(const std::array<std::pair<E, std::string_view>, N>& table, std::string_view s) {
    for (const auto& [value, name] : table)
        if (name == s) return value;
    return std::nullopt;
}
} // namespace

std::string_view toString(DepthConvention v) {
    return nameOf(kDepth, v);
}
std::string_view toString(NormalEncoding v) {
    return nameOf(kNormal, v);
}
std::string_view toString(MotionUnits v) {
    return nameOf(kMotion, v);
}
std::string_view toString(SampleType v) {
    return v == SampleType::Half ? "HALF" : "FLOAT";
}

std::optional<DepthConvention> parseDepthConvention(std::string_view s) {
    return valueOf(kDepth, s);
}
std::optional<NormalEncoding> parseNormalEncoding(std::string_view s) {
    return valueOf(kNormal, s);
}
std::optional<MotionUnits> parseMotionUnits(std::string_view s) {
    return valueOf(kMotion, s);
}

} // namespace glint::capture
