#include "capture/capture_frame.h"

#include <cmath>

namespace glint::capture {

namespace {
template <typename LayerT, typename ContainerT> LayerT* findIn(ContainerT& layers, std::string_view name) {
    for (auto& layer : layers)
        if (layer.name == name) return &layer;
    return nullptr;
}
} // namespace

const Layer* findLayer(const Frame& frame, std::string_view name) {
    return findIn<const Layer>(frame.layers, name);
}

Layer* findLayer(Frame& frame, std::string_view name) {
    return findIn<Layer>(frame.layers, name);
}

const LayerInfo* findLayer(const FrameHeader& header, std::string_view name) {
    return findIn<const LayerInfo>(header.layers, name);
}

int channelIndex(const std::vector<std::string>& channels, std::string_view channel) {
    for (std::size_t i = 0; i < channels.size(); ++i)
        if (channels[i] == channel) return static_cast<int>(i);
    return -1;
}

std::size_t countNonFinite(const std::vector<float>& samples) {
    std::size_t count = 0;
    for (float v : samples)
        if (!std::isfinite(v)) ++count;
    return count;
}

NonFiniteSummary summarizeNonFinite(const Frame& frame) {
    NonFiniteSummary summary;
    for (const Layer& layer : frame.layers) {
        if (layer.nonFinite == 0) continue;
        summary.layers.push_back({layer.name, layer.nonFinite});
        summary.total += layer.nonFinite;
    }
    return summary;
}

FrameHeader headerOf(const Frame& frame) {
    FrameHeader h;
    h.width = frame.width;
    h.height = frame.height;
    h.formatVersion = frame.formatVersion;
    h.frameIndex = frame.frameIndex;
    h.camera = frame.camera;
    h.normalEncoding = frame.normalEncoding;
    h.motion = frame.motion;
    h.roughness = frame.roughness;
    h.shadowLightTanHalfAngle = frame.shadowLightTanHalfAngle;
    h.effects = frame.effects;
    for (const Layer& layer : frame.layers) h.layers.push_back({layer.name, layer.channels, layer.storage});
    return h;
}

Frame frameFromHeader(const FrameHeader& header) {
    Frame f;
    f.width = header.width;
    f.height = header.height;
    f.formatVersion = header.formatVersion;
    f.frameIndex = header.frameIndex;
    f.camera = header.camera;
    f.normalEncoding = header.normalEncoding;
    f.motion = header.motion;
    f.roughness = header.roughness;
    f.shadowLightTanHalfAngle = header.shadowLightTanHalfAngle;
    f.effects = header.effects;
    return f;
}

Mat4 viewProjection(const Camera& camera) {
    return multiply(camera.projection, camera.view);
}

} // namespace glint::capture
