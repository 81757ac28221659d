#include "replay/replay_shadow.h"

#include "capture/mat4.h"
#include "capture/motion_convention.h"
#include "replay/replay_sssr.h"

#include <stdexcept>

namespace glint::replay {

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
}

gpu::ShadowInputs shadowInputsFromFrame(const capture::Frame& frame,
                                        const std::vector<float>& previousDepth) {
    gpu::ShadowInputs inputs;
    inputs.visibility = layerChannels(frame, "shadow", 1);
    inputs.depth = layerChannels(frame, "depth", 1);
    inputs.previousDepth = previousDepth.size() == inputs.depth.size() ? previousDepth : inputs.depth;
    inputs.normals = decodedNormals(frame);
    inputs.motion = motionConventionA(frame);
    return inputs;
}

} // namespace glint::replay
