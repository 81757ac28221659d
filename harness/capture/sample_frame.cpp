#include "capture/sample_frame.h"

#include "capture/motion_convention.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace glint::capture {

namespace {
struct V3 {
    double x = 0.0, y = 0.0, z = 0.0;
};
V3 operator+(V3 a, V3 b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
V3 operator-(V3 a, V3 b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
V3 operator*(V3 a, double s) {
    return {a.x * s, a.y * s, a.z * s};
}
double dot(V3 a, V3 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
V3 cross(V3 a, V3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
V3 normalize(V3 a) {
    return a * (1.0 / std::sqrt(dot(a, a)));
}

constexpr double kNear = 0.1;
constexpr double kFar = 100.0;
constexpr double kFovY = 50.0 * std::numbers::pi / 180.0;
const V3 kTarget{0.0, 0.5, 0.0};
const V3 kLight = normalize({0.4, 1.0, 0.3});

// The camera path: a slow sideways and downward drift while looking at a fixed point, so
// consecutive frames differ by both a translation and a rotation.
V3 eyeAt(double frame) {
    return {-0.3 + 0.05 * frame, 1.6 - 0.01 * frame, 4.0};
}

Mat4 lookAt(V3 eye, V3 target) {
    // Right-handed view space: the camera looks down -z, +y up.
    const V3 f = normalize(target - eye);
    const V3 r = normalize(cross(f, {0.0, 1.0, 0.0}));
    const V3 u = cross(r, f);
    return {{r.x, r.y, r.z, -dot(r, eye), u.x, u.y, u.z, -dot(u, eye), -f.x, -f.y, -f.z, dot(f, eye), 0.0,
             0.0, 0.0, 1.0}};
}

Mat4 perspective(double aspect) {
    // D3D-style clip space with depth in [0,1] (standard: near -> 0, far -> 1).
    const double fy = 1.0 / std::tan(0.5 * kFovY);
    const double a = kFar / (kNear - kFar);
    return {{fy / aspect, 0.0, 0.0, 0.0, 0.0, fy, 0.0, 0.0, 0.0, 0.0, a, kNear * a, 0.0, 0.0, -1.0, 0.0}};
}

Mat4 viewProjectionAt(double frame, double aspect) {
    return multiply(perspective(aspect), lookAt(eyeAt(frame), kTarget));
}

V3 skyColor(V3 dir) {
    const double t = std::clamp(0.5 + 0.5 * dir.y, 0.0, 1.0);
    return V3{0.9, 0.85, 0.8} * (1.0 - t) + V3{0.35, 0.55, 0.95} * t;
}

// Nearest positive ray parameter of the sphere or the ground, or a negative value.
double intersect(V3 o, V3 d, V3& normal, bool& onSphere) {
    const SampleScene& s = kSampleScene;
    const V3 c{s.sphereCenter[0], s.sphereCenter[1], s.sphereCenter[2]};
    double best = -1.0;
    const V3 oc = o - c;
    const double b = dot(oc, d);
    const double disc = b * b - (dot(oc, oc) - s.sphereRadius * s.sphereRadius);
    if (disc >= 0.0) {
        const double t = -b - std::sqrt(disc);
        if (t > 0.0) {
            best = t;
            normal = normalize(o + d * t - c);
            onSphere = true;
        }
    }
    if (d.y < 0.0) {
        const double t = (s.groundY - o.y) / d.y;
        if (t > 0.0 && (best < 0.0 || t < best)) {
            best = t;
            normal = {0.0, 1.0, 0.0};
            onSphere = false;
        }
    }
    return best;
}

// Screen UV of a homogeneous world point (w = 0 for a point at infinity), D3D-style NDC.
void uvOf(const Mat4& vp, V3 p, double w, double& u, double& v) {
    const Vec4 c = transform(vp, {p.x, p.y, p.z, w});
    u = 0.5 * (c.x / c.w) + 0.5;
    v = 0.5 - 0.5 * (c.y / c.w);
}

void put(Layer& layer, std::size_t pixel, std::initializer_list<double> values) {
    std::size_t i = pixel * layer.channels.size();
    for (double value : values) layer.pixels[i++] = static_cast<float>(value);
}
} // namespace

Camera sampleCamera(std::uint32_t width, std::uint32_t height, std::uint32_t frameIndex) {
    const double aspect = static_cast<double>(width) / static_cast<double>(height);
    const double frame = static_cast<double>(frameIndex);
    Camera c;
    c.view = lookAt(eyeAt(frame), kTarget);
    c.projection = perspective(aspect);
    c.prevViewProjection = viewProjectionAt(frame - 1.0, aspect);
    c.depth = DepthConvention::Standard;
    c.nearZ = kNear;
    c.farZ = kFar;
    c.ndcYDown = false;
    return c;
}

Frame makeSampleFrame(std::uint32_t width, std::uint32_t height, std::uint32_t frameIndex) {
    Frame f;
    f.width = width;
    f.height = height;
    f.frameIndex = frameIndex;
    f.camera = sampleCamera(width, height, frameIndex);
    f.normalEncoding = NormalEncoding::WorldUnit;
    f.motion = kConventionA;
    f.roughness = {"material", "G", true};
    f.effects = {"reflections"};

    const std::size_t pixels = std::size_t{width} * height;
    Layer color{"color", {"R", "G", "B"}, std::vector<float>(pixels * 3), 0, SampleType::Half};
    Layer depth{"depth", {"Z"}, std::vector<float>(pixels), 0, SampleType::Float};
    Layer normal{"normal", {"X", "Y", "Z"}, std::vector<float>(pixels * 3), 0, SampleType::Float};
    Layer material{"material", {"R", "G"}, std::vector<float>(pixels * 2), 0, SampleType::Half};
    Layer motion{"motion", {"X", "Y"}, std::vector<float>(pixels * 2), 0, SampleType::Float};

    const Mat4 vp = viewProjection(f.camera);
    const Mat4 invVp = *inverse(vp);
    const V3 eye = eyeAt(static_cast<double>(frameIndex));
    for (std::uint32_t y = 0; y < height; ++y) {
        for (std::uint32_t x = 0; x < width; ++x) {
            const std::size_t pixel = std::size_t{y} * width + x;
            const double u = (x + 0.5) / width;
            const double v = (y + 0.5) / height;
            const double nx = 2.0 * u - 1.0, ny = 1.0 - 2.0 * v;
            const Vec4 farPoint = transform(invVp, {nx, ny, 1.0, 1.0});
            const V3 dir = normalize(V3{farPoint.x, farPoint.y, farPoint.z} * (1.0 / farPoint.w) - eye);

            V3 n;
            bool onSphere = false;
            const double t = intersect(eye, dir, n, onSphere);
            const V3 hit = eye + dir * t;
            const Vec4 clip = transform(vp, {hit.x, hit.y, hit.z, 1.0});
            const bool sky = t <= 0.0 || clip.z / clip.w >= 1.0;

            double prevU = 0.0, prevV = 0.0;
            const double roughness = 0.05 + 0.9 * u;
            if (sky) {
                uvOf(f.camera.prevViewProjection, dir, 0.0, prevU, prevV);
                const V3 c = skyColor(dir);
                put(depth, pixel, {1.0});
                put(normal, pixel, {-dir.x, -dir.y, -dir.z});
                put(color, pixel, {c.x, c.y, c.z});
                put(material, pixel, {0.0, roughness});
            } else {
                uvOf(f.camera.prevViewProjection, hit, 1.0, prevU, prevV);
                const bool checker =
                    (static_cast<long>(std::floor(hit.x)) + static_cast<long>(std::floor(hit.z))) % 2 == 0;
                const V3 albedo =
                    onSphere ? V3{0.9, 0.6, 0.3} : (checker ? V3{0.7, 0.7, 0.7} : V3{0.3, 0.3, 0.3});
                const V3 c = albedo * (0.15 + std::max(0.0, dot(n, kLight)));
                put(depth, pixel, {clip.z / clip.w});
                put(normal, pixel, {n.x, n.y, n.z});
                put(color, pixel, {c.x, c.y, c.z});
                put(material, pixel, {onSphere ? 1.0 : 0.0, roughness});
            }
            put(motion, pixel, {prevU - u, prevV - v});
        }
    }
    f.layers = {std::move(color), std::move(depth), std::move(normal), std::move(material),
                std::move(motion)};
    return f;
}

Environment makeSampleEnvironment(std::uint32_t width, std::uint32_t height) {
    Environment env;
    env.layout = EnvironmentLayout::LatLong;
    env.width = width;
    env.height = height;
    env.rgb.assign(std::size_t{width} * height * 3, 0.0f);
    for (std::uint32_t y = 0; y < height; ++y) {
        // OpenEXR lat-long: latitude +pi/2 on the top row, -pi/2 on the bottom row.
        const double latitude = std::numbers::pi * (0.5 - (y + 0.5) / height);
        const V3 c = skyColor({0.0, std::sin(latitude), std::cos(latitude)});
        for (std::uint32_t x = 0; x < width; ++x) {
            const std::size_t i = (std::size_t{y} * width + x) * 3;
            env.rgb[i + 0] = static_cast<float>(c.x);
            env.rgb[i + 1] = static_cast<float>(c.y);
            env.rgb[i + 2] = static_cast<float>(c.z);
        }
    }
    return env;
}

} // namespace glint::capture
