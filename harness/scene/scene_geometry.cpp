#include "scene/scene_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace glint::scene {
namespace {

using capture::Mat4;

struct D3 {
    double x = 0.0, y = 0.0, z = 0.0;
};
// Scene vectors are float; the camera and matrix math runs in double.
double wide(float v) {
    return static_cast<double>(v);
}
D3 d3(const Vec3& v) {
    return {wide(v[0]), wide(v[1]), wide(v[2])};
}
D3 operator-(D3 a, D3 b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
double dot(D3 a, D3 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
D3 cross(D3 a, D3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
D3 normalized(D3 a) {
    const double len = std::sqrt(dot(a, a));
    return {a.x / len, a.y / len, a.z / len};
}

double lerp(double a, double b, double t) {
    return a + (b - a) * t;
}
Vec3 lerp(const Vec3& a, const Vec3& b, double t) {
    return {static_cast<float>(lerp(wide(a[0]), wide(b[0]), t)),
            static_cast<float>(lerp(wide(a[1]), wide(b[1]), t)),
            static_cast<float>(lerp(wide(a[2]), wide(b[2]), t))};
}

// Index of the keyframe segment containing `frame` and the blend inside it; clamps outside.
template <typename Key>
std::pair<const Key*, std::pair<const Key*, double>> segment(const std::vector<Key>& keys, double frame) {
    const auto at = [&](std::size_t i) { return static_cast<double>(keys[i].frame); };
    if (frame <= at(0) || keys.size() == 1) return {&keys.front(), {&keys.front(), 0.0}};
    if (frame >= at(keys.size() - 1)) return {&keys.back(), {&keys.back(), 0.0}};
    std::size_t i = 1;
    while (at(i) < frame) ++i;
    const double t = (frame - at(i - 1)) / (at(i) - at(i - 1));
    return {&keys[i - 1], {&keys[i], t}};
}

Mat4 translation(const Vec3& t) {
    Mat4 m = capture::identity();
    m.m[3] = wide(t[0]);
    m.m[7] = wide(t[1]);
    m.m[11] = wide(t[2]);
    return m;
}
Mat4 rotation(int axis, double degrees) {
    const double a = degrees * std::numbers::pi / 180.0;
    const double c = std::cos(a), s = std::sin(a);
    Mat4 m = capture::identity();
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    m.m[static_cast<std::size_t>(i * 4 + i)] = c;
    m.m[static_cast<std::size_t>(i * 4 + j)] = -s;
    m.m[static_cast<std::size_t>(j * 4 + i)] = s;
    m.m[static_cast<std::size_t>(j * 4 + j)] = c;
    return m;
}
Mat4 scaling(const Vec3& s) {
    Mat4 m = capture::identity();
    m.m[0] = wide(s[0]);
    m.m[5] = wide(s[1]);
    m.m[10] = wide(s[2]);
    return m;
}

shaders::float3 f3(double x, double y, double z) {
    return {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)};
}
shaders::float3 apply(const Mat4& m, const Vec3& p) {
    const capture::Vec4 q = capture::transform(m, {wide(p[0]), wide(p[1]), wide(p[2]), 1.0});
    return f3(q.x, q.y, q.z);
}

void addTriangle(FrameGeometry& g, const Mat4& m, const Vec3& a, const Vec3& b, const Vec3& c,
                 std::uint32_t material, std::uint32_t object) {
    shaders::ScenePrimitive p{};
    p.kind = GLINT_SCENE_PRIM_TRIANGLE;
    p.p0 = apply(m, a);
    p.p1 = apply(m, b);
    p.p2 = apply(m, c);
    p.material = material;
    p.object = object;
    g.primitives.push_back(p);
}

void addQuad(FrameGeometry& g, const Mat4& m, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
             std::uint32_t material, std::uint32_t object) {
    addTriangle(g, m, a, b, c, material, object);
    addTriangle(g, m, a, c, d, material, object);
}

// Model space -> the object's "fit" space: centred on x/z, resting on y = 0, largest extent
// fitSize. Real models come in any unit; fitting makes them usable without knowing it.
Mat4 fitMatrix(const ObjectDesc& object, const Mesh& mesh) {
    if (object.fitSize <= 0.0f || mesh.positions.empty()) return capture::identity();
    Vec3 lo{std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
            std::numeric_limits<float>::max()};
    Vec3 hi{-lo[0], -lo[1], -lo[2]};
    for (const Vec3& p : mesh.positions)
        for (std::size_t k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], p[k]);
            hi[k] = std::max(hi[k], p[k]);
        }
    const float extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1e-20f});
    const float s = object.fitSize / extent;
    return capture::multiply(scaling({s, s, s}),
                             translation({-0.5f * (lo[0] + hi[0]), -lo[1], -0.5f * (lo[2] + hi[2])}));
}

} // namespace

Mat4 objectMatrix(const ObjectDesc& object, double frame) {
    const auto [a, next] = segment(object.keys, frame);
    const auto [b, t] = next;
    const Vec3 position = lerp(a->position, b->position, t);
    const Vec3 rot = lerp(a->rotationDegrees, b->rotationDegrees, t);
    const Vec3 scale = lerp(a->scale, b->scale, t);
    Mat4 r = capture::multiply(rotation(2, wide(rot[2])),
                               capture::multiply(rotation(1, wide(rot[1])), rotation(0, wide(rot[0]))));
    return capture::multiply(translation(position), capture::multiply(r, scaling(scale)));
}

LightDesc lightAt(const LightDesc& light, double frame) {
    LightDesc out = light;
    if (light.keys.empty()) return out;
    const auto [a, next] = segment(light.keys, frame);
    const auto [b, t] = next;
    out.position = lerp(a->position, b->position, t);
    // Keys never differ by ~180 degrees (scene_file.cpp), so the blend is never near zero.
    const D3 d = normalized(d3(lerp(a->direction, b->direction, t)));
    out.direction = {static_cast<float>(d.x), static_cast<float>(d.y), static_cast<float>(d.z)};
    return out;
}

std::vector<LightDesc> lightsAt(const Scene& scene, std::uint32_t frame) {
    std::vector<LightDesc> out;
    for (const LightDesc& light : scene.lights) out.push_back(lightAt(light, frame));
    return out;
}

FrameGeometry buildGeometry(const Scene& scene, const std::vector<Mesh>& meshes, std::uint32_t frame) {
    FrameGeometry g;
    std::size_t meshIndex = 0;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const ObjectDesc& o = scene.objects[i];
        const auto objectId = static_cast<std::uint32_t>(i);
        const Mat4 world = objectMatrix(o, frame);
        const Mat4 previous = objectMatrix(o, static_cast<double>(frame) - 1.0);
        // A scale of zero makes the world matrix singular; the object then has no area and
        // its motion is irrelevant, so identity is as good as any.
        const Mat4 toPrevious =
            capture::multiply(previous, capture::inverse(world).value_or(capture::identity()));
        shaders::SceneObject so{};
        for (std::size_t row = 0; row < 3; ++row)
            so.toPrevious[row] = {
                static_cast<float>(toPrevious.m[row * 4 + 0]), static_cast<float>(toPrevious.m[row * 4 + 1]),
                static_cast<float>(toPrevious.m[row * 4 + 2]), static_cast<float>(toPrevious.m[row * 4 + 3])};
        g.objects.push_back(so);

        const float hx = 0.5f * o.size[0], hy = 0.5f * o.size[1], hz = 0.5f * o.size[2];
        switch (o.shape) {
        case ShapeKind::Plane: // counter-clockwise seen from +y
            addQuad(g, world, {-hx, 0, -hz}, {-hx, 0, hz}, {hx, 0, hz}, {hx, 0, -hz}, o.material, objectId);
            break;
        case ShapeKind::Box: {
            const Vec3 c[8] = {{-hx, -hy, -hz}, {hx, -hy, -hz}, {hx, hy, -hz}, {-hx, hy, -hz},
                               {-hx, -hy, hz},  {hx, -hy, hz},  {hx, hy, hz},  {-hx, hy, hz}};
            const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 4, 7, 3},
                                     {1, 2, 6, 5}, {0, 1, 5, 4}, {3, 7, 6, 2}};
            for (const auto& f : faces)
                addQuad(g, world, c[f[0]], c[f[1]], c[f[2]], c[f[3]], o.material, objectId);
            break;
        }
        case ShapeKind::Sphere: {
            // Spheres stay analytic; a non-uniform scale is approximated by the largest axis.
            const capture::Vec4 centre = capture::transform(world, {0, 0, 0, 1});
            double s = 0.0;
            for (int axis = 0; axis < 3; ++axis) {
                const capture::Vec4 v = capture::transform(
                    world, {axis == 0 ? 1.0 : 0.0, axis == 1 ? 1.0 : 0.0, axis == 2 ? 1.0 : 0.0, 0.0});
                s = std::max(s, std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z));
            }
            shaders::ScenePrimitive p{};
            p.kind = GLINT_SCENE_PRIM_SPHERE;
            p.p0 = f3(centre.x, centre.y, centre.z);
            p.p1 = f3(static_cast<double>(o.radius) * s, 0.0, 0.0);
            p.material = o.material;
            p.object = objectId;
            g.primitives.push_back(p);
            break;
        }
        case ShapeKind::Mesh: {
            const Mesh& mesh = meshes.at(meshIndex++);
            const Mat4 m = capture::multiply(world, fitMatrix(o, mesh));
            for (std::size_t v = 0; v + 2 < mesh.positions.size(); v += 3)
                addTriangle(g, m, mesh.positions[v], mesh.positions[v + 1], mesh.positions[v + 2], o.material,
                            objectId);
            break;
        }
        }
    }
    return g;
}

namespace {
Mat4 lookAt(D3 eye, D3 target, D3 up) {
    // Right-handed view space: the camera looks down -z with +y up.
    const D3 f = normalized(target - eye);
    const D3 r = normalized(cross(f, up));
    const D3 u = cross(r, f);
    return {{r.x, r.y, r.z, -dot(r, eye), u.x, u.y, u.z, -dot(u, eye), -f.x, -f.y, -f.z, dot(f, eye), 0, 0, 0,
             1}};
}

Mat4 perspective(const CameraDesc& c, double aspect) {
    const double fy = 1.0 / std::tan(0.5 * c.fovYDegrees * std::numbers::pi / 180.0);
    const double n = c.nearZ, f = c.farZ;
    Mat4 p{};
    p.m[0] = fy / aspect;
    p.m[5] = c.ndcYDown ? -fy : fy; // Vulkan-style NDC: flip y so the image stays upright
    p.m[14] = -1.0;                 // w = -z_view
    switch (c.depth) {
    case capture::DepthConvention::Standard: // z_ndc = 0 at near, 1 at far
        p.m[10] = f / (n - f);
        p.m[11] = n * f / (n - f);
        break;
    case capture::DepthConvention::Reversed: // 1 at near, 0 at far
        p.m[10] = n / (f - n);
        p.m[11] = n * f / (f - n);
        break;
    case capture::DepthConvention::ReversedInfinite: // 1 at near, 0 at infinity
        p.m[10] = 0.0;
        p.m[11] = n;
        break;
    }
    return p;
}

Mat4 viewAt(const Scene& scene, double frame, Vec3& eye) {
    const CameraDesc& c = scene.camera;
    if (c.view) {
        const Mat4 inv = *capture::inverse(*c.view);
        eye = {static_cast<float>(inv.m[3]), static_cast<float>(inv.m[7]), static_cast<float>(inv.m[11])};
        return *c.view;
    }
    const auto [position, target] = cameraEyeTarget(c, frame);
    eye = position;
    return lookAt(d3(eye), d3(target), d3(c.up));
}
} // namespace

std::pair<Vec3, Vec3> cameraEyeTarget(const CameraDesc& camera, double frame) {
    const auto [a, next] = segment(camera.keys, frame);
    const auto [b, t] = next;
    return {lerp(a->position, b->position, t), lerp(a->target, b->target, t)};
}

FrameCamera cameraAt(const Scene& scene, std::uint32_t frame) {
    FrameCamera fc;
    capture::Camera& cam = fc.camera;
    const double aspect = static_cast<double>(scene.width) / static_cast<double>(scene.height);
    cam.projection = scene.camera.projection ? *scene.camera.projection : perspective(scene.camera, aspect);
    cam.view = viewAt(scene, frame, fc.eye);
    Vec3 prevEye{};
    cam.prevViewProjection =
        capture::multiply(cam.projection, viewAt(scene, static_cast<double>(frame) - 1.0, prevEye));
    cam.depth = scene.camera.depth;
    cam.nearZ = scene.camera.nearZ;
    cam.farZ = scene.camera.depth == capture::DepthConvention::ReversedInfinite
                   ? std::numeric_limits<double>::infinity()
                   : scene.camera.farZ;
    cam.ndcYDown = scene.camera.ndcYDown;
    return fc;
}

} // namespace glint::scene
