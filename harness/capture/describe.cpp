#include "capture/describe.h"

#include "capture/enum_names.h"

#include <cstdio>
#include <string_view>

namespace glint::capture {

namespace {
std::string number(double v) {
    char text[40];
    std::snprintf(text, sizeof(text), "%.9g", v == 0.0 ? 0.0 : v); // no "-0" in matrices
    return text;
}

std::string joined(const std::vector<std::string>& items, std::string_view separator) {
    std::string out;
    for (const std::string& item : items) out += (out.empty() ? "" : std::string(separator)) + item;
    return out;
}

std::string padded(std::string s, std::size_t width) {
    if (s.size() < width) s.append(width - s.size(), ' ');
    return s;
}

std::string effectsLine(const FrameHeader& h) {
    return "effects: " + (h.effects.empty() ? std::string("(none)") : joined(h.effects, ", ")) + "\n";
}

// Everything before the per-layer lines, which differ between a header and a loaded frame.
// The effects come after the layers, whose presence they required.
std::string describeCommon(const FrameHeader& h) {
    const Camera& c = h.camera;
    std::string out;
    out += "format version " + std::to_string(h.formatVersion) + ", frame " + std::to_string(h.frameIndex) +
           ", " + std::to_string(h.width) + "x" + std::to_string(h.height) + "\n";
    out += "depth: " + std::string(toString(c.depth)) + ", near " + number(c.nearZ) + ", far " +
           number(c.farZ) + "\n";
    out += std::string("ndc: ") + (c.ndcYDown ? "+y down (Vulkan-style)" : "+y up (D3D-style)") + "\n";
    out += "view: " + describe(c.view) + "\n";
    out += "projection: " + describe(c.projection) + "\n";
    out += "prevViewProjection: " + describe(c.prevViewProjection) + "\n";
    out += "normals: " + std::string(toString(h.normalEncoding)) + "\n";
    out += "motion: " + std::string(toString(h.motion.units)) + ", scale (" +
           number(static_cast<double>(h.motion.scale.x)) + ", " +
           number(static_cast<double>(h.motion.scale.y)) + ")\n";
    const RoughnessSource& r = h.roughness;
    out += "roughness: " +
           (r.layer.empty()
                ? std::string("(none)")
                : r.layer + "." + r.channel + (r.perceptual ? " (perceptual r)" : " (GGX alpha = r^2)")) +
           "\n";
    return out;
}

std::string layerLine(const LayerInfo& layer, const FrameHeader& h) {
    return "  " + padded(layer.name, 22) + " " + padded(joined(layer.channels, ","), 10) + " " +
           padded(std::string(toString(layer.storage)), 5) + " " + std::to_string(h.width) + "x" +
           std::to_string(h.height) + "x" + std::to_string(layer.channels.size());
}
} // namespace

std::string describe(const Mat4& m) {
    std::string out = "[";
    for (std::size_t i = 0; i < 16; ++i) {
        out += number(m.m[i]);
        if (i == 15) break;
        out += (i % 4 == 3) ? "; " : " ";
    }
    return out + "]";
}

std::string describe(const FrameHeader& header) {
    std::string out = describeCommon(header);
    out += "layers:\n";
    for (const LayerInfo& layer : header.layers) out += layerLine(layer, header) + "\n";
    return out + effectsLine(header);
}

std::string describe(const Frame& frame) {
    const FrameHeader header = headerOf(frame);
    std::string out = describeCommon(header);
    out += "layers:\n";
    for (std::size_t i = 0; i < frame.layers.size(); ++i)
        out += layerLine(header.layers[i], header) + "  non-finite " +
               std::to_string(frame.layers[i].nonFinite) + "\n";
    out += "non-finite samples: " + std::to_string(summarizeNonFinite(frame).total) + "\n";
    return out + effectsLine(header);
}

} // namespace glint::capture
