// A capture sequence: a folder holding frame files, an optional environment map and
// manifest.json (docs/capture-format.md, "Sequences"):
//   {"format": "glint-sequence", "version": 1, "frames": ["frame_0000.exr", ...],
//    "frameRate": 30, "environment": "environment.exr"}
#pragma once

#include "capture/capture_frame.h"
#include "capture/environment_io.h"

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace glint::capture {

inline constexpr const char* kManifestName = "manifest.json";

struct Sequence {
    std::filesystem::path directory;
    double frameRate = 30.0;
    std::vector<std::string> frameFiles; // manifest order, relative to directory
    std::vector<FrameHeader> headers;    // one validated header per frame, same order
    std::string environment;             // relative to directory; empty when there is none
    std::string scene; // the scene file the frames were simulated from (glint simulate); empty for others
};

// Reads the manifest (from `path`, a sequence folder or its manifest.json) and the header
// of every frame; pixels stay on disk until loadFrame. Fails on malformed JSON, a wrong
// format/version, a missing or invalid frame, frames of different sizes, a missing
// environment file.
Sequence readSequence(const std::filesystem::path& path);

Frame loadFrame(const Sequence& sequence, std::size_t index); // readFrame of frame `index`
std::optional<Environment> loadEnvironment(const Sequence& sequence);

// Writes frames as frame_0000.exr, frame_0001.exr, ... (numbered by position), the
// environment as environment.exr when given, and manifest.json last, into `directory`
// (created if needed). All frames must have the same size.
// `scene`: the scene file the frames come from, recorded (absolute) so that a replay can rebuild
// the geometry (the hybrid effect's ray tracer).
void writeSequence(const std::filesystem::path& directory, const std::vector<Frame>& frames, double frameRate,
                   const Environment* environment = nullptr, const std::filesystem::path& scene = {});

} // namespace glint::capture
