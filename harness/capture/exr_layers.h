// Channel naming of capture files: every channel is "<layer>.<channel>", where the layer
// name may itself contain dots ("reference.reflection.R") and the channel name is the part
// after the last dot. Internal to the capture library.
#pragma once

#include "capture/capture_frame.h"

#include <OpenEXR/ImfChannelList.h>

#include <filesystem>
#include <string>
#include <vector>

namespace glint::capture {

std::string exrChannelName(const std::string& layer, const std::string& channel);

// Groups the file's channels into layers in canonical order (the file itself keeps channels
// sorted by name only): layers color, depth, normal, roughness, material, motion, shadow,
// then other layers, then reference.* layers, each group alphabetically; channels R,G,B,A,
// then X,Y,Z,W, then the rest alphabetically. Fails with a CaptureError on a channel outside any layer, an
// integer channel, a subsampled channel or a layer that mixes HALF and FLOAT.
std::vector<LayerInfo> layersFromChannels(const Imf::ChannelList& channels,
                                          const std::filesystem::path& file);

} // namespace glint::capture
