// glint info: what a capture holds — layers, sizes, camera, conventions, effects and
// non-finite pixel counts — for one frame file or every frame of a sequence folder; with
// --map, the frames of a foreign capture as the channel map turns them into glint frames.
#include "cli_capture.h"
#include "cli_commands.h"

#include <CLI/CLI.hpp>

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

// A mapped frame exists only once converted, so its pixels are always read; --header-only
// leaves out the non-finite counts.
int printMapped(const std::string& path, const std::string& mapPath, bool loadPixels) {
    const CaptureSource source(path, mapPath);
    const capture::Frame first = source.frame(0);
    std::printf("mapped capture %s through %s: %zu frames, %ux%u, environment %s\n", path.c_str(),
                mapPath.c_str(), source.frameCount(), first.width, first.height,
                source.environmentName().c_str());
    for (std::size_t index = 0; index < source.frameCount(); ++index) {
        const capture::Frame frame = index == 0 ? first : source.frame(index);
        const std::string text =
            loadPixels ? capture::describe(frame) : capture::describe(capture::headerOf(frame));
        std::printf("%s:\n%s", source.framePath(index).c_str(), text.c_str());
    }
    return kExitOk;
}

} // namespace

void addInfoOptions(CLI::App& command, InfoOptions& options) {
    command
        .add_option("capture", options.path,
                    "frame file, sequence folder, or with --map one foreign EXR or a folder of them")
        ->required();
    command.add_option("--map", options.mapPath, "channel map of a foreign capture (docs/replay.md)");
    command.add_flag("--header-only", options.headerOnly,
                     "read headers only; skip pixels and non-finite counts");
}

int runInfo(InfoOptions options, bool) {
    const std::string& path = options.path;
    const std::string& mapPath = options.mapPath;
    const bool loadPixels = !options.headerOnly;
    if (!mapPath.empty()) return printMapped(path, mapPath, loadPixels);
    const std::filesystem::path target(path);
    if (!std::filesystem::is_directory(target) && target.filename() != capture::kManifestName) {
        printFrame(target, loadPixels);
        return kExitOk;
    }
    if (std::filesystem::is_directory(target)) requireManifest(target);
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
