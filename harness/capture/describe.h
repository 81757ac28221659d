// Human-readable summaries of captures for `glint info`: layers (channels, storage type,
// size), camera matrices, conventions, effects and, for loaded frames, non-finite counts.
// The structured data is FrameHeader / Frame itself; these only format it.
#pragma once

#include "capture/capture_frame.h"

#include <string>

namespace glint::capture {

std::string describe(const FrameHeader& header); // multi-line: header, camera, conventions, layers, effects
std::string describe(const Frame& frame);        // as above plus non-finite counts per layer
std::string describe(const Mat4& m);             // one line: [a b c d; e f g h; ...]

} // namespace glint::capture
