// Capture frame -> what every effect reads (glint_effect.h): the frame's camera, depth
// convention and G-buffer encoding as a FrameInfo, and each application input by what it
// holds: normals decoded to unit world vectors, roughness from the declared source into
// channel 0, motion converted to convention A, the environment as an RGBA lat-long map
// (docs/capture-format.md, docs/conventions.md).
#pragma once

#include "capture/capture_frame.h"
#include "capture/environment_io.h"

#include "glint/glint_effect.h"

#include <string>
#include <vector>

namespace glint::replay {

// `index` is the frame's position in the replayed run; `reset` drops every history (first
// frame, camera cut). The environment gives the solid angle and mip count of its texels.
FrameInfo frameInfo(const capture::Frame& frame, const capture::Environment& environment, std::uint32_t index,
                    bool reset);

// A static camera: last frame's view-projection becomes this frame's (benchmarks that repeat a
// frame).
void holdCamera(FrameInfo& info);

// The texels of `kind` (not Environment or PreviousDepth), `channels` floats each. Throws
// std::runtime_error naming the missing layer.
std::vector<float> inputTexels(const capture::Frame& frame, InputKind kind, std::uint32_t& channels);

// The environment as RGBA level 0, or throws for a layout the replay does not read.
std::vector<float> environmentTexels(const capture::Environment& environment);

// Interleaved copy of a layer's first `channels` channels (missing ones 0), or throws.
std::vector<float> layerChannels(const capture::Frame& frame, const std::string& name, std::size_t channels);

// The capture layer an input kind comes from ("" for the environment and previous depth).
std::string inputLayer(const capture::Frame& frame, InputKind kind);

} // namespace glint::replay
