#include "replay/replay_sssr.h"

#include "capture/mat4.h"
#include "capture/motion_convention.h"

#include <algorithm>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace glint::replay {
namespace {

// conventions.md section 5: octahedral decode, then normalize.
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

ReflectionsDenoiserDesc denoiserFromFrame(const capture::Frame& frame, const SssrDesc& sssr,
                                          std::uint32_t frameIndex, bool reset) {
    ReflectionsDenoiserDesc d;
    d.size = sssr.size;
    d.projection = sssr.projection;
    d.viewFromWorld = sssr.viewFromWorld;
    d.previousClipFromWorld = frame.camera.prevViewProjection.m;
    d.depth = sssr.depth;
    d.nearPlane = sssr.nearPlane;
    d.farPlane = sssr.farPlane;
    d.vulkanNdc = sssr.vulkanNdc;
    d.normalUnpackMul = sssr.normalUnpackMul;
    d.normalUnpackAdd = sssr.normalUnpackAdd;
    d.motionScaleX = sssr.motionScaleX;
    d.motionScaleY = sssr.motionScaleY;
    d.roughnessThreshold = sssr.roughnessThreshold;
    d.mirrorThreshold = sssr.mirrorThreshold;
    d.halfPrecisionStorage = sssr.halfPrecisionStorage;
    d.resetHistory = reset;
    d.frameIndex = frameIndex;
    return d;
}

void sssrFromFrame(const capture::Frame& frame, const capture::Environment& environment, SssrDesc& desc,
                   gpu::SssrFrameInputs& inputs) {
    const capture::Camera& camera = frame.camera;
    desc.size = {frame.width, frame.height};
    desc.projection = camera.projection.m;
    desc.viewFromWorld = camera.view.m;
    desc.depth = camera.depth == capture::DepthConvention::Standard ? DepthConvention::Standard
                                                                    : DepthConvention::Reversed;
    desc.nearPlane = static_cast<float>(camera.nearZ);
    desc.farPlane =
        camera.depth == capture::DepthConvention::ReversedInfinite ? 0.0f : static_cast<float>(camera.farZ);
    desc.vulkanNdc = camera.ndcYDown;
    desc.normalUnpackMul = 1.0f;
    desc.normalUnpackAdd = 0.0f;

    inputs.depth = layerChannels(frame, "depth", 1);
    const std::size_t count = std::size_t{frame.width} * frame.height;
    if (frame.normalEncoding == capture::NormalEncoding::WorldUnorm) {
        desc.normalUnpackMul = 2.0f;
        desc.normalUnpackAdd = -1.0f;
    }
    inputs.normals = decodedNormals(frame);

    const capture::RoughnessSource& source = frame.roughness;
    if (source.layer.empty()) throw std::runtime_error("capture declares no roughness source");
    const capture::Layer* roughness = capture::findLayer(frame, source.layer);
    if (!roughness)
        throw std::runtime_error("capture has no '" + source.layer + "' layer (roughness source)");
    const int channel = capture::channelIndex(roughness->channels, source.channel);
    if (channel < 0)
        throw std::runtime_error("roughness layer '" + source.layer + "' has no channel '" + source.channel +
                                 "'");
    inputs.material.assign(4 * count, 0.0f);
    const std::size_t have = roughness->channels.size();
    for (std::size_t i = 0; i < count; ++i)
        inputs.material[4 * i] = roughness->pixels[i * have + static_cast<std::size_t>(channel)];
    desc.materialChannel = 0;
    desc.roughnessIsPerceptual = source.perceptual;

    inputs.color = layerChannels(frame, "color", 4);
    inputs.motion = motionConventionA(frame);
    desc.motionScaleX = 1.0f;
    desc.motionScaleY = 1.0f;
    if (capture::findLayer(frame, "material")) inputs.baseColorMetallic = layerChannels(frame, "material", 4);

    if (environment.layout != capture::EnvironmentLayout::LatLong)
        throw std::runtime_error("the SSSR replay reads lat-long environments only (this one is a cube map)");
    inputs.environmentWidth = environment.width;
    inputs.environmentHeight = environment.height;
    inputs.environment.resize(std::size_t{environment.width} * environment.height * 4);
    for (std::size_t i = 0; i < std::size_t{environment.width} * environment.height; ++i) {
        for (std::size_t c = 0; c < 3; ++c) inputs.environment[4 * i + c] = environment.rgb[3 * i + c];
        inputs.environment[4 * i + 3] = 1.0f;
    }
    // A lat-long texel at the equator spans (2 pi / w) x (pi / h) steradians.
    desc.environmentTexelSolidAngle =
        static_cast<float>(2.0 * std::numbers::pi * std::numbers::pi /
                           (static_cast<double>(environment.width) * environment.height));
    desc.environmentMaxLod =
        std::floor(std::log2(static_cast<float>(std::max(environment.width, environment.height))));
}

} // namespace glint::replay
