// Scene files: a valid file round-trips into the scene, and malformed ones fail with one line
// naming the file, the line or key, and the problem.
#include "scene/scene_file.h"
#include "scene/scene_geometry.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

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

TEST_CASE("A missing scene file is an error naming it", "[scene][file]") {
    CHECK_THROWS_WITH(loadScene("/no/such/scene.toml"), "/no/such/scene.toml: cannot open the scene file");
}

} // namespace
} // namespace glint::scene
