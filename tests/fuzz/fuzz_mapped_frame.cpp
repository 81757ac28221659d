// Fuzz target "mapped_frame": the bytes are a foreign OpenEXR frame (0002.exr, after a valid
// 0001.exr and with camera.json beside it), read through the bundled Blender map (camera
// from the side file) and through a map taking the camera from the frame's own header.
// Every rejection must be a capture::CaptureError.
#include "fuzz_support.h"

#include <capture/capture_error.h>
#include <capture/channel_map.h>

namespace {
struct Fixture {
    std::filesystem::path dir;
    glint::capture::ChannelMap blender, header;
};

const Fixture& fixture() {
    static const Fixture f = [] {
        using namespace glint;
        Fixture made;
        made.dir = fuzz::scratchDir() / "capture";
        fuzz::writeBlenderCapture(made.dir);
        made.blender = capture::loadChannelMap(fuzz::blenderMapPath());
        const std::filesystem::path headerMap = fuzz::scratchDir() / "header_camera.toml";
        fuzz::writeText(headerMap, fuzz::headerCameraMap());
        made.header = capture::loadChannelMap(headerMap.string());
        return made;
    }();
    return f;
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace glint;
    const Fixture& f = fixture();
    const std::filesystem::path frame = f.dir / "0002.exr";
    fuzz::writeBytes(frame, data, size);
    for (const capture::ChannelMap* map : {&f.blender, &f.header}) {
        try {
            (void)capture::readMappedFrame(frame.string(), *map, 1);
        } catch (const capture::CaptureError&) {
        }
    }
    return 0;
}
