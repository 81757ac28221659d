#include "capture/exr_layers.h"

#include "capture/capture_error.h"

#include <algorithm>
#include <array>
#include <string_view>

namespace glint::capture {

namespace {
std::size_t channelRank(std::string_view c) {
    constexpr std::array<std::string_view, 8> kOrder{"R", "G", "B", "A", "X", "Y", "Z", "W"};
    for (std::size_t i = 0; i < kOrder.size(); ++i)
        if (kOrder[i] == c) return i;
    return kOrder.size();
}

// Known layers first, in the order a reader of `glint info` expects, then extra layers,
// then references; names within a group sort alphabetically.
std::size_t layerRank(std::string_view name) {
    constexpr std::array<std::string_view, 7> kOrder{"color",    "depth",  "normal", "roughness",
                                                     "material", "motion", "shadow"};
    for (std::size_t i = 0; i < kOrder.size(); ++i)
        if (kOrder[i] == name) return i;
    return name.rfind("reference.", 0) == 0 ? kOrder.size() + 1 : kOrder.size();
}

std::string_view typeName(Imf::PixelType t) {
    switch (t) {
    case Imf::UINT:
        return "UINT";
    case Imf::HALF:
        return "HALF";
    case Imf::FLOAT:
        return "FLOAT";
    default:
        return "an unknown type";
    }
}
} // namespace

std::string exrChannelName(const std::string& layer, const std::string& channel) {
    return layer + "." + channel;
}

std::vector<LayerInfo> layersFromChannels(const Imf::ChannelList& channels,
                                          const std::filesystem::path& file) {
    std::vector<LayerInfo> layers;
    for (auto it = channels.begin(); it != channels.end(); ++it) {
        const std::string full = it.name();
        const Imf::Channel& ch = it.channel();
        const std::size_t dot = full.rfind('.');
        if (dot == std::string::npos || dot == 0 || dot + 1 == full.size())
            fail(file, "channel '" + full + "' is not named <layer>.<channel>");
        if (ch.type != Imf::HALF && ch.type != Imf::FLOAT)
            fail(file, "channel '" + full + "' has type " + std::string(typeName(ch.type)) +
                           "; capture channels must be HALF or FLOAT");
        if (ch.xSampling != 1 || ch.ySampling != 1)
            fail(file, "channel '" + full + "' is subsampled (" + std::to_string(ch.xSampling) + "x" +
                           std::to_string(ch.ySampling) +
                           "); capture channels must have one sample per pixel");
        const std::string layerName = full.substr(0, dot);
        const SampleType storage = ch.type == Imf::HALF ? SampleType::Half : SampleType::Float;
        auto layer = std::find_if(layers.begin(), layers.end(),
                                  [&](const LayerInfo& l) { return l.name == layerName; });
        if (layer == layers.end()) {
            layers.push_back({layerName, {}, storage});
            layer = layers.end() - 1;
        } else if (layer->storage != storage) {
            fail(file, "layer '" + layerName + "' mixes HALF and FLOAT channels");
        }
        layer->channels.push_back(full.substr(dot + 1));
    }
    for (LayerInfo& layer : layers) {
        std::stable_sort(
            layer.channels.begin(), layer.channels.end(), [](const std::string& a, const std::string& b) {
                return channelRank(a) < channelRank(b) || (channelRank(a) == channelRank(b) && a < b);
            });
    }
    std::stable_sort(layers.begin(), layers.end(), [](const LayerInfo& a, const LayerInfo& b) {
        return layerRank(a.name) < layerRank(b.name) ||
               (layerRank(a.name) == layerRank(b.name) && a.name < b.name);
    });
    return layers;
}

} // namespace glint::capture
