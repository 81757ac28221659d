// glint_make_blender_sample <out-dir>: Blender-style renders of the sample frames for the CLI
// tests (tests/capture/blender_capture.h): <out-dir>/blender (0001.exr, 0002.exr and
// camera.json, without the Diffuse Color pass or a world) and <out-dir>/blender_full (with the
// Diffuse Color pass and world.exr).
#include "capture/blender_capture.h"

#include <cstdio>
#include <exception>
#include <filesystem>

int main(int argc, char** argv) {
    using namespace glint::capture;
    if (argc != 2) {
        std::fprintf(stderr, "usage: glint_make_blender_sample <out-dir>\n");
        return 2;
    }
    try {
        const std::filesystem::path out(argv[1]);
        test::writeBlenderCapture(out / "blender");
        test::writeBlenderCapture(out / "blender_full", {.roughness = true, .diffuseColor = true});
        test::writeBlenderWorld(out / "blender_full" / "world.exr", 64, 32);
        std::printf("wrote %s and %s\n", (out / "blender").string().c_str(),
                    (out / "blender_full").string().c_str());
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "glint_make_blender_sample: %s\n", e.what());
        return 1;
    }
}
