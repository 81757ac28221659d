// Shared by the libFuzzer targets (docs/robustness.md) and the corpus generator: a private
// scratch folder per process, byte files written into it, and the fixed files a target
// reads next to its fuzzed one (a small sample sequence, Blender-style frames, a camera
// side file).
//
// The readers take paths, so every target writes its input to a file and calls the reader
// exactly as `glint` does. A target catches only the error type its reader documents
// (capture::CaptureError, scene::SceneError); anything else escaping is a bug and reaches
// libFuzzer as a crash.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace glint::fuzz {

// $TMPDIR/glint-fuzz-XXXXXX, created on first use and removed at exit.
const std::filesystem::path& scratchDir();

void writeBytes(const std::filesystem::path& file, const std::uint8_t* data, std::size_t size);
void writeText(const std::filesystem::path& file, std::string_view text);

// A valid two-frame sample sequence (16x12 frames, 16x8 environment, manifest.json) in `dir`.
void writeSampleSequence(const std::filesystem::path& dir);

// Blender-style multilayer frames 0001.exr and 0002.exr (the channel names of
// harness/maps/blender.toml, 16x12) with camera.json beside them, in `dir`.
void writeBlenderCapture(const std::filesystem::path& dir);
inline constexpr std::uint32_t kBlenderWidth = 16, kBlenderHeight = 12;
// The camera.json writeBlenderCapture writes.
std::string blenderCameraJson();

// The bundled Blender map (harness/maps/blender.toml of the source tree).
std::string blenderMapPath();

// A map reading the same frames with the camera from their OpenEXR headers
// (camera.source = "header", view from the standard worldToCamera attribute).
std::string headerCameraMap();

} // namespace glint::fuzz
