// Fuzz target "camera_file": the bytes are the camera side file (camera.json, docs/replay.md)
// of a folder of two Blender-style frames, read through the bundled Blender map for each
// frame (capture::mappedCamera, as readMappedFrame does). Every rejection must be a
// capture::CaptureError.
#include "fuzz_support.h"

#include <capture/capture_error.h>
#include <capture/channel_map.h>

namespace {
struct Fixture {
    std::filesystem::path dir;
    glint::capture::ChannelMap map;
};

const Fixture& fixture() {
    static const Fixture f = [] {
        using namespace glint;
        Fixture made;
        made.dir = fuzz::scratchDir() / "capture";
        fuzz::writeBlenderCapture(made.dir);
        made.map = capture::loadChannelMap(fuzz::blenderMapPath());
        return made;
    }();
    return f;
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace glint;
    const Fixture& f = fixture();
    fuzz::writeBytes(f.dir / "camera.json", data, size);
    for (const char* name : {"0001.exr", "0002.exr"}) {
        try {
            (void)capture::mappedCamera((f.dir / name).string(), f.map, fuzz::kBlenderWidth,
                                        fuzz::kBlenderHeight);
        } catch (const capture::CaptureError&) {
        }
    }
    return 0;
}
