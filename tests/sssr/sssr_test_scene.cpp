#include "sssr/sssr_test_scene.h"

#include <algorithm>
#include <cmath>

namespace glint::test {
namespace {

struct Rng {
    std::uint64_t state;
    double next() {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return static_cast<double>(state >> 11) * (1.0 / 9007199254740992.0);
    }
};

using Vec3 = std::array<double, 3>;

Vec3 normalized(Vec3 v) {
    const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return {v[0] / length, v[1] / length, v[2] / length};
}

double dot3(const Vec3& a, const Vec3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

std::array<double, 4> mul(const std::array<double, 16>& m, const std::array<double, 4>& p) {
    std::array<double, 4> q{};
    for (std::size_t r = 0; r < 4; ++r)
        q[r] = m[4 * r] * p[0] + m[4 * r + 1] * p[1] + m[4 * r + 2] * p[2] + m[4 * r + 3] * p[3];
    return q;
}

} // namespace

std::array<double, 16> sssrPerspective(double fovY, double aspect, double n, double f, bool reversed) {
    const double g = 1.0 / std::tan(0.5 * fovY);
    // d = (a z + b) / (-z): standard maps z = -n to 0 and z = -f to 1; reversed the opposite.
    const double a = reversed ? n / (f - n) : f / (n - f);
    const double b = reversed ? n * f / (f - n) : n * f / (n - f);
    return {g / aspect, 0, 0, 0, 0, g, 0, 0, 0, 0, a, b, 0, 0, -1, 0};
}

double sssrDeviceDepth(double z, double n, double f, bool reversed) {
    const double standard = (f - n * f / z) / (f - n);
    return reversed ? 1.0 - standard : standard;
}

SssrTestView makeSssrTestView(std::uint32_t width, std::uint32_t height, bool reversed) {
    SssrTestView view;
    SssrDesc& desc = view.desc;
    desc.halfPrecisionStorage = false; // the CPU references' 32-bit permutation
    desc.size = {width, height};
    desc.depth = reversed ? DepthConvention::Reversed : DepthConvention::Standard;
    desc.nearPlane = 0.1f;
    desc.farPlane = 100.0f;
    desc.projection = sssrPerspective(1.0, static_cast<double>(width) / height, 0.1, 100.0, reversed);
    desc.vulkanNdc = false;
    desc.roughnessIsPerceptual = false;
    desc.environmentTexelSolidAngle = static_cast<float>(4.0 * 3.14159265358979 / (16.0 * 8.0));
    desc.environmentMaxLod = 4.0f;
    const std::size_t count = std::size_t{width} * height;
    gpu::SssrFrameInputs& in = view.inputs;
    in.depth.assign(count, reversed ? 0.0f : 1.0f);
    in.normals.assign(4 * count, 0.0f);
    in.material.assign(4 * count, 0.0f);
    in.color.assign(4 * count, 1.0f);
    in.motion.assign(2 * count, 0.0f);
    in.baseColorMetallic.assign(4 * count, 0.5f);
    for (std::size_t i = 0; i < count; ++i) {
        in.normals[4 * i + 2] = 1.0f;
        const std::size_t x = i % width, y = i / width;
        const float checker = ((x / 4 + y / 4) & 1) ? 0.8f : 0.2f;
        in.color[4 * i + 0] = checker;
        in.color[4 * i + 1] = 0.5f * checker;
        in.color[4 * i + 2] = 0.25f;
    }
    in.environmentWidth = 16;
    in.environmentHeight = 8;
    for (std::uint32_t y = 0; y < 8; ++y)
        for (std::uint32_t x = 0; x < 16; ++x) {
            const float sky = 1.0f - static_cast<float>(y) / 8.0f;
            in.environment.insert(in.environment.end(), {0.2f + sky, 0.3f + sky, 0.5f + sky, 1.0f});
        }
    return view;
}

void setViewDepth(SssrTestView& view, std::uint32_t x, std::uint32_t y, double viewDepth) {
    view.inputs.depth[std::size_t{y} * view.desc.size.width + x] = static_cast<float>(sssrDeviceDepth(
        viewDepth, view.desc.nearPlane, view.desc.farPlane, view.desc.depth == DepthConvention::Reversed));
}

void fillRandomSurfaces(SssrTestView& view, std::uint32_t seed) {
    const std::uint32_t w = view.desc.size.width, h = view.desc.size.height;
    Rng rng{seed * 0x9E3779B97F4A7C15ull + 1};
    std::vector<double> z(std::size_t{w} * h);
    for (std::uint32_t y = 0; y < h; ++y)
        for (std::uint32_t x = 0; x < w; ++x) z[std::size_t{y} * w + x] = 3.0 + 9.0 * (1.0 - (y + 0.5) / h);
    for (int r = 0; r < 12; ++r) {
        const auto x0 = static_cast<std::uint32_t>(rng.next() * w),
                   y0 = static_cast<std::uint32_t>(rng.next() * h);
        const auto rw = 1 + static_cast<std::uint32_t>(rng.next() * w / 4),
                   rh = 1 + static_cast<std::uint32_t>(rng.next() * h / 4);
        const double depth = 1.0 + 6.0 * rng.next();
        const double slope = (rng.next() - 0.5) * 0.2;
        for (std::uint32_t y = y0; y < std::min(h, y0 + rh); ++y)
            for (std::uint32_t x = x0; x < std::min(w, x0 + rw); ++x)
                z[std::size_t{y} * w + x] = std::min(z[std::size_t{y} * w + x], depth + slope * (x - x0));
    }
    for (std::uint32_t y = 0; y < h; ++y)
        for (std::uint32_t x = 0; x < w; ++x) {
            const std::size_t i = std::size_t{y} * w + x;
            if (rng.next() < 0.02) continue; // sky: far depth stays
            setViewDepth(view, x, y, z[i]);
            const Vec3 toEye = normalized({-((x + 0.5) / w - 0.5), ((y + 0.5) / h - 0.5), 1.0});
            Vec3 n;
            do {
                n = normalized({toEye[0] + 1.6 * (rng.next() - 0.5), toEye[1] + 1.6 * (rng.next() - 0.5),
                                toEye[2] + 1.6 * (rng.next() - 0.5)});
            } while (dot3(n, toEye) < 0.2);
            for (std::size_t c = 0; c < 3; ++c) view.inputs.normals[4 * i + c] = static_cast<float>(n[c]);
        }
}

SssrCpuRay sssrMirrorRay(const SssrTestView& view, std::uint32_t x, std::uint32_t y) {
    const SssrDesc& desc = view.desc;
    const double w = desc.size.width, h = desc.size.height;
    const std::size_t i = std::size_t{y} * desc.size.width + x;
    const double depth = view.inputs.depth[i];
    const double u = (x + 0.5) / w, v = (y + 0.5) / h;
    const double ySign = desc.vulkanNdc ? 1.0 : -1.0;
    // Unproject with the analytic inverse of sssrPerspective (the same camera, in double).
    const double n = desc.nearPlane, f = desc.farPlane;
    const bool reversed = desc.depth == DepthConvention::Reversed;
    const double standardDepth = reversed ? 1.0 - depth : depth;
    const double viewDepth = n * f / (f - standardDepth * (f - n));
    const double g = desc.projection[5], aspectG = desc.projection[0];
    const Vec3 p{(2.0 * u - 1.0) * viewDepth / aspectG, ySign * (2.0 * v - 1.0) * viewDepth / g, -viewDepth};
    const Vec3 toEye = normalized({-p[0], -p[1], -p[2]});
    const Vec3 normal = normalized(
        {view.inputs.normals[4 * i], view.inputs.normals[4 * i + 1], view.inputs.normals[4 * i + 2]});
    const double nv = dot3(normal, toEye);
    const Vec3 l{2 * nv * normal[0] - toEye[0], 2 * nv * normal[1] - toEye[1], 2 * nv * normal[2] - toEye[2]};
    // The segment's end from the geometry of the view-space ray p + t l (view depth -p_z - t l_z):
    // toward the camera it ends where it reaches the near plane (view depth n); away from it,
    // on the far plane (view depth f); parallel to the image plane (constant depth), far away
    // (the screen clips it). The device stops a ray toward the camera 1e-3 of the clip-space
    // length short of the near plane (docs/sssr.md, "Ray setup"); over that last stretch the ray's
    // view depth stays below n + 1e-3 (viewDepth - n), far in front of any surface these scenes
    // hold, so the expected hits do not depend on that margin.
    double t = 0.0;
    const double along = std::sqrt(dot3(l, l));
    if (l[2] > 1e-9 * along)
        t = (-p[2] - n) / l[2];
    else if (l[2] < -1e-9 * along)
        t = (f + p[2]) / -l[2];
    else
        t = 1e6 * viewDepth;
    t = std::max(t, 0.0);
    const auto end = mul(desc.projection, {p[0] + t * l[0], p[1] + t * l[1], p[2] + t * l[2], 1.0});
    const double endU = 0.5 * end[0] / end[3] + 0.5, endV = 0.5 * ySign * end[1] / end[3] + 0.5;
    SssrCpuRay ray;
    ray.origin = {x + 0.5, y + 0.5, depth};
    ray.direction = {endU * w - ray.origin[0], endV * h - ray.origin[1], end[2] / end[3] - depth};
    ray.towardCamera = l[2] > 1e-9 * along;
    ray.viewPosition = p;
    ray.viewDirection = l;
    double tEnd = 1.0;
    if (ray.direction[0] > 0) tEnd = std::min(tEnd, (w - ray.origin[0]) / ray.direction[0]);
    if (ray.direction[0] < 0) tEnd = std::min(tEnd, -ray.origin[0] / ray.direction[0]);
    if (ray.direction[1] > 0) tEnd = std::min(tEnd, (h - ray.origin[1]) / ray.direction[1]);
    if (ray.direction[1] < 0) tEnd = std::min(tEnd, -ray.origin[1] / ray.direction[1]);
    ray.tEnd = tEnd;
    ray.degenerate = ray.direction[0] * ray.direction[0] + ray.direction[1] * ray.direction[1] < 1e-4;
    return ray;
}

} // namespace glint::test
