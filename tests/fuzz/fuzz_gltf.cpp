// Fuzz target "gltf": the bytes are the model file of a scene's mesh object, loaded through
// assimp as the simulator loads it (scene::loadMeshes). A file starting with the binary
// glTF magic is written as model.glb, anything else as model.gltf (assimp picks its importer
// by extension and content). Every rejection must be a scene::SceneError.
#include "fuzz_support.h"

#include <scene/scene_file.h>
#include <scene/scene_geometry.h>

#include <cstring>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace glint;
    const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    const std::filesystem::path file = fuzz::scratchDir() / (binary ? "model.glb" : "model.gltf");
    fuzz::writeBytes(file, data, size);
    scene::Scene s;
    scene::ObjectDesc object;
    object.name = "model";
    object.shape = scene::ShapeKind::Mesh;
    object.file = file;
    s.objects.push_back(object);
    try {
        (void)scene::loadMeshes(s);
    } catch (const scene::SceneError&) {
    }
    return 0;
}
