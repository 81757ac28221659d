// glint_make_sample <out-dir>: writes the bundled sample sequence to <out-dir>/sample
// (two 64x48 frames, an environment map and manifest.json). Generated, never committed.
#include "capture/capture_error.h"
#include "capture/sample_frame.h"
#include "capture/sequence_io.h"

#include <cstdio>
#include <exception>
#include <vector>

int main(int argc, char** argv) {
    using namespace glint::capture;
    if (argc != 2) {
        std::fprintf(stderr, "usage: glint_make_sample <out-dir>\n");
        return 2;
    }
    try {
        const std::vector<Frame> frames{makeSampleFrame(64, 48, 0), makeSampleFrame(64, 48, 1)};
        const Environment environment = makeSampleEnvironment(64, 32);
        const std::filesystem::path out = std::filesystem::path(argv[1]) / "sample";
        writeSequence(out, frames, 30.0, &environment);
        std::printf("wrote %s\n", out.string().c_str());
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "glint_make_sample: %s\n", e.what());
        return 1;
    }
}
