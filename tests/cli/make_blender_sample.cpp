// glint_make_blender_sample <out-dir>: Blender-style renders of the sample frames for the CLI
// tests (tests/capture/blender_capture.h): <out-dir>/blender (0001.exr, 0002.exr and
// camera.json, without the Diffuse Color pass or a world) and <out-dir>/blender_full (with the
// Diffuse Color pass and world.exr) and <out-dir>/blender_plain (the frames with a plain camera
// JSON, plain_camera.json: view, OpenGL projection, near and far per frame, no camera.json; the
// input of docs/replay.md's recipe, "From a camera JSON you already have").
#include "capture/blender_capture.h"

#include <capture/sample_frame.h>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>

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
        const std::filesystem::path plain = out / "blender_plain";
        std::filesystem::create_directories(plain);
        nlohmann::json frames = nlohmann::json::array();
        for (std::uint32_t i = 0; i < 2; ++i) {
            const char* name = i == 0 ? "0001.exr" : "0002.exr";
            test::writeBlenderFrame(plain, name, i);
            const Camera c = sampleCamera(test::kForeignWidth, test::kForeignHeight, i);
            frames.push_back({{"file", name},
                              {"view", test::jsonRows(test::blenderView(c.view))},
                              {"projection", test::jsonRows(test::openGlProjection(c))},
                              {"near", c.nearZ},
                              {"far", c.farZ}});
        }
        std::ofstream(plain / "plain_camera.json") << nlohmann::json{{"frames", frames}}.dump(1);
        std::printf("wrote %s and %s\n", (out / "blender").string().c_str(),
                    (out / "blender_full").string().c_str());
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "glint_make_blender_sample: %s\n", e.what());
        return 1;
    }
}
