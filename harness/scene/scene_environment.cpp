#include "scene/scene_environment.h"

#include "capture/capture_error.h"
#include "scene/scene_file.h"
#include "scene/scene_geometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace glint::scene {

Vec3 latLongDirection(std::uint32_t x, std::uint32_t y, std::uint32_t width, std::uint32_t height) {
    const double longitude = 2.0 * std::numbers::pi * (0.5 - (x + 0.5) / width);
    const double latitude = std::numbers::pi * (0.5 - (y + 0.5) / height);
    return {static_cast<float>(std::cos(latitude) * std::sin(longitude)),
            static_cast<float>(std::sin(latitude)),
            static_cast<float>(std::cos(latitude) * std::cos(longitude))};
}

capture::Environment bakeEnvironment(const Scene& scene) {
    const EnvironmentDesc& desc = scene.environment;
    capture::Environment env;
    if (desc.kind == EnvironmentKind::Map) {
        try {
            env = capture::readEnvironment(desc.file);
        } catch (const std::exception& error) {
            throw SceneError(std::string(error.what()));
        }
        if (env.layout != capture::EnvironmentLayout::LatLong)
            throw SceneError(desc.file.string() +
                             ": environment.file must be a lat-long map (cube maps are not supported)");
        for (float& v : env.rgb) v = std::isfinite(v) ? std::max(v, 0.0f) * desc.intensity : 0.0f;
        env.nonFinite = 0;
        return env;
    }
    env.layout = capture::EnvironmentLayout::LatLong;
    env.width = desc.width;
    env.height = desc.height;
    env.rgb.assign(std::size_t{env.width} * env.height * 3, 0.0f);
    for (std::uint32_t y = 0; y < env.height; ++y) {
        for (std::uint32_t x = 0; x < env.width; ++x) {
            const Vec3 d = latLongDirection(x, y, env.width, env.height);
            Vec3 c{};
            // Smooth gradient: horizon to zenith above, horizon to ground below.
            const float t = std::sqrt(std::fabs(d[1]));
            const Vec3& pole = d[1] >= 0.0f ? desc.zenith : desc.ground;
            for (std::size_t k = 0; k < 3; ++k) c[k] = desc.horizon[k] + (pole[k] - desc.horizon[k]) * t;
            if (desc.sunDisc) {
                // Baked once: a keyframed light's disc stays where the light is on frame 0.
                for (const LightDesc& light : lightsAt(scene, 0)) {
                    if (light.kind != LightKind::Directional || light.angularRadiusDegrees <= 0.0f) continue;
                    const double radius =
                        static_cast<double>(light.angularRadiusDegrees) * std::numbers::pi / 180.0;
                    const double cosAngle = static_cast<double>(
                        d[0] * light.direction[0] + d[1] * light.direction[1] + d[2] * light.direction[2]);
                    if (cosAngle < std::cos(radius)) continue;
                    // The disc's radiance delivers the light's irradiance over its solid angle.
                    const double solidAngle = 2.0 * std::numbers::pi * (1.0 - std::cos(radius));
                    for (std::size_t k = 0; k < 3; ++k)
                        c[k] += static_cast<float>(static_cast<double>(light.color[k] * light.intensity) /
                                                   solidAngle);
                }
            }
            const std::size_t i = (std::size_t{y} * env.width + x) * 3;
            for (std::size_t k = 0; k < 3; ++k) env.rgb[i + k] = c[k] * desc.intensity;
        }
    }
    return env;
}

std::vector<shaders::SceneEnvironmentSample> environmentSamplingTable(const capture::Environment& env) {
    const std::size_t width = env.width, height = env.height, count = width * height;
    if (count == 0 || env.rgb.size() < count * 3) return {};
    std::vector<double> luminance(count);
    for (std::size_t i = 0; i < count; ++i) {
        const float* c = &env.rgb[i * 3];
        const double y = 0.2126 * double{c[0]} + 0.7152 * double{c[1]} + 0.0722 * double{c[2]};
        luminance[i] = std::isfinite(y) ? std::max(y, 0.0) : 0.0;
    }
    std::vector<double> weight(count);
    double total = 0.0;
    for (std::size_t y = 0; y < height; ++y) {
        const double latitude =
            std::numbers::pi * (0.5 - (static_cast<double>(y) + 0.5) / static_cast<double>(height));
        for (std::size_t x = 0; x < width; ++x) {
            const double l = luminance[y * width + x];
            weight[y * width + x] = l * l * std::cos(latitude);
            total += weight[y * width + x];
        }
    }
    if (!(total > 0.0) || !std::isfinite(total)) return {};

    // Vose's construction: slots scaled to a mean of 1; each underfull slot is topped up by one
    // overfull texel, which moves to the underfull list once it drops below 1.
    std::vector<shaders::SceneEnvironmentSample> table(count);
    std::vector<double> scaled(count);
    std::vector<std::uint32_t> small, large;
    for (std::size_t i = 0; i < count; ++i) {
        table[i] = {1.0f, static_cast<std::uint32_t>(i), static_cast<float>(weight[i] / total), 0u};
        scaled[i] = weight[i] / total * static_cast<double>(count);
        (scaled[i] < 1.0 ? small : large).push_back(static_cast<std::uint32_t>(i));
    }
    while (!small.empty() && !large.empty()) {
        const std::uint32_t s = small.back(), l = large.back();
        small.pop_back();
        table[s].keep = static_cast<float>(scaled[s]);
        table[s].alias = l;
        scaled[l] -= 1.0 - scaled[s];
        if (scaled[l] < 1.0) {
            large.pop_back();
            small.push_back(l);
        }
    }
    // Left over from rounding: slots that keep their own texel always.
    for (std::uint32_t i : small) table[i].keep = 1.0f;
    for (std::uint32_t i : large) table[i].keep = 1.0f;
    return table;
}

} // namespace glint::scene
