// glint_export_geometry <scene.toml> <out.gltf>: the scene's geometry at frame 0 as glTF 2.0
// (tests/scene/scene_gltf_export.h), for the CLI tests of glint run --geometry.
#include "scene/scene_gltf_export.h"

#include <scene/scene_file.h>

#include <cstdio>
#include <exception>
#include <fstream>

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: glint_export_geometry <scene.toml> <out.gltf>\n");
        return 2;
    }
    try {
        const std::string gltf = glint::test::sceneAsGltf(glint::scene::loadScene(argv[1]));
        std::ofstream out(argv[2], std::ios::binary);
        out << gltf;
        if (!out.flush()) throw std::runtime_error(std::string(argv[2]) + ": cannot write");
        std::printf("wrote %s\n", argv[2]);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "glint_export_geometry: %s\n", e.what());
        return 1;
    }
}
