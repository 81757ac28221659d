// The environment map of a mapped capture, turned into glint's world axes: a lat-long file
// whose centre faces another horizontal direction (Blender's faces +X) is re-indexed column by
// column, exactly, since a quarter turn about the up axis moves whole columns.
#include "capture/channel_map.h"

#include "capture/capture_error.h"

#include <array>
#include <cmath>
#include <numbers>

namespace glint::capture {

namespace {
using Vec3 = std::array<double, 3>;

Vec3 unitAxis(const AxisDirection& d) {
    Vec3 v{0.0, 0.0, 0.0};
    v[static_cast<std::size_t>(d.axis)] = d.sign;
    return v;
}

Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

double dot(const Vec3& a, const Vec3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// Whether the file is already in glint's orientation: its centre is what becomes glint's +z.
bool isGlintOriented(const ChannelMap& map) {
    const AxisDirection& c = map.environment.center;
    return c.axis == map.worldAxes.axis[2] && c.sign == map.worldAxes.sign[2];
}

// For each glint column, the file column holding the same longitude. glint's lat-long
// (sssr_environment.hlsli, OpenEXR's layout): u = 0.5 - atan2(d.x, d.z) / 2pi, latitude on
// +y; the file's: the same with its centre F and its left L = up x F in place of +z and +x.
std::vector<std::uint32_t> sourceColumns(const ChannelMap& map, std::uint32_t width,
                                         const std::filesystem::path& file) {
    const Vec3 f = unitAxis(map.environment.center);
    const Vec3 l = cross(unitAxis(map.environment.up), f);
    std::vector<std::uint32_t> columns(width);
    for (std::uint32_t x = 0; x < width; ++x) {
        const double longitude = 2.0 * std::numbers::pi * (0.5 - (x + 0.5) / width);
        const Vec3 glint{std::sin(longitude), 0.0, std::cos(longitude)};
        Vec3 source{}; // glint axis i = sign[i] * source axis[axis[i]]
        for (std::size_t i = 0; i < 3; ++i)
            source[static_cast<std::size_t>(map.worldAxes.axis[i])] = map.worldAxes.sign[i] * glint[i];
        const double u = 0.5 - std::atan2(dot(source, l), dot(source, f)) / (2.0 * std::numbers::pi);
        const double column = u * width - 0.5;
        const double nearest = std::round(column);
        if (std::abs(column - nearest) > 1e-6 * width)
            fail(file, "is " + std::to_string(width) +
                           " texels wide; turning it a quarter turn into glint's orientation "
                           "(environment.center in " +
                           map.path + ") needs a width divisible by 4");
        const long long wrapped = (static_cast<long long>(nearest) % width + width) % width;
        columns[x] = static_cast<std::uint32_t>(wrapped);
    }
    return columns;
}
} // namespace

std::optional<Environment> loadMappedEnvironment(const ChannelMap& map, const std::string& dirOrFile) {
    const std::filesystem::path file = mappedEnvironmentFile(map, dirOrFile);
    if (file.empty()) return std::nullopt;
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) {
        if (map.environment.optional) return std::nullopt;
        fail(file, "environment map does not exist (environment in " + map.path + ")");
    }
    Environment env = readEnvironment(file, EnvironmentLayout::LatLong);
    if (isGlintOriented(map)) return env;
    if (env.layout != EnvironmentLayout::LatLong)
        fail(file, "a cube map cannot be turned into glint's orientation (environment.center in " + map.path +
                       "); give a lat-long map");
    const std::vector<std::uint32_t> columns = sourceColumns(map, env.width, file);
    std::vector<float> turned(env.rgb.size());
    for (std::size_t y = 0; y < env.height; ++y)
        for (std::size_t x = 0; x < env.width; ++x)
            for (std::size_t c = 0; c < 3; ++c)
                turned[(y * env.width + x) * 3 + c] = env.rgb[(y * env.width + columns[x]) * 3 + c];
    env.rgb = std::move(turned);
    return env;
}

} // namespace glint::capture
