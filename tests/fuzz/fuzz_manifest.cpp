// Fuzz target "manifest": the bytes are the manifest.json of a sequence folder that also
// holds two valid 16x12 frames (frame_0000.exr, frame_0001.exr) and environment.exr.
// readSequence, then every frame it lists and its environment are loaded.
#include "fuzz_support.h"

#include <capture/capture_error.h>
#include <capture/sequence_io.h>

namespace {
const std::filesystem::path& sequenceDir() {
    static const std::filesystem::path dir = [] {
        const std::filesystem::path d = glint::fuzz::scratchDir() / "sequence";
        glint::fuzz::writeSampleSequence(d);
        return d;
    }();
    return dir;
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace glint;
    const std::filesystem::path& dir = sequenceDir();
    fuzz::writeBytes(dir / capture::kManifestName, data, size);
    try {
        const capture::Sequence sequence = capture::readSequence(dir);
        for (std::size_t i = 0; i < sequence.frameFiles.size() && i < 4; ++i)
            (void)capture::loadFrame(sequence, i);
        (void)capture::loadEnvironment(sequence);
    } catch (const capture::CaptureError&) {
    }
    return 0;
}
