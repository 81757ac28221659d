// Fuzz target "frame": the bytes are one OpenEXR file, read as a frame capture (readFrame,
// then describe it as `glint info` does) and as an environment map (readEnvironment). Every
// rejection must be a capture::CaptureError.
#include "fuzz_support.h"

#include <capture/capture_error.h>
#include <capture/describe.h>
#include <capture/environment_io.h>
#include <capture/frame_io.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace glint;
    const std::filesystem::path file = fuzz::scratchDir() / "frame.exr";
    fuzz::writeBytes(file, data, size);
    try {
        const capture::Frame frame = capture::readFrame(file);
        (void)capture::describe(frame);
    } catch (const capture::CaptureError&) {
    }
    try {
        (void)capture::readEnvironment(file);
    } catch (const capture::CaptureError&) {
    }
    return 0;
}
