// Reading and writing one frame capture file (format v1, docs/capture-format.md).
//
// Every failure is a CaptureError whose what() is one line "<file>: <problem>"; malformed
// files never crash, hang or allocate more than the limits in frame_validation.h allow.
#pragma once

#include "capture/capture_frame.h"

#include <filesystem>

namespace glint::capture {

// Reads and validates the whole frame. Samples are returned as float whatever their file
// type; non-finite samples are kept and counted per layer (Layer::nonFinite); the motion
// layer is converted to convention A (motion_convention.h), so frame.motion is kConventionA.
Frame readFrame(const std::filesystem::path& file);

// Reads and validates the header only (no pixel data): layers, camera, conventions, effects.
// The motion convention is reported as declared in the file.
FrameHeader readFrameHeader(const std::filesystem::path& file);

// Everything readFrame checks before it reads pixels: the header as readFrameHeader checks it,
// and that the file is large enough for the pixel data the header declares. Cheap (no pixels
// are read or allocated), so a replay can check every frame before it writes anything.
FrameHeader checkFrameFile(const std::filesystem::path& file);

// Validates (checkFrame) and writes one single-part scanline file with ZIP compression.
// Each layer is stored as its Layer::storage says; depth and motion must be Float. The file
// appears under its final name only once complete.
void writeFrame(const std::filesystem::path& file, const Frame& frame);

} // namespace glint::capture
