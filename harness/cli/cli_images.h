// Writing a replayed image as EXR (the data) and PNG (a preview whose mapping suits what the
// image holds: tone-mapped colour, grey scalars, heat maps, category colours).
#pragma once

#include "capture/capture_frame.h"
#include "replay/replay_session.h"
#include "report/report_image.h"

#include <filesystem>
#include <string>

namespace glint::cli {

// The preview mapping for an image by its name "<effect>/<output>": the effect's evaluation's
// (OutputPreview, glint_effect.h; a scored effect's "error" a heat map to its errorHeatScale and
// its "mask" categories), else tone-mapped colour for 3 or more channels and grey over [0, 1].
report::PngMapping previewMapping(const std::string& name, const report::Image& image);

// Channel names of the EXR: R,G,B(,A) for colour, Y for one channel, X,Y for two.
std::vector<std::string> exrChannels(const report::Image& image);

// Writes <dir>/<stem>.exr and, when `png`, <dir>/<stem>.png. Returns the PNG's path (empty
// without one).
std::filesystem::path writeImageFiles(const std::filesystem::path& dir, const std::string& stem,
                                      const std::string& name, const report::Image& image, bool png);

// The reference layer of `frame` for `effect` ("reference.reflection" for reflections) as an
// image of at most 3 channels, for writing it out. Throws std::runtime_error naming the layer
// when the frame lacks it.
report::Image referenceImage(const capture::Frame& frame, const std::string& effect);

// An error mask (replay::errorMask: 1 inside, 0 outside) as a one-channel image.
report::Image maskImage(const capture::Frame& frame, const std::vector<std::uint8_t>& mask);

} // namespace glint::cli
