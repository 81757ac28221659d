// What a scene declares decides what is traced and written: layer sets and passes per effect,
// valid captures, per-frame noise in the shadow layer, and bit-identical reruns.
#include "scene/scene_test_scenes.h"
#include "support/gpu_test_context.h"

#include "capture/sequence_io.h"
#include "scene/scene_bvh.h"
#include "scene/scene_file.h"
#include "scene/scene_geometry.h"
#include "scene/scene_simulate.h"
#include "scene/scene_trace.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <filesystem>

namespace glint::scene {
namespace {

std::vector<std::string> passNames(const Simulation& sim) {
    std::vector<std::string> names;
    for (const PassTime& p : sim.passes) names.push_back(p.pass);
    return names;
}

std::vector<std::string> frameLayers(const capture::Frame& frame) {
    std::vector<std::string> names;
    for (const capture::Layer& l : frame.layers) names.push_back(l.name);
    return names;
}

using Names = std::vector<std::string>;

TEST_CASE("A shadows-only scene traces no reflection rays and writes no reflection layers", "[scene][gpu]") {
    Scene scene = test::analyticScene(32, 18, 1);
    scene.effects = {Effect::Shadows};
    scene.reference.shadows = true;
    scene.reference.samplesPerPixel = 4;
    const Simulation sim = simulate(test::testContext(), scene);
    CHECK(passNames(sim) == Names{"gbuffer", "shadow", "reference.shadow"});
    CHECK(frameLayers(sim.frames[0]) ==
          Names{"depth", "normal", "motion", "shadow", "shadow_blocker", "reference.shadow"});
    // The shadow denoiser's penumbra estimate: the sun's tan(4 degrees), and a blocker distance
    // exactly where the noisy sample is shadowed (0 where lit; > 0, or 0 for a direction below
    // the surface, where shadowed).
    CHECK(sim.frames[0].shadowLightTanHalfAngle == Approx(std::tan(4.0 * 3.14159265358979 / 180.0)));
    const auto& visibility = capture::findLayer(sim.frames[0], "shadow")->pixels;
    const auto& blocker = capture::findLayer(sim.frames[0], "shadow_blocker")->pixels;
    REQUIRE(blocker.size() == visibility.size());
    for (std::size_t i = 0; i < visibility.size(); ++i) {
        CHECK(std::isfinite(blocker[i]));
        CHECK(blocker[i] >= 0.0f);
        if (visibility[i] > 0.5f) CHECK(blocker[i] == 0.0f);
    }
    CHECK_FALSE(sim.environment.has_value());
    CHECK(sim.frames[0].effects == Names{"shadows"});
    CHECK(sim.frames[0].roughness.layer.empty());
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("A reflections-only scene traces no shadow layers", "[scene][gpu]") {
    Scene scene = test::analyticScene(32, 18, 1);
    scene.effects = {Effect::Hybrid};
    const Simulation plain = simulate(test::testContext(), scene);
    CHECK(passNames(plain) == Names{"gbuffer", "shade"});
    CHECK(frameLayers(plain.frames[0]) ==
          Names{"depth", "normal", "motion", "roughness", "material", "color"});
    CHECK(plain.environment.has_value());
    // The capture declares the hybrid effect, which replays it (its manifest names the scene).
    CHECK(plain.frames[0].effects == Names{"hybrid"});

    scene.reference.reflections = true;
    scene.reference.samplesPerPixel = 2;
    const Simulation referenced = simulate(test::testContext(), scene);
    CHECK(passNames(referenced) == Names{"gbuffer", "shade", "reference.reflection"});
    CHECK(frameLayers(referenced.frames.at(0)).back() == "reference.reflection");
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

// A wall at 9990 across the whole view, tilted 5 degrees (so that no pixel sees it head-on) and
// a near sphere; `depth`, `effects` and the clip planes vary.
Scene farWallScene(const std::string& depth, const std::string& effects, const std::string& nearZ = "0.001",
                   const std::string& farZ = "10000") {
    return parseScene("effects = [" + effects + R"(]
resolution = [48, 27]
[camera]
position = [0, 0, 0]
target = [0, 0, -1]
near = )" + nearZ + R"(
far = )" + farZ + R"(
depth = ")" + depth + R"("
[[lights]]
direction = [0, 1, 1]
[materials.wall]
roughness = 0.5
[[objects]]
type = "box"
material = "wall"
position = [0, 0, -9990]
size = [30000, 30000, 1]
rotation = [0, 5, 0]
[[objects]]
type = "sphere"
material = "wall"
position = [0, 0, -5]
radius = 1
)",
                      "far_wall.toml");
}

// The wall's pixels by a CPU ray per pixel centre (tests/reference BVH, the eye at the origin),
// with each pixel's device depth in double from the scene's own projection: the pixels whose
// depth lies within `window` of the far value, and those of them not next to a sphere pixel
// (where the GPU's float ray may take the other object).
struct WallPixels {
    std::size_t withinWindow = 0, clearOfSphere = 0, sphere = 0;
};
WallPixels wallPixels(const Scene& scene, double window) {
    const FrameCamera cam = cameraAt(scene, 0);
    const Bvh bvh = buildBvh(buildGeometry(scene, {}, 0).primitives);
    const capture::Mat4 vp = capture::viewProjection(cam.camera);
    const capture::Mat4 inv = *capture::inverse(vp);
    const bool reversed = scene.camera.depth != capture::DepthConvention::Standard;
    std::vector<int> kind(std::size_t{scene.width} * scene.height, 0); // 0 none, 1 wall in window, 2 sphere
    for (std::uint32_t y = 0; y < scene.height; ++y)
        for (std::uint32_t x = 0; x < scene.width; ++x) {
            const capture::Vec4 q = capture::transform(
                inv, {2.0 * (x + 0.5) / scene.width - 1.0, 1.0 - 2.0 * (y + 0.5) / scene.height, 0.5, 1.0});
            const double d[3] = {q.x / q.w, q.y / q.w, q.z / q.w};
            const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            const Ray ray{{0.0f, 0.0f, 0.0f},
                          {static_cast<float>(d[0] / len), static_cast<float>(d[1] / len),
                           static_cast<float>(d[2] / len)}};
            const Hit hit = traceClosest(bvh, ray);
            if (hit.t < 0.0f) continue;
            const double t = hit.t;
            const capture::Vec4 clip = capture::transform(
                vp, {static_cast<double>(ray.direction[0]) * t, static_cast<double>(ray.direction[1]) * t,
                     static_cast<double>(ray.direction[2]) * t, 1.0});
            const double fromFar = reversed ? clip.z / clip.w : 1.0 - clip.z / clip.w;
            int& k = kind[std::size_t{y} * scene.width + x];
            k = t < 10.0 ? 2 : std::abs(fromFar) < window ? 1 : 0;
        }
    WallPixels w;
    for (std::uint32_t y = 0; y < scene.height; ++y)
        for (std::uint32_t x = 0; x < scene.width; ++x) {
            const int k = kind[std::size_t{y} * scene.width + x];
            w.sphere += k == 2;
            if (k != 1) continue;
            ++w.withinWindow;
            bool nearSphere = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const auto xx = static_cast<std::int64_t>(x) + dx, yy = static_cast<std::int64_t>(y) + dy;
                    if (xx >= 0 && yy >= 0 && xx < scene.width && yy < scene.height)
                        nearSphere =
                            nearSphere ||
                            kind[static_cast<std::size_t>(yy) * scene.width + static_cast<std::size_t>(xx)] ==
                                2;
                }
            w.clearOfSphere += !nearSphere;
        }
    return w;
}

TEST_CASE("Surface pixels the background test takes for the sky are counted and warned about in both "
          "depth conventions, and the advice clears them",
          "[scene][gpu]") {
    // Near 0.001, far 10000: the wall (view depth 9550 to 10430) lies within about 5e-9 of the
    // far value in either convention, far inside the 1e-6 cut-off. The window 1e-6 plus the ray
    // caster's float error on clip.z / clip.w (~1e-7) bounds the count from above; the wall
    // beyond the far plane is in the window too (the ray caster keeps a hit whose float depth
    // reaches the far value), so there is no lower bound beyond "some".
    const Scene scene = farWallScene("standard", "\"reflections\"");
    const Simulation sim = simulate(test::testContext(), scene);
    const WallPixels wall = wallPixels(scene, 1.1e-6);
    REQUIRE(wall.sphere > 0);
    CHECK(sim.surfacesAtBackgroundDepth > 0);
    CHECK(sim.surfacesAtBackgroundDepth <= wall.withinWindow);
    REQUIRE(sim.warnings.size() == 1);
    CHECK(sim.warnings[0] ==
          "far_wall.toml: warning: " + std::to_string(sim.surfacesAtBackgroundDepth) +
              " surface pixels on 1 of 1 frame have device depth within 1e-6 of the background's 1 "
              "(standard depth, near 0.001, far 10000), so they replay as sky while their other layers "
              "show a surface; a surface at view depth z keeps its depth apart only while near * (far - z) "
              "/ (z * (far - near)) > 1e-6, in either depth convention: raise camera.near above 2e-6 "
              "times the farthest surface's view depth, with camera.far at least twice that depth");

    // Without material layers the normal alone tells the wall from the sky (it never faces the
    // ray head-on): the same pixels are found.
    const Simulation shadows = simulate(test::testContext(), farWallScene("standard", "\"shadows\""));
    CHECK(shadows.surfacesAtBackgroundDepth == sim.surfacesAtBackgroundDepth);

    // Far 1e6, well beyond the wall: its depth lies n (f - z) / (z (f - n)) ~ 1e-7 from the far
    // value in both conventions (reversed: ~1e-7, not 0), still under the cut-off, so every wall
    // pixel is sky. Bounds: the wall pixels within the window, and those clear of the sphere.
    for (const char* depth : {"standard", "reversed"}) {
        CAPTURE(depth);
        const Scene farScene = farWallScene(depth, "\"reflections\"", "0.001", "1000000");
        const Simulation beyond = simulate(test::testContext(), farScene);
        const WallPixels w = wallPixels(farScene, 1.1e-6);
        REQUIRE(w.clearOfSphere > 0);
        CHECK(beyond.surfacesAtBackgroundDepth >= w.clearOfSphere);
        CHECK(beyond.surfacesAtBackgroundDepth <= w.withinWindow);
        REQUIRE(beyond.warnings.size() == 1);
        CHECK(beyond.warnings[0].find(std::string("background's ") + (depth[0] == 's' ? "1" : "0") + " (" +
                                      depth + " depth, near 0.001, far 1e+06)") != std::string::npos);
    }

    // The advice followed: near 0.1 (above 2e-6 of 10430) and far 1e6 put the wall about 1e-5
    // from the far value, beyond the cut-off: no pixel is lost and nothing warns.
    for (const char* depth : {"standard", "reversed"}) {
        CAPTURE(depth);
        const Scene cleared = farWallScene(depth, "\"reflections\"", "0.1", "1000000");
        REQUIRE(wallPixels(cleared, 1.1e-6).withinWindow == 0);
        const Simulation ok = simulate(test::testContext(), cleared);
        CHECK(ok.surfacesAtBackgroundDepth == 0);
        CHECK(ok.warnings.empty());
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("Simulated captures are valid sequences and reruns are bit-identical", "[scene][gpu]") {
    Scene scene = test::analyticScene(40, 24, 2);
    scene.effects = {Effect::Reflections, Effect::Shadows};
    scene.reference = {true, true, 2};
    const Simulation a = simulate(test::testContext(), scene);
    const Simulation b = simulate(test::testContext(), scene);
    REQUIRE(a.frames.size() == b.frames.size());
    for (std::size_t f = 0; f < a.frames.size(); ++f) {
        REQUIRE(a.frames[f].layers.size() == b.frames[f].layers.size());
        for (std::size_t l = 0; l < a.frames[f].layers.size(); ++l) {
            const auto& x = a.frames[f].layers[l].pixels;
            const auto& y = b.frames[f].layers[l].pixels;
            INFO("frame " << f << " layer " << a.frames[f].layers[l].name);
            REQUIRE(x.size() == y.size());
            CHECK(std::memcmp(x.data(), y.data(), x.size() * sizeof(float)) == 0);
            CHECK(capture::countNonFinite(x) == 0);
        }
    }
    const std::filesystem::path dir = std::filesystem::path(GLINT_TEST_OUTPUT_DIR) / "scene_effects_sequence";
    std::filesystem::remove_all(dir);
    capture::writeSequence(dir, a.frames, scene.frameRate, &*a.environment);
    const capture::Sequence seq = capture::readSequence(dir); // validates every header
    CHECK(seq.headers.size() == 2);
    CHECK(seq.environment == "environment.exr");
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

double layerRmse(const Simulation& sim, std::size_t frame, const Simulation& truth, const char* layer) {
    const auto& a = capture::findLayer(sim.frames.at(frame), layer)->pixels;
    const auto& b = capture::findLayer(truth.frames.at(0), layer)->pixels;
    double sum = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
        sum += (double{a[i]} - double{b[i]}) * (double{a[i]} - double{b[i]});
    return std::sqrt(sum / static_cast<double>(a.size()));
}

TEST_CASE("References accumulate over unchanged frames and start again after a change", "[scene][gpu]") {
    Scene still = test::analyticScene(24, 14, 4);
    still.camera.keys.resize(1);
    still.objects[2].keys.resize(1);
    still.effects = {Effect::Reflections, Effect::Shadows};
    still.lights[0].angularRadiusDegrees = 20.0f; // penumbrae wide enough to measure the noise on
    still.reference = {true, true, 4};
    const Simulation accumulated = simulate(test::testContext(), still);
    CHECK(accumulated.referenceSamples == std::vector<std::uint32_t>{4, 8, 12, 16});
    // The reflection reference continues one sequence of samples per pixel: the fourth frame at
    // 4 samples a frame is the first frame at 16, bit for bit.
    Scene once = still;
    once.frameCount = 1;
    once.reference.samplesPerPixel = 16;
    const Simulation sixteen = simulate(test::testContext(), once);
    const auto& last = capture::findLayer(accumulated.frames.at(3), "reference.reflection")->pixels;
    const auto& single = capture::findLayer(sixteen.frames.at(0), "reference.reflection")->pixels;
    REQUIRE(last.size() == single.size());
    CHECK(std::memcmp(last.data(), single.data(), last.size() * sizeof(float)) == 0);
    // The shadow reference is a running mean of each frame's own stratification: on the fourth
    // frame, nearer an independent 256-spp one than the first frame is (1/2 ideally).
    Scene truthScene = once;
    truthScene.seed = 99;
    truthScene.reference.samplesPerPixel = 256;
    const Simulation truth = simulate(test::testContext(), truthScene);
    const double first = layerRmse(accumulated, 0, truth, "reference.shadow");
    const double fourth = layerRmse(accumulated, 3, truth, "reference.shadow");
    INFO("shadow reference RMSE against 256 spp: frame 0 " << first << ", frame 3 " << fourth);
    CHECK(fourth < 0.7 * first);

    // Without accumulation every frame stands alone; the analytic scene's camera and ball move
    // until frame 4 and hold still after it, so the run starts again there.
    Scene independent = still;
    independent.reference.accumulate = false;
    CHECK(simulate(test::testContext(), independent).referenceSamples ==
          std::vector<std::uint32_t>{4, 4, 4, 4});
    Scene moving = test::analyticScene(24, 14, 7);
    moving.effects = {Effect::Shadows};
    moving.reference = {false, true, 4};
    CHECK(simulate(test::testContext(), moving).referenceSamples ==
          std::vector<std::uint32_t>{4, 4, 4, 4, 4, 8, 12});
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("The noisy shadow layer draws new random numbers every frame and averages to the reference",
          "[scene][gpu]") {
    Scene scene = test::analyticScene(96, 54, 3);
    scene.camera.keys.resize(1); // static camera and objects: only the noise may change
    scene.objects[2].keys.resize(1);
    scene.lights[0].angularRadiusDegrees = 12.0f; // wide penumbrae: many pixels with 0 < V < 1
    scene.effects = {Effect::Shadows};
    scene.reference = {false, true, 256};
    const Simulation sim = simulate(test::testContext(), scene);
    const auto& s0 = capture::findLayer(sim.frames[0], "shadow")->pixels;
    const auto& s1 = capture::findLayer(sim.frames[1], "shadow")->pixels;
    const auto& ref = capture::findLayer(sim.frames[0], "reference.shadow")->pixels;
    std::size_t changed = 0, penumbra = 0;
    double noisySum = 0.0, refSum = 0.0;
    for (std::size_t i = 0; i < s0.size(); ++i) {
        CHECK((s0[i] == 0.0f || s0[i] == 1.0f)); // one sample: visible or not
        changed += s0[i] != s1[i];
        if (ref[i] > 0.05f && ref[i] < 0.95f) ++penumbra;
        for (const auto& frame : sim.frames)
            noisySum += static_cast<double>(capture::findLayer(frame, "shadow")->pixels[i]);
        refSum += static_cast<double>(ref[i]);
    }
    INFO("penumbra pixels " << penumbra << ", changed " << changed);
    CHECK(penumbra > 20);
    CHECK(changed > penumbra / 8); // P(change) = 2V(1-V) per penumbra pixel
    // Mean over pixels and frames of the 1-sample estimate vs the converged mean.
    const double n = static_cast<double>(s0.size());
    CHECK(std::fabs(noisySum / (3.0 * n) - refSum / n) < 0.02);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("A keyframed light lights each frame as a still light at its interpolated pose would",
          "[scene][gpu]") {
    Scene scene = test::analyticScene(48, 27, 3);
    scene.camera.keys.resize(1); // only the light moves
    scene.objects[2].keys.resize(1);
    scene.environment.sunDisc = false; // the baked sky shows frame 0's disc; leave it out
    scene.effects = {Effect::Reflections, Effect::Shadows};
    scene.reference = {false, true, 4};
    LightDesc& sun = scene.lights[0];
    sun.keys = {{0.0f, sun.direction, sun.position}, {2.0f, {-0.5f, 0.7f, 0.3f}, sun.position}};
    const Simulation moving = simulate(test::testContext(), scene);
    for (std::uint32_t f = 0; f < scene.frameCount; ++f) {
        Scene still = scene;
        still.lights[0] = lightAt(sun, f);
        still.lights[0].keys.clear();
        still.reference.accumulate = false; // each frame its own estimate, as the moving light's frames are
        const Simulation expected = simulate(test::testContext(), still);
        for (const char* name : {"shadow", "reference.shadow", "color"}) {
            INFO("frame " << f << " layer " << name);
            const auto& x = capture::findLayer(moving.frames[f], name)->pixels;
            const auto& y = capture::findLayer(expected.frames[f], name)->pixels;
            REQUIRE(x.size() == y.size());
            CHECK(std::memcmp(x.data(), y.data(), x.size() * sizeof(float)) == 0);
        }
    }
    const auto& first = capture::findLayer(moving.frames[0], "reference.shadow")->pixels;
    const auto& last = capture::findLayer(moving.frames[2], "reference.shadow")->pixels;
    std::size_t moved = 0;
    for (std::size_t i = 0; i < first.size(); ++i) moved += std::fabs(first[i] - last[i]) > 0.5f ? 1u : 0u;
    CHECK(moved > 20u); // the shadows really moved
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

} // namespace
} // namespace glint::scene
