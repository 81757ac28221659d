// The GPU ray caster's G-buffer against CPU ray casting through the same BVH, and its motion
// vectors against reprojection of world positions with the previous frame's matrices.
#include "scene/scene_test_scenes.h"
#include "support/gpu_test_context.h"

#include "capture/capture_frame.h"
#include "scene/scene_bvh.h"
#include "scene/scene_geometry.h"
#include "scene/scene_simulate.h"
#include "scene/scene_trace.h"

#include <catch2/catch.hpp>

#include <cmath>

namespace glint::scene {
namespace {

using capture::Mat4;
using capture::Vec4;

struct Expected {
    bool hit = false;
    double depth = 1.0;
    double normal[3] = {};
    double world[3] = {};
    std::uint32_t object = 0;
};

// An independent primary ray: the pixel centre unprojected in double.
Expected castPixel(const Bvh& bvh, const FrameCamera& cam, std::uint32_t x, std::uint32_t y, std::uint32_t w,
                   std::uint32_t h) {
    const Mat4 vp = capture::viewProjection(cam.camera);
    const Mat4 inv = *capture::inverse(vp);
    const double ndcX = 2.0 * (x + 0.5) / w - 1.0, ndcY = 1.0 - 2.0 * (y + 0.5) / h;
    const Vec4 q = capture::transform(inv, {ndcX, ndcY, 0.5, 1.0});
    double d[3] = {q.x / q.w - static_cast<double>(cam.eye[0]), q.y / q.w - static_cast<double>(cam.eye[1]),
                   q.z / q.w - static_cast<double>(cam.eye[2])};
    const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    Ray ray{{cam.eye[0], cam.eye[1], cam.eye[2]},
            {static_cast<float>(d[0] / len), static_cast<float>(d[1] / len), static_cast<float>(d[2] / len)}};
    const Hit hit = traceClosest(bvh, ray);
    Expected e;
    if (hit.t < 0.0f) return e;
    const auto& p = bvh.primitives[hit.primitive];
    for (int k = 0; k < 3; ++k)
        e.world[k] = static_cast<double>(ray.origin[k]) + static_cast<double>(ray.direction[k] * hit.t);
    double n[3];
    if (p.kind == GLINT_SCENE_PRIM_SPHERE) {
        n[0] = e.world[0] - static_cast<double>(p.p0.x);
        n[1] = e.world[1] - static_cast<double>(p.p0.y);
        n[2] = e.world[2] - static_cast<double>(p.p0.z);
    } else {
        const double a[3] = {static_cast<double>(p.p1.x - p.p0.x), static_cast<double>(p.p1.y - p.p0.y),
                             static_cast<double>(p.p1.z - p.p0.z)};
        const double b[3] = {static_cast<double>(p.p2.x - p.p0.x), static_cast<double>(p.p2.y - p.p0.y),
                             static_cast<double>(p.p2.z - p.p0.z)};
        n[0] = a[1] * b[2] - a[2] * b[1];
        n[1] = a[2] * b[0] - a[0] * b[2];
        n[2] = a[0] * b[1] - a[1] * b[0];
    }
    const double nl = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const double facing = n[0] * static_cast<double>(ray.direction[0]) +
                          n[1] * static_cast<double>(ray.direction[1]) +
                          n[2] * static_cast<double>(ray.direction[2]);
    for (int k = 0; k < 3; ++k) e.normal[k] = (facing > 0.0 ? -n[k] : n[k]) / nl;
    const Vec4 clip = capture::transform(vp, {e.world[0], e.world[1], e.world[2], 1.0});
    e.depth = clip.z / clip.w;
    e.hit = true;
    e.object = p.object;
    return e;
}

TEST_CASE("G-buffer and motion of an analytic scene match CPU ray casting and reprojection", "[scene][gpu]") {
    const std::uint32_t w = 96, h = 54;
    Scene scene = test::analyticScene(w, h, 2);
    scene.effects = {Effect::Reflections};
    const Simulation sim = simulate(test::testContext(), scene);
    REQUIRE(sim.frames.size() == 2);
    const capture::Frame& frame = sim.frames[1];
    const auto* depth = capture::findLayer(frame, "depth");
    const auto* normal = capture::findLayer(frame, "normal");
    const auto* motion = capture::findLayer(frame, "motion");
    const auto* roughness = capture::findLayer(frame, "roughness");
    REQUIRE(depth);
    REQUIRE(normal);
    REQUIRE(motion);
    REQUIRE(roughness);

    const FrameCamera cam = cameraAt(scene, 1);
    const Bvh bvh = buildBvh(buildGeometry(scene, {}, 1).primitives);
    const Mat4 invVp = *capture::inverse(capture::viewProjection(cam.camera));
    std::size_t disagreements = 0, hits = 0, moving = 0;
    double worstDepth = 0.0, worstNormal = 1.0, worstMotionPx = 0.0;
    for (std::uint32_t y = 0; y < h; ++y) {
        for (std::uint32_t x = 0; x < w; ++x) {
            const std::size_t i = std::size_t{y} * w + x;
            const Expected e = castPixel(bvh, cam, x, y, w, h);
            const double d = static_cast<double>(depth->pixels[i]);
            const bool gpuHit = d < 1.0;
            const double gn[3] = {static_cast<double>(normal->pixels[3 * i]),
                                  static_cast<double>(normal->pixels[3 * i + 1]),
                                  static_cast<double>(normal->pixels[3 * i + 2])};
            const double agreement = gn[0] * e.normal[0] + gn[1] * e.normal[1] + gn[2] * e.normal[2];
            // Silhouette pixels may see different surfaces in float and double; count them.
            if (gpuHit != e.hit || (e.hit && agreement < 0.99)) {
                ++disagreements;
                continue;
            }
            const double u = (x + 0.5) / w, v = (y + 0.5) / h;
            const double mvx = static_cast<double>(motion->pixels[2 * i]),
                         mvy = static_cast<double>(motion->pixels[2 * i + 1]);
            double prevU = 0.0, prevV = 0.0;
            if (!e.hit) {
                CHECK(d == 1.0);
                const Vec4 far = capture::transform(invVp, {2.0 * u - 1.0, 1.0 - 2.0 * v, 0.5, 1.0});
                const Vec4 c = capture::transform(cam.camera.prevViewProjection,
                                                  {far.x / far.w - static_cast<double>(cam.eye[0]),
                                                   far.y / far.w - static_cast<double>(cam.eye[1]),
                                                   far.z / far.w - static_cast<double>(cam.eye[2]), 0.0});
                prevU = 0.5 * c.x / c.w + 0.5;
                prevV = 0.5 - 0.5 * c.y / c.w;
            } else {
                ++hits;
                worstDepth = std::max(worstDepth, std::fabs(d - e.depth));
                worstNormal = std::min(worstNormal, agreement);
                // World position from the GPU's own depth, then to where it was last frame.
                const Vec4 q = capture::transform(invVp, {2.0 * u - 1.0, 1.0 - 2.0 * v, d, 1.0});
                Vec4 p{q.x / q.w, q.y / q.w, q.z / q.w, 1.0};
                const ObjectDesc& object = scene.objects[e.object];
                const Mat4 toPrevious = capture::multiply(objectMatrix(object, 0.0),
                                                          *capture::inverse(objectMatrix(object, 1.0)));
                if (!(toPrevious == capture::identity())) ++moving;
                p = capture::transform(toPrevious, p);
                const Vec4 c = capture::transform(cam.camera.prevViewProjection, p);
                prevU = 0.5 * c.x / c.w + 0.5;
                prevV = 0.5 - 0.5 * c.y / c.w;
                const double expectedRoughness =
                    static_cast<double>(scene.materials[scene.objects[e.object].material].roughness);
                CHECK(std::fabs(static_cast<double>(roughness->pixels[i]) - expectedRoughness) < 1e-6);
            }
            worstMotionPx =
                std::max({worstMotionPx, std::fabs(u + mvx - prevU) * w, std::fabs(v + mvy - prevV) * h});
        }
    }
    INFO("disagreeing pixels " << disagreements << ", hits " << hits << ", on the moving sphere " << moving);
    CHECK(disagreements <= w * h / 200); // silhouettes only: well under 0.5% of the pixels
    CHECK(hits > w * h / 3);
    CHECK(moving > 50);
    CHECK(worstDepth < 2e-5);
    CHECK(worstNormal > 0.9999);
    // docs/conventions.md §3: uv + mv equals the reprojection to within 1e-3 px.
    CHECK(worstMotionPx < 1e-3);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

} // namespace
} // namespace glint::scene
