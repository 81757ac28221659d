// Writing a replayed image as EXR (the data) and PNG (a preview whose mapping suits what the
// image holds: tone-mapped colour, grey scalars, heat maps, category colours).
#pragma once

#include "replay/replay_session.h"
#include "report/report_image.h"

#include <filesystem>
#include <string>

namespace glint::cli {

// The preview mapping for an image by its name ("reflections/ray_class" -> categories, ...).
report::PngMapping previewMapping(const std::string& name, const report::Image& image);

// Channel names of the EXR: R,G,B(,A) for colour, Y for one channel, X,Y for two.
std::vector<std::string> exrChannels(const report::Image& image);

// Writes <dir>/<stem>.exr and, when `png`, <dir>/<stem>.png. Returns the PNG's path (empty
// without one).
std::filesystem::path writeImageFiles(const std::filesystem::path& dir, const std::string& stem,
                                      const std::string& name, const report::Image& image, bool png);

} // namespace glint::cli
