#include "cli_images.h"

#include "replay/replay_frame.h"

#include <glint/glint_effect.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace glint::cli {
namespace {

// Whether `output` is `pattern`, or `pattern` followed by digits (a mip level).
bool outputMatches(const std::string& output, const std::string& pattern) {
    if (output.compare(0, pattern.size(), pattern) != 0) return false;
    return std::all_of(output.begin() + static_cast<std::ptrdiff_t>(pattern.size()), output.end(),
                       [](char c) { return c >= '0' && c <= '9'; });
}

// The range of the finite samples (for depth and pyramid levels, whose interesting span is
// narrow); [0, 1] when there are none or they are all equal.
report::Linear finiteRange(const report::Image& image) {
    float low = INFINITY, high = -INFINITY;
    for (float v : image.pixels)
        if (std::isfinite(v)) {
            low = std::min(low, v);
            high = std::max(high, v);
        }
    if (!(low < high)) return {0.0f, 1.0f};
    return {low, high};
}

// The 99th percentile of the finite samples, so that a few outliers do not flatten a heat map.
float percentile99(const report::Image& image) {
    std::vector<float> values;
    for (float v : image.pixels)
        if (std::isfinite(v)) values.push_back(std::abs(v));
    if (values.empty()) return 1.0f;
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(values.size() * 99 / 100),
                     values.end());
    const float value = values[values.size() * 99 / 100];
    return value > 0.0f ? value : 1.0f;
}

} // namespace

report::PngMapping previewMapping(const std::string& name, const report::Image& image) {
    const std::size_t slash = name.find('/');
    const EffectDescriptor* effect = slash == std::string::npos ? nullptr : findEffect(name.substr(0, slash));
    const std::string output = slash == std::string::npos ? name : name.substr(slash + 1);
    // The images glint run adds to an effect's outputs: its error mask and its error map.
    if (output == "mask" && effect && !effect->evaluation.scored.empty()) return report::Categories{};
    if (output == "error" && effect && !effect->evaluation.scored.empty())
        return report::Heat{effect->evaluation.scored.front().errorHeatScale};
    const OutputPreview* preview = nullptr;
    if (effect)
        for (const OutputPreview& row : effect->evaluation.previews)
            if (!preview && outputMatches(output, row.output)) preview = &row;
    switch (preview ? preview->preview : Preview::Colour) {
    case Preview::Categories:
        return report::Categories{};
    case Preview::Heat:
        return report::Heat{preview->scale};
    case Preview::HeatPercentile99:
        return report::Heat{percentile99(image)};
    case Preview::FiniteRange:
        return finiteRange(image);
    case Preview::Colour:
        break;
    }
    if (image.channels >= 3) return report::Tonemap{1.0f};
    return report::Linear{0.0f, 1.0f};
}

std::vector<std::string> exrChannels(const report::Image& image) {
    switch (image.channels) {
    case 1:
        return {"Y"};
    case 2:
        return {"X", "Y"};
    case 3:
        return {"R", "G", "B"};
    default:
        return {"R", "G", "B", "A"};
    }
}

std::filesystem::path writeImageFiles(const std::filesystem::path& dir, const std::string& stem,
                                      const std::string& name, const report::Image& image, bool png) {
    std::filesystem::create_directories(dir);
    report::writeExr((dir / (stem + ".exr")).string(), image, exrChannels(image));
    if (!png) return {};
    const std::filesystem::path path = dir / (stem + ".png");
    report::writePng(path.string(), image, previewMapping(name, image));
    return path;
}

report::Image referenceImage(const capture::Frame& frame, const std::string& effect) {
    const EffectDescriptor* descriptor = findEffect(effect);
    const std::string name = "reference." + (descriptor ? std::string(descriptor->reference) : effect);
    const capture::Layer* layer = capture::findLayer(frame, name);
    if (!layer) throw std::runtime_error("the second reference has no " + name + " layer");
    const auto channels = static_cast<std::uint32_t>(std::min<std::size_t>(layer->channels.size(), 3));
    return {frame.width, frame.height, channels, replay::layerChannels(frame, name, channels)};
}

report::Image maskImage(const capture::Frame& frame, const std::vector<std::uint8_t>& mask) {
    report::Image image{frame.width, frame.height, 1, std::vector<float>(mask.size(), 0.0f)};
    for (std::size_t i = 0; i < mask.size(); ++i) image.pixels[i] = mask[i] ? 1.0f : 0.0f;
    return image;
}

} // namespace glint::cli
