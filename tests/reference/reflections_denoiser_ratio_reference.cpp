#include "reference/reflections_denoiser_ratio_reference.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace glint::reference {
namespace {

double dot3(const Rgb& a, const Rgb& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

Rgb normalized(const Rgb& v) {
    const double length = std::sqrt(dot3(v, v));
    return {v[0] / length, v[1] / length, v[2] / length};
}

// GGX NDF, textbook form (double keeps it accurate down to alpha = 1e-4).
double ggxD(double NdotH, double alpha) {
    if (!(NdotH > 0.0)) return 0.0;
    const double a2 = alpha * alpha;
    const double bracket = NdotH * NdotH * (a2 - 1.0) + 1.0;
    return a2 / (std::numbers::pi * bracket * bracket);
}

// Height-correlated Smith visibility G2 / (4 N.L N.V).
double smithVisibility(double NdotL, double NdotV, double alpha) {
    const double a2 = alpha * alpha;
    return 0.5 / (NdotL * std::sqrt(NdotV * NdotV * (1.0 - a2) + a2) +
                  NdotV * std::sqrt(NdotL * NdotL * (1.0 - a2) + a2));
}

double lumaOf(const Rgb& c) {
    return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
}

bool inImage(const DenoiserSurface& s, std::int64_t x, std::int64_t y) {
    return x >= 0 && y >= 0 && x < std::int64_t{s.width} && y < std::int64_t{s.height};
}

std::size_t indexOf(const DenoiserSurface& s, std::int64_t x, std::int64_t y) {
    return static_cast<std::size_t>(y) * s.width + static_cast<std::size_t>(x);
}

} // namespace

std::array<std::array<double, 2>, 8> reconstructionTaps() {
    std::array<std::array<double, 2>, 8> taps{};
    const double goldenAngle = std::numbers::pi * (3.0 - std::sqrt(5.0));
    for (std::size_t k = 0; k < taps.size(); ++k) {
        const double radius = std::sqrt((static_cast<double>(k) + 0.5) / 8.0);
        const double angle = static_cast<double>(k) * goldenAngle;
        taps[k] = {radius * std::cos(angle), radius * std::sin(angle)};
    }
    return taps;
}

ReconstructResult reconstructPixel(const ReconstructInputs& inputs, std::uint32_t x, std::uint32_t y) {
    const DenoiserSurface& s = *inputs.surface;
    const std::size_t i = indexOf(s, x, y);
    ReconstructResult result;
    if (!s.glossy[i]) {
        result.value.variance = kNotGlossyVariance; // the prefilter's marking, read by the resolve
        return result;
    }
    if (s.alpha[i] < inputs.mirrorThreshold) {
        result.value = {inputs.radiance[i], inputs.variance[i]};
        return result;
    }
    const double alpha = std::clamp(s.alpha[i], 1e-4, 1.0);
    const Rgb& N = s.normal[i];
    const Rgb& V = inputs.view[i];
    const double NdotV = dot3(N, V);
    const double radius = inputs.radius * std::min(1.0, 5.0 * std::sqrt(s.alpha[i]));
    static constexpr std::uint32_t kBayer[16] = {0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5};
    const std::uint32_t step = (kBayer[(y % 4) * 4 + x % 4] + inputs.frameIndex) % 16;
    const double angle = 2.0 * std::numbers::pi * static_cast<double>(step) / 16.0;
    const double cosAngle = std::cos(angle), sinAngle = std::sin(angle);
    const auto taps = reconstructionTaps();

    struct Contribution {
        double weight, luma;
        Rgb radiance;
    };
    std::vector<Contribution> contributions;
    for (std::size_t tap = 0; tap < 9; ++tap) {
        const std::array<double, 2> unit = tap == 0 ? std::array<double, 2>{0.0, 0.0} : taps[tap - 1];
        const double ox = (cosAngle * unit[0] - sinAngle * unit[1]) * radius;
        const double oy = (sinAngle * unit[0] + cosAngle * unit[1]) * radius;
        for (double o : {ox, oy})
            if (std::abs(o + 0.5 - std::round(o + 0.5)) < 1e-3 && tap > 0) result.ambiguous = true;
        const std::int64_t qx = std::int64_t{x} + static_cast<std::int64_t>(std::floor(ox + 0.5));
        const std::int64_t qy = std::int64_t{y} + static_cast<std::int64_t>(std::floor(oy + 0.5));
        if (!inImage(s, qx, qy)) continue;
        const std::size_t q = indexOf(s, qx, qy);
        if (tap > 0 && !s.glossy[q]) continue;
        const StoredRay& ray = inputs.rays[q];
        double weight = 1e-6; // an empty ray
        if (dot3(ray.direction, ray.direction) > 0.25 && std::isfinite(ray.pdf) && ray.pdf >= 0.0) {
            const Rgb L = normalized(ray.direction);
            const double NdotL = dot3(N, L);
            weight = 0.0;
            if (NdotL > 0.0) {
                const Rgb H = normalized({V[0] + L[0], V[1] + L[1], V[2] + L[2]});
                const double spatial = std::exp(-(unit[0] * unit[0] + unit[1] * unit[1]) / (2.0 * 0.81));
                weight = spatial * ggxD(dot3(N, H), alpha) * smithVisibility(NdotL, NdotV, alpha) * NdotL /
                         std::max(ray.pdf, 1e-5);
            }
        }
        if (weight > 0.0) contributions.push_back({weight, lumaOf(inputs.radiance[q]), inputs.radiance[q]});
    }
    double weightSum = 0.0, lumaSum = 0.0;
    Rgb sum{};
    for (const Contribution& c : contributions) {
        weightSum += c.weight;
        lumaSum += c.weight * c.luma;
        for (std::size_t k = 0; k < 3; ++k) sum[k] += c.weight * c.radiance[k];
    }
    Rgb mean = inputs.radiance[i];
    double spatialVariance = 0.0;
    if (weightSum > 0.0) {
        mean = {sum[0] / weightSum, sum[1] / weightSum, sum[2] / weightSum};
        const double lumaMean = lumaSum / weightSum;
        double squares = 0.0;
        for (const Contribution& c : contributions)
            squares += c.weight * (c.luma - lumaMean) * (c.luma - lumaMean);
        const double floor = std::max(lumaMean, 0.5);
        spatialVariance = squares / weightSum / (floor * floor);
    }
    result.value = {mean, 0.1 * spatialVariance + 0.9 * inputs.variance[i]};
    return result;
}

std::optional<Rgb> cleanupPixel(const CleanupInputs& inputs, std::uint32_t x, std::uint32_t y) {
    const DenoiserSurface& s = *inputs.surface;
    const std::size_t i = indexOf(s, x, y);
    if (!s.glossy[i]) return std::nullopt;
    const double variance = inputs.variance[i];
    if (variance <= 5e-5) return std::nullopt;
    const double reach = std::min(1.0, 8.0 * std::sqrt(s.alpha[i])) * (variance > 1e-3 ? 2.0 : 0.0);
    const int radius = static_cast<int>(std::floor(std::min(2.0 * inputs.sigma, reach)));
    if (radius <= 0) return std::nullopt;

    const double z = s.viewDepth[i];
    // The view depth's slope per pixel on each axis: the one-sided difference of smaller
    // magnitude among the glossy neighbours (the forward one on a tie), 0 without either.
    auto slope = [&](int dx, int dy) {
        const std::int64_t bx = std::int64_t{x} - dx, by = std::int64_t{y} - dy;
        const std::int64_t ax = std::int64_t{x} + dx, ay = std::int64_t{y} + dy;
        const bool before = inImage(s, bx, by) && s.glossy[indexOf(s, bx, by)];
        const bool after = inImage(s, ax, ay) && s.glossy[indexOf(s, ax, ay)];
        const double backward = before ? z - s.viewDepth[indexOf(s, bx, by)] : 0.0;
        const double forward = after ? s.viewDepth[indexOf(s, ax, ay)] - z : 0.0;
        if (before && (!after || std::abs(backward) < std::abs(forward))) return backward;
        return after ? forward : 0.0;
    };
    const double gx = slope(1, 0), gy = slope(0, 1);
    Rgb sum{};
    double weightSum = 0.0;
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
            const std::int64_t qx = std::int64_t{x} + dx, qy = std::int64_t{y} + dy;
            if (!inImage(s, qx, qy)) continue;
            const std::size_t q = indexOf(s, qx, qy);
            if (!s.glossy[q]) continue;
            const double distanceSquared = static_cast<double>(dx * dx + dy * dy);
            const double w = std::exp(-0.5 * distanceSquared / (inputs.sigma * inputs.sigma)) *
                             std::exp(-std::abs(z - s.viewDepth[q]) / (std::abs(dx * gx + dy * gy) + 1e-6)) *
                             std::pow(std::max(0.0, dot3(s.normal[i], s.normal[q])), 128.0);
            for (std::size_t k = 0; k < 3; ++k) sum[k] += w * inputs.resolved[q][k];
            weightSum += w;
        }
    return Rgb{sum[0] / weightSum, sum[1] / weightSum, sum[2] / weightSum};
}

} // namespace glint::reference
