// Fuzz target "scene": the bytes are a scene file (TOML, docs/scenes.md), parsed as
// `glint simulate` parses it (scene::parseScene; relative paths resolve in a scratch
// folder). Every rejection must be a scene::SceneError.
#include "fuzz_support.h"

#include <scene/scene_file.h>

#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace glint;
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        (void)scene::parseScene(text, fuzz::scratchDir() / "scene.toml");
    } catch (const scene::SceneError&) {
    }
    return 0;
}
