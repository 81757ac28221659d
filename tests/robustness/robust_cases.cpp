#include "robustness/robust_cases.h"

#include <cmath>
#include <limits>

namespace glint::test {

scene::Scene baseScene(std::uint32_t width, std::uint32_t height) {
    scene::Scene s;
    s.width = width;
    s.height = height;
    s.frameCount = kFrames;
    s.shadowSamples = 4;
    s.effects = {scene::Effect::Reflections, scene::Effect::Shadows, scene::Effect::Hybrid};
    s.camera.keys = {{0.0f, {-0.6f, 1.4f, 4.0f}, {0.0f, 0.8f, -2.0f}},
                     {float(kFrames - 1), {0.6f, 1.2f, 3.0f}, {0.0f, 0.8f, -2.0f}}};
    s.camera.farZ = 50.0;
    scene::LightDesc sun;
    sun.direction = {0.37139f, 0.74278f, 0.55709f};
    sun.angularRadiusDegrees = 3.0f;
    s.lights.push_back(sun);
    scene::MaterialDesc floor;
    floor.name = "floor";
    floor.roughness = 0.3f; // alpha 0.09: glossy, filtered by the denoiser
    floor.baseColor = {0.5f, 0.5f, 0.55f};
    scene::MaterialDesc mirror;
    mirror.name = "mirror";
    mirror.metallic = 1.0f;
    mirror.roughness = 0.0f;
    mirror.baseColor = {0.9f, 0.9f, 0.9f};
    scene::MaterialDesc rough;
    rough.name = "rough";
    rough.roughness = 1.0f;
    rough.baseColor = {0.8f, 0.2f, 0.1f};
    scene::MaterialDesc metal;
    metal.name = "metal";
    metal.metallic = 1.0f;
    metal.roughness = 0.15f;
    metal.baseColor = {0.9f, 0.7f, 0.3f};
    s.materials = {floor, mirror, rough, metal};
    scene::ObjectDesc plane;
    plane.shape = scene::ShapeKind::Plane;
    plane.size = {12.0f, 0.0f, 12.0f};
    plane.material = 0;
    scene::ObjectDesc wall;
    wall.shape = scene::ShapeKind::Box;
    wall.size = {5.0f, 2.5f, 0.1f};
    wall.material = 1;
    wall.keys = {{0.0f, {0.0f, 1.25f, -2.0f}, {}, {1.0f, 1.0f, 1.0f}}};
    scene::ObjectDesc box;
    box.shape = scene::ShapeKind::Box;
    box.size = {0.7f, 0.7f, 0.7f};
    box.material = 2;
    box.keys = {{0.0f, {-1.0f, 0.35f, -0.5f}, {0.0f, 25.0f, 0.0f}, {1.0f, 1.0f, 1.0f}}};
    scene::ObjectDesc ball;
    ball.shape = scene::ShapeKind::Sphere;
    ball.radius = 0.45f;
    ball.material = 3;
    ball.keys = {{0.0f, {0.6f, 0.45f, 0.3f}, {}, {1.0f, 1.0f, 1.0f}},
                 {float(kFrames - 1), {1.2f, 0.45f, 0.0f}, {}, {1.0f, 1.0f, 1.0f}}};
    s.objects = {plane, wall, box, ball};
    return s;
}

namespace {

using Frames = std::vector<capture::Frame>;

void setCamera(scene::Scene& s, std::vector<scene::CameraKey> keys) {
    s.camera.keys = std::move(keys);
}

// A camera that holds pose A until `frame` - 1 and pose B from `frame` on.
void jumpAt(scene::Scene& s, std::uint32_t frame) {
    const scene::CameraKey a{0.0f, {-0.6f, 1.4f, 4.0f}, {0.0f, 0.8f, -2.0f}};
    const scene::CameraKey b{0.0f, {2.5f, 0.6f, 1.0f}, {-1.0f, 0.4f, -1.5f}};
    scene::CameraKey a1 = a, b0 = b, b1 = b;
    a1.frame = float(frame - 1);
    b0.frame = float(frame);
    b1.frame = float(kFrames - 1);
    b1.position[0] += 0.5f;
    setCamera(s, {a, a1, b0, b1});
}

// Every frame in `which` gets its matrix `m` (of the camera) changed by `change`.
void breakFrames(Frames& frames, const std::vector<std::uint32_t>& which,
                 const std::function<void(capture::Camera&)>& change) {
    for (std::uint32_t f : which) change(frames.at(f).camera);
}

} // namespace

std::vector<HardCase> hardCases() {
    std::vector<HardCase> cases;
    std::uint32_t seed = 1;
    const auto add = [&](HardCase c) {
        c.seed = seed++;
        cases.push_back(std::move(c));
    };
    add({"baseline: slow pan over glossy floor, mirror, rough box, metal sphere", 32, 18, {}, {}, {}, {}});
    add({"grazing angles: camera 5 cm above a long glossy floor",
         32,
         18,
         [](scene::Scene& s) {
             s.objects[0].size = {40.0f, 0.0f, 40.0f};
             setCamera(s, {{0.0f, {0.0f, 0.05f, 6.0f}, {0.0f, 0.0f, -30.0f}},
                           {float(kFrames - 1), {0.8f, 0.06f, 5.0f}, {0.0f, 0.0f, -30.0f}}});
         },
         {},
         {},
         {}});
    add({"rays toward the camera: facing the mirror head-on, moving toward it",
         32,
         18,
         [](scene::Scene& s) {
             setCamera(s, {{0.0f, {0.0f, 1.2f, 3.0f}, {0.0f, 1.2f, -2.0f}},
                           {float(kFrames - 1), {0.0f, 1.2f, -1.2f}, {0.0f, 1.2f, -2.0f}}});
         },
         {},
         {},
         {}});
    add({"far plane and sky: the floor runs past the far plane, mostly sky",
         32,
         18,
         [](scene::Scene& s) {
             s.objects[0].size = {200.0f, 0.0f, 200.0f};
             s.camera.farZ = 8.0;
             setCamera(s, {{0.0f, {0.0f, 1.0f, 4.0f}, {0.0f, 2.5f, -10.0f}},
                           {float(kFrames - 1), {0.5f, 1.0f, 4.0f}, {0.5f, 2.0f, -10.0f}}});
         },
         {},
         {},
         {}});
    add({"looking straight up: sky only, no receivers",
         16,
         16,
         [](scene::Scene& s) {
             s.camera.up = {0.0f, 0.0f, -1.0f};
             setCamera(s, {{0.0f, {0.0f, 3.0f, 0.0f}, {0.0f, 10.0f, 0.0f}}});
         },
         {},
         {},
         {}});
    add({"every surface a mirror",
         32,
         18,
         [](scene::Scene& s) {
             for (auto& m : s.materials) m.roughness = 0.0f, m.metallic = 1.0f;
         },
         {},
         {},
         {}});
    add({"every surface fully rough",
         32,
         18,
         [](scene::Scene& s) {
             for (auto& m : s.materials) m.roughness = 1.0f;
         },
         {},
         {},
         {}});
    add({"reversed depth",
         32,
         18,
         [](scene::Scene& s) { s.camera.depth = capture::DepthConvention::Reversed; },
         {},
         {},
         {}});
    add({"reversed infinite depth",
         32,
         18,
         [](scene::Scene& s) { s.camera.depth = capture::DepthConvention::ReversedInfinite; },
         {},
         {},
         {}});
    add({"reversed infinite depth at grazing angles, 33x17",
         33,
         17,
         [](scene::Scene& s) {
             s.camera.depth = capture::DepthConvention::ReversedInfinite;
             s.objects[0].size = {60.0f, 0.0f, 60.0f};
             setCamera(s, {{0.0f, {0.0f, 0.08f, 6.0f}, {0.0f, 0.02f, -30.0f}},
                           {float(kFrames - 1), {-0.8f, 0.1f, 5.0f}, {0.0f, 0.02f, -30.0f}}});
         },
         {},
         {},
         {}});
    add({"tiny near plane, huge far plane (surfaces at the background depth)",
         32,
         18,
         [](scene::Scene& s) {
             s.camera.nearZ = 0.001;
             s.camera.farZ = 1e4;
             s.objects[0].size = {20000.0f, 0.0f, 20000.0f};
         },
         {},
         {},
         {}});
    add({"Vulkan NDC (y down)", 32, 18, [](scene::Scene& s) { s.camera.ndcYDown = true; }, {}, {}, {}});
    add({"1x1", 1, 1, {}, {}, {}, {}});
    add({"7x5", 7, 5, {}, {}, {}, {}});
    add({"33x17", 33, 17, {}, {}, {}, {}});
    add({"64x36, static camera",
         64,
         36,
         [](scene::Scene& s) {
             setCamera(s, {{0.0f, {-0.6f, 1.4f, 4.0f}, {0.0f, 0.8f, -2.0f}}});
         },
         {},
         {},
         {}});
    add({"1x9 column", 1, 9, {}, {}, {}, {}});
    add({"fast orbit",
         32,
         18,
         [](scene::Scene& s) {
             std::vector<scene::CameraKey> keys;
             for (std::uint32_t f = 0; f < kFrames; f += 10) {
                 const float a = 0.35f * float(f) / 10.0f;
                 keys.push_back(
                     {float(f), {3.5f * std::sin(a), 1.3f, 3.5f * std::cos(a)}, {0.0f, 0.5f, 0.0f}});
             }
             setCamera(s, keys);
         },
         {},
         {},
         {}});
    add({"camera cut at frame 60", 32, 18, [](scene::Scene& s) { jumpAt(s, 60); }, {}, {60}, {}});
    add({"teleport at frame 60 (no cut: the histories see the jump)",
         32,
         18,
         [](scene::Scene& s) { jumpAt(s, 60); },
         {},
         {},
         {}});
    add({"camera cuts every 37 frames", 32, 18, {}, {}, {37, 74, 111}, {}});
    add({"moving sun: shadows sweep the floor",
         32,
         18,
         [](scene::Scene& s) {
             s.lights[0].keys = {{0.0f, {0.7f, 0.5f, 0.5f}, {}},
                                 {float(kFrames - 1), {-0.7f, 0.5f, 0.3f}, {}}};
         },
         {},
         {},
         {}});
    // Degenerate matrices. A singular or non-finite camera is refused by the effects that invert it
    // (reflections, hybrid, shadows: their planners' InvalidArgument); the depth pyramid reads no
    // matrix and runs. A degenerate previous view-projection or a nearly singular projection is
    // accepted: the effects run and must stay finite.
    add({"singular projection (all zero) on frames 100-102",
         32,
         18,
         {},
         [](Frames& f) {
             breakFrames(f, {100, 101, 102}, [](capture::Camera& c) { c.projection.m.fill(0.0); });
         },
         {},
         {100, 101, 102},
         true});
    add({"NaN and Inf in the view matrix on frames 60 and 120",
         32,
         18,
         {},
         [](Frames& f) {
             breakFrames(f, {60},
                         [](capture::Camera& c) { c.view.m[3] = std::numeric_limits<double>::quiet_NaN(); });
             breakFrames(f, {120},
                         [](capture::Camera& c) { c.view.m[5] = std::numeric_limits<double>::infinity(); });
         },
         {},
         {60, 120},
         true});
    add({"singular view (rank 2: y collapsed) on frames 110-111",
         32,
         18,
         {},
         [](Frames& f) {
             breakFrames(f, {110, 111}, [](capture::Camera& c) {
                 for (std::size_t k = 0; k < 4; ++k) c.view.m[4 + k] = 0.0;
             });
         },
         {},
         {110, 111},
         true});
    add({"zero previous view-projection on frames 80-82",
         32,
         18,
         {},
         [](Frames& f) {
             breakFrames(f, {80, 81, 82}, [](capture::Camera& c) { c.prevViewProjection.m.fill(0.0); });
         },
         {},
         {80, 81, 82},
         false});
    add({"nearly singular projection (x, y scaled by 1e-20) on frames 90-91",
         32,
         18,
         {},
         [](Frames& f) {
             breakFrames(f, {90, 91}, [](capture::Camera& c) {
                 for (std::size_t k = 0; k < 8; ++k) c.projection.m[k] *= 1e-20;
             });
         },
         {},
         {90, 91},
         false});
    return cases;
}

} // namespace glint::test
