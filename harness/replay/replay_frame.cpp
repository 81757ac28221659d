#include "replay/replay_frame.h"

#include "capture/motion_convention.h"

#include <algorithm>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace glint::replay {
namespace {

// Octahedral decode, then normalize (docs/conventions.md, normal encodings).
void decodeOctahedral(float px, float py, float out[3]) {
    float x = 2.0f * px - 1.0f, y = 2.0f * py - 1.0f;
    const float z = 1.0f - std::abs(x) - std::abs(y);
    const float t = std::max(-z, 0.0f);
    x -= x >= 0.0f ? t : -t;
    y -= y >= 0.0f ? t : -t;
    const float length = std::sqrt(x * x + y * y + z * z);
    out[0] = x / length;
    out[1] = y / length;
    out[2] = z / length;
}

} // namespace

std::vector<float> layerChannels(const capture::Frame& frame, const std::string& name, std::size_t channels) {
    const capture::Layer* layer = capture::findLayer(frame, name);
    if (!layer) throw std::runtime_error("capture has no '" + name + "' layer");
    const std::size_t count = std::size_t{frame.width} * frame.height;
    const std::size_t have = layer->channels.size();
    std::vector<float> out(count * channels, 0.0f);
    for (std::size_t i = 0; i < count; ++i)
        for (std::size_t c = 0; c < std::min(have, channels); ++c)
            out[i * channels + c] = layer->pixels[i * have + c];
    return out;
}

namespace {

std::vector<float> decodedNormals(const capture::Frame& frame) {
    std::vector<float> normals = layerChannels(frame, "normal", 4);
    if (frame.normalEncoding == capture::NormalEncoding::Octahedral)
        for (std::size_t i = 0; i < normals.size() / 4; ++i)
            decodeOctahedral(normals[4 * i], normals[4 * i + 1], &normals[4 * i]);
    return normals;
}

std::vector<float> motionConventionA(const capture::Frame& frame) {
    std::vector<float> motion = layerChannels(frame, "motion", 2);
    for (std::size_t i = 0; i < motion.size() / 2; ++i) {
        const capture::Float2 a = capture::toConventionA({motion[2 * i], motion[2 * i + 1]}, frame.motion,
                                                         frame.width, frame.height, frame.camera.ndcYDown);
        motion[2 * i] = a.x;
        motion[2 * i + 1] = a.y;
    }
    return motion;
}

// Roughness from the declared source, in channel 0 of an RGBA image.
std::vector<float> roughnessTexels(const capture::Frame& frame) {
    const capture::RoughnessSource& source = frame.roughness;
    if (source.layer.empty()) throw std::runtime_error("capture declares no roughness source");
    const capture::Layer* roughness = capture::findLayer(frame, source.layer);
    if (!roughness)
        throw std::runtime_error("capture has no '" + source.layer + "' layer (roughness source)");
    const int channel = capture::channelIndex(roughness->channels, source.channel);
    if (channel < 0)
        throw std::runtime_error("roughness layer '" + source.layer + "' has no channel '" + source.channel +
                                 "'");
    const std::size_t count = std::size_t{frame.width} * frame.height;
    std::vector<float> material(4 * count, 0.0f);
    const std::size_t have = roughness->channels.size();
    for (std::size_t i = 0; i < count; ++i)
        material[4 * i] = roughness->pixels[i * have + static_cast<std::size_t>(channel)];
    return material;
}

} // namespace

std::string inputLayer(const capture::Frame& frame, InputKind kind) {
    switch (kind) {
    case InputKind::Depth:
        return "depth";
    case InputKind::Normals:
        return "normal";
    case InputKind::Material:
        return frame.roughness.layer;
    case InputKind::Color:
        return "color";
    case InputKind::Motion:
        return "motion";
    case InputKind::BaseColorMetallic:
        return "material";
    case InputKind::ShadowVisibility:
        return "shadow";
    case InputKind::ShadowBlockerDistance:
        return "shadow_blocker";
    case InputKind::PreviousDepth:
    case InputKind::Environment:
    case InputKind::SceneGeometry:
    case InputKind::SceneAccelerationStructure:
        return "";
    }
    return "";
}

std::vector<float> inputTexels(const capture::Frame& frame, InputKind kind, std::uint32_t& channels) {
    switch (kind) {
    case InputKind::Depth:
        channels = 1;
        return layerChannels(frame, "depth", 1);
    case InputKind::Normals:
        channels = 4;
        return decodedNormals(frame);
    case InputKind::Material:
        channels = 4;
        return roughnessTexels(frame);
    case InputKind::Color:
        channels = 4;
        return layerChannels(frame, "color", 4);
    case InputKind::Motion:
        channels = 2;
        return motionConventionA(frame);
    case InputKind::BaseColorMetallic:
        channels = 4;
        return layerChannels(frame, "material", 4);
    case InputKind::ShadowVisibility:
        channels = 1;
        return layerChannels(frame, "shadow", 1);
    case InputKind::ShadowBlockerDistance:
        // Optional: without the layer every pixel's blocker is unknown (-1), and the shadow
        // denoiser filters as without its penumbra estimate.
        channels = 1;
        if (!capture::findLayer(frame, "shadow_blocker"))
            return std::vector<float>(std::size_t{frame.width} * frame.height, -1.0f);
        return layerChannels(frame, "shadow_blocker", 1);
    case InputKind::PreviousDepth:
    case InputKind::Environment:
    case InputKind::SceneGeometry:
    case InputKind::SceneAccelerationStructure:
        break;
    }
    throw std::logic_error("replay: inputTexels does not read this kind");
}

std::vector<float> environmentTexels(const capture::Environment& environment) {
    if (environment.layout != capture::EnvironmentLayout::LatLong)
        throw std::runtime_error("the SSSR replay reads lat-long environments only (this one is a cube map)");
    std::vector<float> rgba(std::size_t{environment.width} * environment.height * 4);
    for (std::size_t i = 0; i < std::size_t{environment.width} * environment.height; ++i) {
        for (std::size_t c = 0; c < 3; ++c) rgba[4 * i + c] = environment.rgb[3 * i + c];
        rgba[4 * i + 3] = 1.0f;
    }
    return rgba;
}

void holdCamera(FrameInfo& info) {
    for (std::size_t row = 0; row < 4; ++row)
        for (std::size_t col = 0; col < 4; ++col) {
            double sum = 0.0;
            for (std::size_t k = 0; k < 4; ++k)
                sum += info.projection[row * 4 + k] * info.viewFromWorld[k * 4 + col];
            info.previousClipFromWorld[row * 4 + col] = sum;
        }
}

FrameInfo frameInfo(const capture::Frame& frame, const capture::Environment& environment, std::uint32_t index,
                    bool reset) {
    const capture::Camera& camera = frame.camera;
    FrameInfo info;
    info.size = {frame.width, frame.height};
    info.projection = camera.projection.m;
    info.viewFromWorld = camera.view.m;
    info.previousClipFromWorld = camera.prevViewProjection.m;
    info.depth = camera.depth == capture::DepthConvention::Standard ? DepthConvention::Standard
                                                                    : DepthConvention::Reversed;
    info.nearPlane = static_cast<float>(camera.nearZ);
    info.farPlane =
        camera.depth == capture::DepthConvention::ReversedInfinite ? 0.0f : static_cast<float>(camera.farZ);
    info.vulkanNdc = camera.ndcYDown;
    // Octahedral normals are decoded here; UNORM ones by the passes.
    const bool unorm = frame.normalEncoding == capture::NormalEncoding::WorldUnorm;
    info.normalUnpackMul = unorm ? 2.0f : 1.0f;
    info.normalUnpackAdd = unorm ? -1.0f : 0.0f;
    info.materialChannel = 0;
    info.roughnessIsPerceptual = frame.roughness.perceptual;
    if (environment.width > 0 && environment.height > 0) {
        // A lat-long texel at the equator spans (2 pi / w) x (pi / h) steradians.
        info.environmentTexelSolidAngle =
            static_cast<float>(2.0 * std::numbers::pi * std::numbers::pi /
                               (static_cast<double>(environment.width) * environment.height));
        info.environmentMaxLod =
            std::floor(std::log2(static_cast<float>(std::max(environment.width, environment.height))));
    }
    info.frameIndex = index;
    info.resetHistory = reset;
    info.shadowLightTanHalfAngle = static_cast<float>(frame.shadowLightTanHalfAngle);
    return info;
}

} // namespace glint::replay
