#include "capture/frame_validation.h"

#include "capture/enum_names.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>

namespace glint::capture {

namespace {
constexpr std::array<std::string_view, 4> kEffects{"reflections", "hybrid", "shadows", "depth_pyramid"};

// Appends rather than "'" + s + "'": GCC 12 at -O3 reports a false -Wrestrict (GCC bug
// 105329) on operator+(const char*, std::string&&).
std::string quoted(std::string_view s) {
    std::string out;
    out.reserve(s.size() + 2);
    out.append(1, '\'').append(s).append(1, '\'');
    return out;
}

std::string number(double v) {
    char text[40];
    std::snprintf(text, sizeof(text), "%.9g", v);
    return text;
}

std::vector<std::string> normalChannels(NormalEncoding encoding) {
    if (encoding == NormalEncoding::Octahedral) return {"X", "Y"};
    return {"X", "Y", "Z"};
}

// The channels a known layer must have whenever it is present.
std::vector<std::string> requiredChannels(std::string_view layer, NormalEncoding encoding) {
    if (layer == "color") return {"R", "G", "B"};
    if (layer == "depth") return {"Z"};
    if (layer == "normal") return normalChannels(encoding);
    if (layer == "motion") return {"X", "Y"};
    if (layer == "shadow") return {"Y"};
    return {};
}

std::vector<std::string> layersFor(std::string_view effect) {
    if (effect == "reflections" || effect == "hybrid") return {"color", "depth", "normal", "motion"};
    if (effect == "shadows") return {"depth", "normal", "motion", "shadow"};
    return {"depth"};
}

std::optional<std::string> checkLayerShapes(const FrameHeader& h) {
    std::set<std::string, std::less<>> names;
    std::size_t totalChannels = 0;
    for (const LayerInfo& layer : h.layers) {
        if (layer.name.empty()) return "a layer has an empty name (every channel must be <layer>.<channel>)";
        if (!names.insert(layer.name).second) return "layer " + quoted(layer.name) + " appears twice";
        if (layer.channels.empty()) return "layer " + quoted(layer.name) + " has no channels";
        std::set<std::string, std::less<>> channels;
        for (const std::string& c : layer.channels) {
            if (c.empty() || c.find('.') != std::string::npos)
                return "layer " + quoted(layer.name) + " has an invalid channel name " + quoted(c);
            if (!channels.insert(c).second)
                return "layer " + quoted(layer.name) + " has channel " + quoted(c) + " twice";
        }
        totalChannels += layer.channels.size();
        for (const std::string& c : requiredChannels(layer.name, h.normalEncoding)) {
            if (channelIndex(layer.channels, c) < 0)
                return "layer " + quoted(layer.name) + " lacks channel " + quoted(c);
        }
        if ((layer.name == "depth" || layer.name == "motion") && layer.storage != SampleType::Float)
            return "layer " + quoted(layer.name) + " is stored as " + std::string(toString(layer.storage)) +
                   "; depth and motion must be FLOAT";
    }
    if (totalChannels > kMaxChannels)
        return std::to_string(totalChannels) + " channels exceed the limit of " +
               std::to_string(kMaxChannels);
    const std::uint64_t samples = std::uint64_t{h.width} * h.height * totalChannels;
    if (samples > kMaxSamples)
        return std::to_string(samples) + " samples exceed the limit of " + std::to_string(kMaxSamples);
    return std::nullopt;
}

std::optional<std::string> checkRoughness(const FrameHeader& h, bool required) {
    const RoughnessSource& r = h.roughness;
    if (r.layer.empty() && r.channel.empty()) {
        if (required)
            return "no roughness source declared (glint.roughnessSource) but the reflection effects need one";
        return std::nullopt;
    }
    if (r.layer.empty() || r.channel.empty())
        return "roughness source " + quoted(r.layer + "." + r.channel) + " is not <layer>.<channel>";
    if (!required) return std::nullopt;
    const LayerInfo* layer = findLayer(h, r.layer);
    if (!layer)
        return "missing layer " + quoted(r.layer) + " (roughness source) required by the reflection effects";
    if (channelIndex(layer->channels, r.channel) < 0)
        return "layer " + quoted(r.layer) + " lacks channel " + quoted(r.channel) + " (roughness source)";
    return std::nullopt;
}
} // namespace

bool isKnownEffect(std::string_view effect) {
    for (std::string_view e : kEffects)
        if (e == effect) return true;
    return false;
}

std::optional<std::string> checkDimensions(std::uint64_t width, std::uint64_t height) {
    if (width == 0 || height == 0)
        return "image is empty (" + std::to_string(width) + "x" + std::to_string(height) + ")";
    if (width > kMaxDimension || height > kMaxDimension || width * height > kMaxPixels)
        return "image size " + std::to_string(width) + "x" + std::to_string(height) + " exceeds the limit (" +
               std::to_string(kMaxDimension) + " per side, " + std::to_string(kMaxPixels) + " pixels)";
    return std::nullopt;
}

std::optional<std::string> checkCamera(const Camera& c) {
    if (!isFinite(c.view)) return "camera view matrix is not finite";
    if (!isFinite(c.projection)) return "camera projection matrix is not finite";
    if (!isFinite(c.prevViewProjection)) return "camera previous view-projection matrix is not finite";
    if (!inverse(c.projection)) return "camera projection matrix is singular";
    if (!inverse(c.view)) return "camera view matrix is singular";
    if (!std::isfinite(c.nearZ) || !(c.nearZ > 0.0))
        return "camera near plane " + number(c.nearZ) + " is not a positive finite number";
    const bool infinite = c.depth == DepthConvention::ReversedInfinite;
    const double inf = std::numeric_limits<double>::infinity();
    if (infinite && c.farZ != inf)
        return "camera far plane must be +inf for depth convention reversed_infinite";
    if (!infinite && !(std::isfinite(c.farZ) && c.farZ > c.nearZ))
        return "camera far plane " + number(c.farZ) + " is not a finite number greater than near";
    return std::nullopt;
}

std::optional<std::string> checkHeader(const FrameHeader& h) {
    if (h.formatVersion != kFormatVersion)
        return "unsupported format version " + std::to_string(h.formatVersion) +
               " (this reader knows version " + std::to_string(kFormatVersion) + ")";
    if (auto p = checkDimensions(h.width, h.height)) return p;
    if (h.frameIndex > static_cast<std::uint32_t>(std::numeric_limits<int>::max()))
        return "frame index " + std::to_string(h.frameIndex) + " does not fit the file's int attribute";
    if (auto p = checkCamera(h.camera)) return p;
    if (auto p = checkLayerShapes(h)) return p;
    bool needsRoughness = false;
    std::set<std::string, std::less<>> seen;
    for (const std::string& effect : h.effects) {
        if (!isKnownEffect(effect))
            return "unknown effect " + quoted(effect) +
                   " (known: reflections, hybrid, shadows, depth_pyramid)";
        if (!seen.insert(effect).second) return "effect " + quoted(effect) + " is declared twice";
        needsRoughness = needsRoughness || effect == "reflections" || effect == "hybrid";
        for (const std::string& layer : layersFor(effect)) {
            if (!findLayer(h, layer))
                return "missing layer " + quoted(layer) + " required by effect " + quoted(effect);
        }
    }
    return checkRoughness(h, needsRoughness);
}

std::optional<std::string> checkFrame(const Frame& frame) {
    if (auto p = checkHeader(headerOf(frame))) return p;
    const std::size_t pixels = std::size_t{frame.width} * frame.height;
    for (const Layer& layer : frame.layers) {
        if (layer.pixels.size() != pixels * layer.channels.size())
            return "layer " + quoted(layer.name) + " holds " + std::to_string(layer.pixels.size()) +
                   " samples, expected " + std::to_string(pixels * layer.channels.size()) + " (" +
                   std::to_string(frame.width) + "x" + std::to_string(frame.height) + "x" +
                   std::to_string(layer.channels.size()) + ")";
    }
    return std::nullopt;
}

} // namespace glint::capture
