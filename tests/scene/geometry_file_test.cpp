// scene::loadGeometryScene (glint run --geometry): a glTF as the static scene of the effects
// that ray trace. A scene written as glTF reads back with the same world triangles, materials
// and lights bit for bit; a hand-written file's node transforms, glTF's material defaults,
// emissive strength and punctual lights; and every bad file is one SceneError line naming it.
#include "scene/scene_gltf_export.h"

#include <scene/scene_buffers.h>
#include <scene/scene_file.h>
#include <scene/scene_geometry.h>

#include <catch2/catch.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>

using namespace glint;
using namespace glint::scene;

namespace {

std::filesystem::path outputDir() {
    const std::filesystem::path dir = std::filesystem::path(GLINT_TEST_OUTPUT_DIR) / "geometry_file_test";
    std::filesystem::create_directories(dir);
    return dir;
}

std::filesystem::path writeFile(const std::string& name, const std::string& text) {
    const std::filesystem::path file = outputDir() / name;
    std::ofstream(file, std::ios::binary) << text;
    return file;
}

bool same(const shaders::float3& a, const shaders::float3& b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// The error of loading `file`, which must be one line naming the file.
std::string failure(const std::filesystem::path& file) {
    try {
        (void)loadGeometryScene(file);
    } catch (const SceneError& error) {
        const std::string message = error.what();
        CHECK(message.find('\n') == std::string::npos);
        CHECK(message.rfind(file.string() + ": ", 0) == 0);
        return message;
    }
    FAIL("no error for " + file.string());
    return {};
}

// Three positions (0,0,0), (1,0,0), (0,1,0) as a base64 buffer of 36 bytes.
constexpr const char* kTriangle = "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA";

} // namespace

TEST_CASE("A scene written as glTF reads back with its triangles, materials and lights bit for bit",
          "[scene][geometry]") {
    const Scene source =
        loadScene(std::filesystem::path(GLINT_SOURCE_DIR) / "tests/cli/scenes/geometry_corridor.toml");
    const std::filesystem::path file = writeFile("corridor.gltf", test::sceneAsGltf(source));
    std::vector<std::string> warnings;
    const Scene loaded = loadGeometryScene(file, &warnings);
    CHECK(warnings.empty());
    REQUIRE(loaded.objects.size() == 4); // one per material
    CHECK(loaded.objects[0].name == "floor");
    CHECK(loaded.objects[3].name == "tile");
    CHECK(loaded.frameCount == 1);

    const FrameGeometry a = buildGeometry(source, loadMeshes(source), 0);
    const FrameGeometry b = buildGeometry(loaded, loadMeshes(loaded), 0);
    REQUIRE(a.primitives.size() == b.primitives.size());
    const std::vector<shaders::SceneMaterial> ma = packMaterials(source), mb = packMaterials(loaded);
    for (std::size_t i = 0; i < a.primitives.size(); ++i) {
        const shaders::ScenePrimitive& p = a.primitives[i];
        const shaders::ScenePrimitive& q = b.primitives[i];
        INFO("primitive " << i);
        REQUIRE(q.kind == GLINT_SCENE_PRIM_TRIANGLE);
        CHECK(same(p.p0, q.p0));
        CHECK(same(p.p1, q.p1));
        CHECK(same(p.p2, q.p2));
        const shaders::SceneMaterial& x = ma.at(p.material);
        const shaders::SceneMaterial& y = mb.at(q.material);
        CHECK(same(x.baseColor, y.baseColor));
        CHECK(same(x.emissive, y.emissive)); // 4, 2, 1: emissive factor (1, 0.5, 0.25) times strength 4
        CHECK(x.metallic == y.metallic);
        CHECK(x.roughness == y.roughness);
        CHECK(x.roughnessEnd == y.roughnessEnd);
    }
    const std::vector<shaders::SceneLight> la = packLights(lightsAt(source, 0));
    const std::vector<shaders::SceneLight> lb = packLights(lightsAt(loaded, 0));
    REQUIRE(la.size() == 2);
    REQUIRE(lb.size() == 2);
    for (std::size_t i = 0; i < la.size(); ++i) {
        INFO("light " << i);
        CHECK(la[i].kind == lb[i].kind);
        CHECK(same(la[i].where, lb[i].where));
        CHECK(same(la[i].radiance, lb[i].radiance));
        CHECK(la[i].size == lb[i].size); // zero in the source; glTF's lights have no size
    }
    // Points and directions: one visibility ray is the converged visibility.
    CHECK(loaded.shadowSamples == 1);
}

TEST_CASE("A hand-written glTF: node transforms, glTF's material defaults, emissive strength and lights",
          "[scene][geometry]") {
    const std::string gltf = std::string(R"({"asset":{"version":"2.0"},
"extensionsUsed":["KHR_lights_punctual","KHR_materials_emissive_strength"],
"extensions":{"KHR_lights_punctual":{"lights":[
  {"type":"directional","intensity":2},
  {"type":"spot","color":[1,0.5,0.25],"intensity":4,"spot":{"outerConeAngle":0.5}},
  {"type":"point","intensity":1},
  {"type":"point","intensity":7}]}},
"scene":0,"scenes":[{"nodes":[0,1,2,3,5]}],
"nodes":[
  {"name":"scaled","mesh":0,"translation":[0,1,0],"scale":[2,2,2]},
  {"name":"glowing","mesh":1,"translation":[0,0,-4]},
  {"name":"sun","rotation":[0.70710678,0,0,0.70710678],"extensions":{"KHR_lights_punctual":{"light":0}}},
  {"name":"rig","translation":[10,0,0],"children":[4]},
  {"name":"spot","translation":[1,2,3],"extensions":{"KHR_lights_punctual":{"light":1}}},
  {"name":"bulb","translation":[0,5,0],"scale":[3,3,3],"extensions":{"KHR_lights_punctual":{"light":2}}}],
"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]},
          {"primitives":[{"attributes":{"POSITION":0},"material":0}]}],
"materials":[{"name":"glow","pbrMetallicRoughness":{"baseColorFactor":[0.5,0.25,1,1]},
  "emissiveFactor":[1,0.5,0],"extensions":{"KHR_materials_emissive_strength":{"emissiveStrength":2}}}],
"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],
"bufferViews":[{"buffer":0,"byteLength":36}],
"buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,)") +
                             kTriangle + "\"}]}\n";
    std::vector<std::string> warnings;
    const Scene s = loadGeometryScene(writeFile("hand.gltf", gltf), &warnings);

    REQUIRE(s.objects.size() == 2);
    REQUIRE(s.materials.size() == 2);
    const FrameGeometry g = buildGeometry(s, loadMeshes(s), 0);
    REQUIRE(g.primitives.size() == 2);
    // assimp puts the default material (for the mesh without one) after the file's.
    const MaterialDesc* glow = nullptr;
    const MaterialDesc* plain = nullptr;
    for (const shaders::ScenePrimitive& p : g.primitives) {
        const MaterialDesc& m = s.materials.at(p.material);
        if (p.p0.z == -4.0f) {
            glow = &m;
            CHECK((p.p1.x == 1.0f && p.p2.y == 1.0f));
        } else {
            plain = &m; // scale 2, then up by 1
            CHECK((p.p0.x == 0.0f && p.p0.y == 1.0f && p.p1.x == 2.0f && p.p1.y == 1.0f && p.p2.y == 3.0f));
        }
    }
    REQUIRE(glow);
    REQUIRE(plain);
    CHECK(glow->name == "glow");
    CHECK(glow->baseColor == Vec3{0.5f, 0.25f, 1.0f});
    CHECK(glow->metallic == 1.0f); // glTF's defaults
    CHECK(glow->roughness == 1.0f);
    CHECK(glow->emissive == Vec3{2.0f, 1.0f, 0.0f});
    CHECK(plain->baseColor == Vec3{1.0f, 1.0f, 1.0f});
    CHECK(plain->metallic == 1.0f);
    CHECK(plain->roughness == 1.0f);
    CHECK(plain->emissive == Vec3{0.0f, 0.0f, 0.0f});

    // The sun's node turns -z (its travel) by 90 degrees about x: it shines straight up, so the
    // direction toward it is -y. The spot's parent moves it by 10 in x. The light no node uses
    // is not in the scene (assimp's glTF reader reads only what the scene refers to).
    REQUIRE(s.lights.size() == 3);
    CHECK(s.lights[0].kind == LightKind::Directional);
    CHECK(std::abs(s.lights[0].direction[0]) < 1e-6f);
    CHECK(std::abs(s.lights[0].direction[1] + 1.0f) < 1e-6f);
    CHECK(std::abs(s.lights[0].direction[2]) < 1e-6f);
    CHECK(s.lights[0].color == Vec3{2.0f, 2.0f, 2.0f});
    CHECK(s.lights[0].angularRadiusDegrees == 0.0f);
    CHECK(s.lights[1].kind == LightKind::Sphere);
    CHECK(s.lights[1].position == Vec3{11.0f, 2.0f, 3.0f});
    CHECK(s.lights[1].color == Vec3{4.0f, 2.0f, 1.0f});
    CHECK(s.lights[1].radius == 0.0f);
    CHECK(s.lights[2].position == Vec3{0.0f, 5.0f, 0.0f});
    CHECK(s.lights[2].color == Vec3{1.0f, 1.0f, 1.0f}); // intensity in candela: irradiance at 1 unit
    for (const std::string& warning : warnings) UNSCOPED_INFO(warning);
    REQUIRE(warnings.size() == 1);
    CHECK(warnings[0] == "light 'spot' is a spot light: shaded as a point light, without its cone");
}

TEST_CASE("A missing, unreadable, malformed or triangle-less geometry file is one line naming it",
          "[scene][geometry]") {
    const std::filesystem::path dir = outputDir();
    CHECK(failure(dir / "no_such_model.gltf") == (dir / "no_such_model.gltf").string() + ": no such file");
    std::filesystem::create_directories(dir / "folder.gltf");
    CHECK(failure(dir / "folder.gltf").find("is a folder") != std::string::npos);
    CHECK(failure(writeFile("broken.gltf", "{ this is not json"))
              .find("cannot read as a model: malformed glTF JSON: line 1, column 4: ") != std::string::npos);
    CHECK(failure(writeFile("not_a_model.obj", "this is no model\n")).find("cannot read as a model: ") !=
          std::string::npos);
    CHECK(failure(writeFile("empty.glb", "")).find("cannot read as a model") != std::string::npos);
    const std::string points = std::string(R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],
"nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":{"POSITION":0},"mode":0}]}],
"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],
"bufferViews":[{"buffer":0,"byteLength":36}],
"buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,)") +
                               kTriangle + "\"}]}\n";
    CHECK(failure(writeFile("points.gltf", points)).find("no triangles") != std::string::npos);
    // Binary glTF whose header assimp 5.2.5 would trust (tests/fuzz/third_party_crashes): refused
    // before assimp reads it, here and for a scene file's mesh object.
    const std::filesystem::path crashes =
        std::filesystem::path(GLINT_SOURCE_DIR) / "tests/fuzz/third_party_crashes/gltf";
    for (const char* name : {"assimp-glb-json-chunk-2.1GB.glb", "assimp-glb-json-chunk-1.6GB.glb",
                             "assimp-glb-header-strncmp-overread.glb"}) {
        INFO(name);
        CHECK(failure(crashes / name).find("binary glTF") != std::string::npos);
        Scene s;
        ObjectDesc object;
        object.name = "model";
        object.shape = ShapeKind::Mesh;
        object.file = crashes / name;
        s.objects.push_back(object);
        CHECK_THROWS_AS(loadMeshes(s), SceneError);
    }
}
