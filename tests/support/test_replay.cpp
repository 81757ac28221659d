#include "support/test_replay.h"

#include "capture/mat4.h"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

namespace glint::replay {

void sssrFromFrame(const capture::Frame& frame, const capture::Environment& environment, SssrDesc& desc,
                   gpu::SssrFrameInputs& inputs) {
    std::uint32_t channels = 0;
    inputs.depth = inputTexels(frame, InputKind::Depth, channels);
    inputs.normals = inputTexels(frame, InputKind::Normals, channels);
    inputs.material = inputTexels(frame, InputKind::Material, channels);
    inputs.color = inputTexels(frame, InputKind::Color, channels);
    inputs.motion = inputTexels(frame, InputKind::Motion, channels);
    if (capture::findLayer(frame, inputLayer(frame, InputKind::BaseColorMetallic)))
        inputs.baseColorMetallic = inputTexels(frame, InputKind::BaseColorMetallic, channels);
    inputs.environment = environmentTexels(environment);
    inputs.environmentWidth = environment.width;
    inputs.environmentHeight = environment.height;

    const FrameInfo info = frameInfo(frame, environment, 0, false);
    desc.halfPrecisionStorage = false; // the CPU references' 32-bit permutation
    desc.size = info.size;
    desc.projection = info.projection;
    desc.viewFromWorld = info.viewFromWorld;
    desc.depth = info.depth;
    desc.nearPlane = info.nearPlane;
    desc.farPlane = info.farPlane;
    desc.vulkanNdc = info.vulkanNdc;
    desc.normalUnpackMul = info.normalUnpackMul;
    desc.normalUnpackAdd = info.normalUnpackAdd;
    desc.materialChannel = info.materialChannel;
    desc.roughnessIsPerceptual = info.roughnessIsPerceptual;
    desc.motionScaleX = info.motionScaleX;
    desc.motionScaleY = info.motionScaleY;
    desc.environmentTexelSolidAngle = info.environmentTexelSolidAngle;
    desc.environmentMaxLod = info.environmentMaxLod;
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

void shadowDescFromFrame(const capture::Frame& frame, std::uint32_t index, bool reset,
                         ShadowDenoiserDesc& desc) {
    desc.size = {frame.width, frame.height};
    const capture::Camera& camera = frame.camera;
    desc.depth = camera.depth == capture::DepthConvention::Standard ? ShadowDenoiserDepth::Standard
                                                                    : ShadowDenoiserDepth::Reversed;
    desc.nearPlane = static_cast<float>(camera.nearZ);
    desc.farPlane =
        camera.depth == capture::DepthConvention::ReversedInfinite ? 0.0f : static_cast<float>(camera.farZ);
    const capture::Mat4 viewProjection = capture::multiply(camera.projection, camera.view);
    const std::optional<capture::Mat4> inverseViewProjection = capture::inverse(viewProjection);
    const std::optional<capture::Mat4> inverseView = capture::inverse(camera.view);
    if (!inverseViewProjection || !inverseView)
        throw std::runtime_error("frame " + std::to_string(frame.frameIndex) +
                                 ": the camera's view-projection is not invertible");
    desc.inverseViewProjection = inverseViewProjection->m;
    desc.reprojection = capture::multiply(camera.prevViewProjection, *inverseViewProjection).m;
    desc.eyePosition = {static_cast<float>(inverseView->m[3]), static_cast<float>(inverseView->m[7]),
                        static_cast<float>(inverseView->m[11])};
    desc.vulkanNdc = camera.ndcYDown;
    desc.resetHistory = reset;
    desc.frameIndex = index;
    desc.normalUnpackMul = frame.normalEncoding == capture::NormalEncoding::WorldUnorm ? 2.0f : 1.0f;
    desc.normalUnpackAdd = frame.normalEncoding == capture::NormalEncoding::WorldUnorm ? -1.0f : 0.0f;
    // The penumbra estimate's sizes (light < 0, pixel 0 when unknown): the light's, and a pixel's at the
    // image centre, 2 tan(fovY / 2) / H with 1 / tan(fovY / 2) the projection's [1][1].
    desc.lightTanHalfAngle = static_cast<float>(frame.shadowLightTanHalfAngle);
    const double focalY = std::abs(camera.projection.m[5]);
    desc.pixelAngularSize = focalY > 0.0 ? static_cast<float>(2.0 / (focalY * frame.height)) : 0.0f;
}

gpu::ShadowInputs shadowInputsFromFrame(const capture::Frame& frame,
                                        const std::vector<float>& previousDepth) {
    gpu::ShadowInputs inputs;
    std::uint32_t channels = 0;
    inputs.visibility = inputTexels(frame, InputKind::ShadowVisibility, channels);
    inputs.depth = inputTexels(frame, InputKind::Depth, channels);
    inputs.previousDepth = previousDepth.size() == inputs.depth.size() ? previousDepth : inputs.depth;
    inputs.normals = inputTexels(frame, InputKind::Normals, channels);
    inputs.motion = inputTexels(frame, InputKind::Motion, channels);
    inputs.blockerDistance = inputTexels(frame, InputKind::ShadowBlockerDistance, channels);
    return inputs;
}

} // namespace glint::replay
