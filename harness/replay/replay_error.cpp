#include "replay/replay_error.h"

#include "replay/replay_frame.h"

#include <glint/glint_effect.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>

namespace glint::replay {
namespace {

float luminance(const float* rgb, std::uint32_t channels) {
    if (channels < 3) return rgb[0];
    return 0.2126f * rgb[0] + 0.7152f * rgb[1] + 0.0722f * rgb[2];
}

bool finitePixel(const float* p, std::uint32_t channels) {
    for (std::uint32_t c = 0; c < channels; ++c)
        if (!std::isfinite(p[c])) return false;
    return true;
}

// Pixels with a surface (finite depth short of the background value).
std::vector<std::uint8_t> surfaceMask(const capture::Frame& frame) {
    const capture::Layer* depth = capture::findLayer(frame, "depth");
    std::vector<std::uint8_t> mask(std::size_t{frame.width} * frame.height, 0);
    if (!depth) return mask;
    const bool reversed = frame.camera.depth != capture::DepthConvention::Standard;
    for (std::size_t i = 0; i < mask.size(); ++i) {
        const float d = depth->pixels[i];
        mask[i] = std::isfinite(d) && (reversed ? d > 1e-6f : d < 1.0f - 1e-6f);
    }
    return mask;
}

// Surface pixels whose GGX alpha is below `threshold`.
std::vector<std::uint8_t> alphaBelowMask(const capture::Frame& frame, float threshold) {
    std::vector<std::uint8_t> mask = surfaceMask(frame);
    const capture::Layer* layer = capture::findLayer(frame, frame.roughness.layer);
    const int channel = layer ? capture::channelIndex(layer->channels, frame.roughness.channel) : -1;
    if (channel < 0) return std::vector<std::uint8_t>(mask.size(), 0);
    const std::size_t stride = layer->channels.size();
    for (std::size_t i = 0; i < mask.size(); ++i) {
        const float r = layer->pixels[i * stride + static_cast<std::size_t>(channel)];
        const float alpha = frame.roughness.perceptual ? r * r : r;
        mask[i] = mask[i] && alpha < threshold;
    }
    return mask;
}

double thresholdOf(const ErrorMask& mask, const SettingValues& settings) {
    return mask.pixels == ErrorMask::Pixels::SurfaceAlphaBelow ? double{settings.real(mask.setting)} : -1.0;
}

ReferenceError compare(const std::string& effect, const NamedImage& output, const report::Image& reference,
                       const std::vector<std::uint8_t>& mask, ErrorMetric metric) {
    const bool relative = metric == ErrorMetric::RelativeLuminance;
    const bool visibility = metric == ErrorMetric::Visibility;
    ReferenceError error;
    error.effect = effect;
    error.image = output.name;
    error.visibility = visibility;
    const report::Image& out = output.image;
    const std::uint32_t channels = std::min(out.channels, reference.channels);
    error.map = report::Image{out.width, out.height, 1,
                              std::vector<float>(std::size_t{out.width} * out.height, 0.0f)};
    double sum = 0.0, squares = 0.0, clampedSum = 0.0, clampedSquares = 0.0, penumbraSum = 0.0;
    std::size_t penumbraCount = 0, nonFinite = 0;
    for (std::size_t i = 0; i < mask.size(); ++i) {
        const float* a = &out.pixels[i * out.channels];
        const float* b = &reference.pixels[i * reference.channels];
        const bool finite = finitePixel(a, channels);
        if (!finite) ++nonFinite;
        if (!mask[i] || !finitePixel(b, channels)) continue;
        float difference[3] = {};
        double pixelSquares = 0.0, pixelClamped = 0.0, pixelClampedSquares = 0.0;
        for (std::uint32_t c = 0; c < std::min(channels, 3u); ++c) {
            difference[c] = finite ? std::abs(a[c] - b[c]) : 0.0f;
            pixelSquares += double{difference[c]} * double{difference[c]};
            // A non-finite output pixel counts as the largest clamped difference.
            const double clamped = finite ? std::abs(std::clamp(double{a[c]}, 0.0, kMaeClamp) -
                                                     std::clamp(double{b[c]}, 0.0, kMaeClamp))
                                          : kMaeClamp;
            pixelClamped += clamped;
            pixelClampedSquares += clamped * clamped;
        }
        float value = luminance(difference, std::min(channels, 3u));
        if (relative) value /= std::max(luminance(b, std::min(channels, 3u)), 0.05f);
        if (!finite) value = 1.0f;
        error.map.pixels[i] = value;
        sum += double{value};
        squares += pixelSquares / std::min(channels, 3u);
        clampedSum += pixelClamped / std::min(channels, 3u);
        clampedSquares += pixelClampedSquares / std::min(channels, 3u);
        ++error.pixels;
        if (visibility && b[0] > 0.05f && b[0] < 0.95f) {
            penumbraSum += double{value};
            ++penumbraCount;
        }
    }
    if (error.pixels > 0) {
        error.mean = sum / static_cast<double>(error.pixels);
        error.rmse = std::sqrt(squares / static_cast<double>(error.pixels));
        error.maeClamped = clampedSum / static_cast<double>(error.pixels);
        error.rmseClamped = std::sqrt(clampedSquares / static_cast<double>(error.pixels));
    }
    if (penumbraCount > 0) error.penumbra = penumbraSum / static_cast<double>(penumbraCount);
    error.nonFinite =
        static_cast<double>(nonFinite) / static_cast<double>(std::max<std::size_t>(1, mask.size()));
    return error;
}

// `previous`'s reference layer for `effect`, one channel (what the moving edges compare), or
// none when it has no such layer.
std::optional<report::Image> previousReference(const capture::Frame& previous, const capture::Frame& frame,
                                               const std::string& effect) {
    if (previous.width != frame.width || previous.height != frame.height)
        throw std::invalid_argument("previous frame: it is " + std::to_string(previous.width) + "x" +
                                    std::to_string(previous.height) + ", the frame " +
                                    std::to_string(frame.width) + "x" + std::to_string(frame.height));
    const EffectDescriptor* descriptor = findEffect(effect);
    if (!descriptor || descriptor->reference.empty()) return std::nullopt;
    const std::string name = "reference." + descriptor->reference;
    if (!capture::findLayer(previous, name)) return std::nullopt;
    return report::Image{previous.width, previous.height, 1, layerChannels(previous, name, 1)};
}

// The moving edges of `error` (an absolute, visibility error): the output's and the noisy
// input's mean over the mask's pixels whose reference moved since `previous`.
void scoreMovingEdges(ReferenceError& error, const NamedImage& output, const NamedImage* noisy,
                      const report::Image& reference, const report::Image& previous,
                      const std::vector<std::uint8_t>& mask) {
    const std::vector<std::uint8_t> moving = movingEdgeMask(reference, previous, mask);
    const ReferenceError edges = compare(error.effect, output, reference, moving, ErrorMetric::Visibility);
    error.movingEdgePixels = edges.pixels;
    if (edges.pixels == 0) return;
    error.movingEdge = edges.mean;
    if (noisy)
        error.noisyMovingEdge =
            compare(error.effect, *noisy, reference, moving, ErrorMetric::Visibility).mean;
}

} // namespace

std::vector<std::uint8_t> errorMask(const capture::Frame& frame, const ErrorMask& mask,
                                    const SettingValues& settings) {
    if (mask.pixels == ErrorMask::Pixels::SurfaceAlphaBelow)
        return alphaBelowMask(frame, settings.real(mask.setting));
    return surfaceMask(frame);
}

const ScoredOutput* scoredOutput(const std::string& effect) {
    const EffectDescriptor* descriptor = findEffect(effect);
    if (!descriptor || descriptor->evaluation.scored.empty()) return nullptr;
    return &descriptor->evaluation.scored.front();
}

namespace {

// The output `scored` scores in `result` (the first of its `final` images there) and its noisy
// input (null without one, or when it is the output itself).
std::pair<const NamedImage*, const NamedImage*>
scoredImages(const FrameResult& result, const std::string& effect, const ScoredOutput& scored) {
    const NamedImage* output = nullptr;
    for (const std::string& name : scored.final)
        if (!output) output = result.find(effect + "/" + name);
    const NamedImage* noisy = scored.noisy.empty() ? nullptr : result.find(effect + "/" + scored.noisy);
    return {output, noisy == output ? nullptr : noisy};
}

} // namespace

std::vector<std::uint8_t> movingEdgeMask(const report::Image& reference,
                                         const report::Image& previousReference,
                                         const std::vector<std::uint8_t>& mask, float change) {
    const std::size_t count = mask.size();
    if (std::size_t{reference.width} * reference.height != count ||
        std::size_t{previousReference.width} * previousReference.height != count)
        throw std::invalid_argument(
            "moving edges: references of " + std::to_string(reference.width) + "x" +
            std::to_string(reference.height) + " and " + std::to_string(previousReference.width) + "x" +
            std::to_string(previousReference.height) + " for a mask of " + std::to_string(count) + " pixels");
    std::vector<std::uint8_t> moving(count, 0);
    for (std::size_t i = 0; i < count; ++i) {
        const float now = reference.pixels[i * reference.channels];
        const float before = previousReference.pixels[i * previousReference.channels];
        moving[i] = mask[i] && std::isfinite(now) && std::isfinite(before) && std::abs(now - before) > change;
    }
    return moving;
}

std::vector<ReferenceError> referenceErrors(const capture::Frame& frame, const FrameResult& result,
                                            const SettingValues& settings, const capture::Frame* previous) {
    std::vector<ReferenceError> errors;
    for (const EffectDescriptor* descriptor : effectRegistry()) {
        if (descriptor->evaluation.scored.empty()) continue;
        const std::string& effect = descriptor->name;
        const ScoredOutput* scored = &descriptor->evaluation.scored.front();
        const NamedImage* reference = result.find(effect + "/reference");
        if (!reference) continue;
        const auto [output, noisy] = scoredImages(result, effect, *scored);
        if (!output) continue;
        const std::vector<std::uint8_t> mask = errorMask(frame, scored->mask, settings);
        errors.push_back(compare(effect, *output, reference->image, mask, scored->metric));
        errors.back().maskThreshold = thresholdOf(scored->mask, settings);
        if (noisy) {
            const ReferenceError input = compare(effect, *noisy, reference->image, mask, scored->metric);
            errors.back().noisyMean = input.mean;
            errors.back().noisyRmse = input.rmse;
        }
        if (previous && scored->metric == ErrorMetric::Visibility)
            if (const std::optional<report::Image> before = previousReference(*previous, frame, effect))
                scoreMovingEdges(errors.back(), *output, noisy, reference->image, *before, mask);
    }
    return errors;
}

std::vector<ReferenceError> referenceNoise(const capture::Frame& frame, const FrameResult& result,
                                           const capture::Frame& second, const SettingValues& settings) {
    if (second.width != frame.width || second.height != frame.height)
        throw std::invalid_argument("second reference: its frame is " + std::to_string(second.width) + "x" +
                                    std::to_string(second.height) + ", the capture's " +
                                    std::to_string(frame.width) + "x" + std::to_string(frame.height));
    std::vector<ReferenceError> noise;
    for (const EffectDescriptor* descriptor : effectRegistry()) {
        if (descriptor->evaluation.scored.empty() || descriptor->reference.empty()) continue;
        const std::string& effect = descriptor->name;
        const ScoredOutput* scored = &descriptor->evaluation.scored.front();
        const NamedImage* reference = result.find(effect + "/reference");
        if (!reference) continue;
        const capture::Layer* layer = capture::findLayer(second, "reference." + descriptor->reference);
        if (!layer) continue;
        const std::uint32_t channels = std::min<std::uint32_t>(
            reference->image.channels, static_cast<std::uint32_t>(layer->channels.size()));
        const report::Image other{second.width, second.height, channels,
                                  layerChannels(second, layer->name, channels)};
        const std::vector<std::uint8_t> mask = errorMask(frame, scored->mask, settings);
        noise.push_back(compare(effect, *reference, other, mask, scored->metric));
        noise.back().maskThreshold = thresholdOf(scored->mask, settings);
        const auto [output, noisy] = scoredImages(result, effect, *scored);
        if (output && noisy && noise.back().pixels > 0)
            noise.back().differenceAgainstSecond =
                compare(effect, *output, other, mask, scored->metric).mean -
                compare(effect, *noisy, other, mask, scored->metric).mean;
    }
    return noise;
}

} // namespace glint::replay
