// Scene files: a valid file round-trips into the scene, and malformed ones fail with one line
// naming the file, the line or key, and the problem.
#include "scene/scene_file.h"
#include "scene/scene_geometry.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

namespace glint::scene {
namespace {

std::string errorOf(const std::string& text, const std::filesystem::path& file = "bad.toml") {
    try {
        parseScene(text, file);
    } catch (const SceneError& error) {
        const std::string message = error.what();
        CHECK(message.find('\n') == std::string::npos);
        return message;
    }
    return "no error";
}

bool contains(const std::string& haystack, const std::string& needle) {
    INFO(haystack);
    return haystack.find(needle) != std::string::npos;
}

const char* kMinimal = "effects = [\"shadows\"]\n[[lights]]\ntype = \"directional\"\n";

TEST_CASE("A scene file fills every section", "[scene][file]") {
    const Scene s = parseScene(R"(
effects = ["reflections", "shadows"]
resolution = [64, 32]
frames = 3
seed = 9
[camera]
position = [0, 2, 4]
target = [0, 0, 0]
fov_y = 60
depth = "reversed"
[[camera.keyframes]]
frame = 0
[[camera.keyframes]]
frame = 2
position = [1, 2, 4]
[[lights]]
type = "sphere"
position = [0, 3, 0]
radius = 0.2
[materials.m]
roughness_ramp = { start = [-1, 0, 0], end = [1, 0, 0], from = 0.0, to = 1.0 }
[[objects]]
type = "sphere"
material = "m"
radius = 0.5
[[objects.keyframes]]
frame = 0
[[objects.keyframes]]
frame = 2
position = [1, 0, 0]
[reference]
shadows = true
spp = 16
environment_sampling = false
)",
                               "good.toml");
    CHECK(s.width == 64);
    CHECK(s.height == 32);
    CHECK(s.frameCount == 3);
    CHECK(s.seed == 9);
    CHECK(s.camera.depth == capture::DepthConvention::Reversed);
    REQUIRE(s.camera.keys.size() == 2);
    CHECK(s.camera.keys[1].position[0] == 1.0f);
    CHECK(s.camera.keys[1].target[1] == 0.0f);
    REQUIRE(s.lights.size() == 1);
    CHECK(s.lights[0].kind == LightKind::Sphere);
    REQUIRE(s.materials.size() == 1);
    CHECK(s.materials[0].ramp);
    REQUIRE(s.objects.size() == 1);
    CHECK(s.objects[0].keys.size() == 2);
    CHECK(needsReflections(s));
    CHECK(needsShadows(s));
    CHECK(s.reference.shadows);
    CHECK(s.reference.samplesPerPixel == 16);
    CHECK_FALSE(s.reference.environmentSampling);
    CHECK(parseScene(kMinimal, "minimal.toml").reference.environmentSampling);
}

TEST_CASE("Malformed scene files name the file, line, key and problem", "[scene][file]") {
    CHECK(contains(errorOf("effects = [\"reflections\"\n"), "bad.toml:"));
    CHECK(contains(errorOf("effects = [\"reflections\"\n"), "syntax"));
    CHECK(contains(errorOf("resolution = [1, 2]\n"), "effects: missing"));
    CHECK(contains(errorOf("effects = [\"refractions\"]\n"),
                   "bad.toml:1: effects: unknown effect 'refractions'"));
    CHECK(contains(errorOf("effects = [\"reflections\", \"reflections\"]\n"), "listed twice"));
    CHECK(
        contains(errorOf("frames = 0\n" + std::string(kMinimal)), "bad.toml:1: frames: value 0 is outside"));
    CHECK(contains(errorOf("resolutoin = [1, 2]\n" + std::string(kMinimal)),
                   "bad.toml:1: resolutoin: unknown key"));
    CHECK(contains(errorOf(std::string(kMinimal) + "[camera]\nfov_y = \"wide\"\n"),
                   "bad.toml:5: camera.fov_y: expected a finite number"));
    CHECK(contains(errorOf(std::string(kMinimal) + "[camera]\nposition = [1, 2]\n"),
                   "bad.toml:5: camera.position: expected an array of 3 numbers"));
    CHECK(contains(errorOf(std::string(kMinimal) + "[camera]\nnear = 2.0\nfar = 1.0\n"),
                   "camera.far: must be greater"));
    CHECK(contains(errorOf(std::string(kMinimal) + "[[objects]]\ntype = \"box\"\nmaterial = \"nope\"\n"),
                   "bad.toml:6: objects[0].material: unknown material 'nope'"));
    CHECK(contains(
        errorOf(std::string(kMinimal) + "[materials.m]\n[[objects]]\ntype = \"cone\"\nmaterial = \"m\"\n"),
        "objects[0].type: expected"));
    CHECK(contains(errorOf(std::string(kMinimal) + "[materials.m]\nmetallic = 2.0\n"),
                   "materials.m.metallic: value 2 is outside [0, 1]"));
    CHECK(contains(errorOf("effects = [\"shadows\"]\n"), "shadow_light: effect 'shadows' needs a light"));
    CHECK(contains(errorOf(std::string(kMinimal) + "[reference]\nreflections = true\n"),
                   "reference.reflections: needs effect"));
    CHECK(contains(
        errorOf(std::string(kMinimal) + "[[lights]]\ntype = \"directional\"\ndirection = [0, 0, 0]\n"),
        "lights[1].direction: must not be zero"));
}

TEST_CASE("Light keyframes are parsed, carried over and interpolated per frame", "[scene][file]") {
    const Scene s = parseScene(R"(
effects = ["shadows"]
[[lights]]
type = "directional"
direction = [0, 2, 0]
[[lights.keyframes]]
frame = 2
[[lights.keyframes]]
frame = 6
direction = [1, 1, 0]
[[lights]]
type = "sphere"
position = [0, 3, 0]
[[lights.keyframes]]
frame = 0
[[lights.keyframes]]
frame = 4
position = [4, 3, 0]
)",
                               "good.toml");
    REQUIRE(s.lights.size() == 2);
    const LightDesc& sun = s.lights[0];
    REQUIRE(sun.keys.size() == 2);
    CHECK(sun.keys[0].frame == 2.0f);
    // The first key carries the light's own (normalised) direction; every key is normalised.
    CHECK(sun.keys[0].direction == Vec3{0.0f, 1.0f, 0.0f});
    CHECK(sun.keys[1].direction[0] == Approx(std::sqrt(0.5)));
    CHECK(sun.keys[1].direction[1] == Approx(std::sqrt(0.5)));
    // Clamped before the first and after the last key.
    CHECK(lightAt(sun, 0.0).direction == sun.keys[0].direction);
    CHECK(lightAt(sun, 9.0).direction == sun.keys[1].direction);
    // Halfway: the normalised blend, 22.5 degrees from +y toward +x.
    const Vec3 mid = lightAt(sun, 4.0).direction;
    CHECK(mid[0] == Approx(std::sin(std::numbers::pi / 8.0)));
    CHECK(mid[1] == Approx(std::cos(std::numbers::pi / 8.0)));
    CHECK(mid[2] == Approx(0.0).margin(1e-7));
    const LightDesc& bulb = s.lights[1];
    REQUIRE(bulb.keys.size() == 2);
    CHECK(lightAt(bulb, 1.0).position[0] == Approx(1.0));
    CHECK(lightAt(bulb, 1.0).position[1] == Approx(3.0));
    const std::vector<LightDesc> atThree = lightsAt(s, 3);
    REQUIRE(atThree.size() == 2);
    CHECK(atThree[1].position[0] == Approx(3.0));
    // A light without keys is the same on every frame.
    const Scene still = parseScene(kMinimal, "good.toml");
    CHECK(still.lights[0].keys.empty());
    CHECK(lightAt(still.lights[0], 5.0).direction == still.lights[0].direction);
}

TEST_CASE("Malformed light keyframes fail with one line naming the key", "[scene][file]") {
    const std::string light = std::string(kMinimal) + "[[lights.keyframes]]\nframe = 3\n";
    CHECK(contains(errorOf(light + "[[lights.keyframes]]\nframe = 3\n"),
                   "bad.toml:6: lights[0].keyframes[1].frame: keyframes must be in increasing frame order"));
    CHECK(contains(errorOf(light + "direction = [0, 0, 0]\n"),
                   "bad.toml:6: lights[0].keyframes[0].direction: must not be zero"));
    CHECK(
        contains(errorOf(light + "radius = 2\n"), "bad.toml:6: lights[0].keyframes[0].radius: unknown key"));
    CHECK(contains(
        errorOf(light + "direction = [0, 1, 0]\n[[lights.keyframes]]\nframe = 4\ndirection = [0, -1, 0]\n"),
        "bad.toml:9: lights[0].keyframes[1].direction: turns by nearly 180 degrees"));
    CHECK(contains(errorOf(std::string(kMinimal) + "keyframes = 3\n"),
                   "bad.toml:4: lights[0].keyframes: expected an array of tables"));
}

TEST_CASE("A missing model file is an error naming the key and the path", "[scene][file]") {
    const std::string message = errorOf(
        std::string(kMinimal) +
            "[materials.m]\n[[objects]]\ntype = \"mesh\"\nmaterial = \"m\"\nfile = \"no/such/model.glb\"\n",
        "/tmp/scenes/bad.toml");
    CHECK(contains(
        message,
        "/tmp/scenes/bad.toml:8: objects[0].file: file '/tmp/scenes/no/such/model.glb' does not exist"));
}

TEST_CASE("A model file assimp cannot read fails when the geometry is built", "[scene][file]") {
    const std::filesystem::path dir = std::filesystem::path(GLINT_TEST_OUTPUT_DIR) / "scene_file_test";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "broken.gltf") << "{ this is not json";
    const Scene s = parseScene(
        std::string(kMinimal) +
            "[materials.m]\n[[objects]]\ntype = \"mesh\"\nmaterial = \"m\"\nfile = \"broken.gltf\"\n",
        dir / "scene.toml");
    try {
        loadMeshes(s);
        FAIL("no error");
    } catch (const SceneError& error) {
        CHECK(contains(error.what(), "broken.gltf: object 'objects[0]': cannot load model"));
    }
}

TEST_CASE("A look-at camera parallel to its up vector names camera.up, not the view matrix",
          "[scene][file]") {
    // Straight down with the default up: cross(direction, up) is zero, so the view matrix would
    // have no right vector (frames were once refused as "camera view matrix is not finite").
    CHECK(errorOf(std::string(kMinimal) + "[camera]\nposition = [0, 5, 0]\ntarget = [0, 0, 0]\n",
                  "scenes/down.toml") ==
          "scenes/down.toml:4: camera.up: the default [0, 1, 0] is parallel to the view direction [0, -1, 0] "
          "on "
          "frame 0; give camera.up a direction across the view (for a camera looking straight up or down, "
          "e.g. [0, 0, -1])");
    // A given up is quoted as given, on its own line.
    CHECK(
        errorOf(std::string(kMinimal) +
                "[camera]\nposition = [0, 0, 0]\ntarget = [2, 0, 0]\nup = [-3, 0, 0]\n") ==
        "bad.toml:7: camera.up: [-3, 0, 0] is parallel to the view direction [1, 0, 0] on frame 0; give "
        "camera.up a direction across the view (for a camera looking straight up or down, e.g. [0, 0, -1])");
    CHECK(errorOf(std::string(kMinimal) + "[camera]\nup = [0, 0, 0]\n") ==
          "bad.toml:5: camera.up: must not be zero");
    CHECK(errorOf(std::string(kMinimal) + "[camera]\nposition = [1, 2, 3]\ntarget = [1, 2, 3]\n") ==
          "bad.toml:6: camera.target: equals camera.position [1, 2, 3] on frame 0: the camera looks nowhere");
    // Keyframes: the first frame whose interpolated camera looks along up is named (frame 1 of
    // keys at 0 and 2 is halfway: from [0, 5, 0] toward [0, 0, 0], straight down).
    CHECK(errorOf("frames = 3\n" + std::string(kMinimal) +
                  "[camera]\n[[camera.keyframes]]\nframe = 0\nposition = [-1, 5, 0]\ntarget = [1, 0, 0]\n"
                  "[[camera.keyframes]]\nframe = 2\nposition = [1, 5, 0]\ntarget = [-1, 0, 0]\n") ==
          "bad.toml:5: camera.up: the default [0, 1, 0] is parallel to the view direction [0, -1, 0] on "
          "frame 1; "
          "give camera.up a direction across the view (for a camera looking straight up or down, e.g. [0, 0, "
          "-1])");
    // A key past the rendered frames is checked too (--frame-count may reach it).
    CHECK(contains(errorOf(std::string(kMinimal) +
                           "[camera]\n[[camera.keyframes]]\nframe = 0\n[[camera.keyframes]]\nframe = 9\n"
                           "position = [0, 5, 0]\n"),
                   "camera.up: the default [0, 1, 0] is parallel to the view direction [0, -1, 0] at "
                   "camera.keyframes[1]"));
    // Straight down with an up across the view, or given by a view matrix, is fine.
    CHECK_NOTHROW(parseScene(std::string(kMinimal) + "[camera]\nposition = [0, 5, 0]\ntarget = [0, 0, 0]\n"
                                                     "up = [0, 0, -1]\n",
                             "good.toml"));
    CHECK_NOTHROW(parseScene(std::string(kMinimal) +
                                 "[camera]\nposition = [0, 5, 0]\ntarget = [0, 0, 0]\n"
                                 "view = [1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, -5, 0, 0, 0, 1]\n",
                             "good.toml"));
}

TEST_CASE("A missing scene file is an error naming it", "[scene][file]") {
    CHECK_THROWS_WITH(loadScene("/no/such/scene.toml"), "/no/such/scene.toml: cannot open the scene file");
}

} // namespace
} // namespace glint::scene
