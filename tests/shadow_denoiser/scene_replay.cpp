#include "shadow_denoiser/scene_replay.h"

#include "support/test_replay.h"

namespace glint::test {

SceneShadowReplay::Result SceneShadowReplay::run(const capture::Frame& frame, std::uint32_t index) {
    ShadowDenoiserDesc desc;
    replay::shadowDescFromFrame(frame, index, index == 0, desc);
    if (!runner_) runner_.emplace(desc);
    Result result;
    result.inputs = replay::shadowInputsFromFrame(frame, previousDepth_);
    result.outputs = runner_->run(desc, result.inputs);
    previousDepth_ = result.inputs.depth;
    return result;
}

} // namespace glint::test
