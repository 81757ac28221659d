// glint info: what a capture holds — layers, sizes, camera, conventions, effects and
// non-finite pixel counts — for one frame file or every frame of a sequence folder.
#include "cli_commands.h"

#include <capture/describe.h>
#include <capture/frame_io.h>
#include <capture/sequence_io.h>

#include <cstdio>
#include <filesystem>

namespace glint::cli {
namespace {

// Non-finite pixels are legal input (they are counted, and every pass must cope), so they
// are reported but do not fail the command.
void printFrame(const std::filesystem::path& file, bool loadPixels) {
    const std::string text = loadPixels ? capture::describe(capture::readFrame(file))
                                        : capture::describe(capture::readFrameHeader(file));
    std::printf("%s:\n%s", file.string().c_str(), text.c_str());
}

} // namespace

int runInfo(const std::string& path, bool loadPixels) {
    const std::filesystem::path target(path);
    if (!std::filesystem::is_directory(target) && target.filename() != capture::kManifestName) {
        printFrame(target, loadPixels);
        return kExitOk;
    }
    const capture::Sequence sequence = capture::readSequence(target);
    std::printf("sequence %s: %zu frames at %.6g fps, %ux%u, environment %s\n",
                sequence.directory.string().c_str(), sequence.frameFiles.size(), sequence.frameRate,
                sequence.headers.empty() ? 0u : sequence.headers.front().width,
                sequence.headers.empty() ? 0u : sequence.headers.front().height,
                sequence.environment.empty() ? "none" : sequence.environment.c_str());
    for (const std::string& frame : sequence.frameFiles) printFrame(sequence.directory / frame, loadPixels);
    return kExitOk;
}

} // namespace glint::cli
