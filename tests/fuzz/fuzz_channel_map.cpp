// Fuzz target "channel_map": the bytes are a channel map (TOML, docs/replay.md). A map
// that loads is then used as `glint run --map` would: the frames of a folder of two
// Blender-style frames with camera.json, each frame read and its camera built. Every
// rejection must be a capture::CaptureError.
#include "fuzz_support.h"

#include <capture/capture_error.h>
#include <capture/channel_map.h>

namespace {
const std::filesystem::path& captureDir() {
    static const std::filesystem::path dir = [] {
        const std::filesystem::path d = glint::fuzz::scratchDir() / "capture";
        glint::fuzz::writeBlenderCapture(d);
        return d;
    }();
    return dir;
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace glint;
    const std::filesystem::path& dir = captureDir();
    const std::filesystem::path map = fuzz::scratchDir() / "map.toml";
    fuzz::writeBytes(map, data, size);
    try {
        const capture::ChannelMap loaded = capture::loadChannelMap(map.string());
        const std::vector<std::string> frames = capture::mappedSequenceFiles(dir.string(), loaded);
        for (std::size_t i = 0; i < frames.size() && i < 2; ++i)
            (void)capture::readMappedFrame(frames[i], loaded, static_cast<std::uint32_t>(i));
        (void)capture::loadMappedEnvironment(loaded, dir.string());
    } catch (const capture::CaptureError&) {
    }
    return 0;
}
