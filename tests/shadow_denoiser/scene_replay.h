// The scene tests' frame loop: a simulated capture replayed through the shadow denoiser frame
// by frame, histories reset on frame 0 and last frame's depth carried as the previous depth.
#pragma once

#include "shadow_denoiser/shadow_runner.h"

#include "capture/capture_frame.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace glint::test {

class SceneShadowReplay {
  public:
    struct Result {
        ShadowInputs inputs;
        ShadowOutputs outputs;
    };
    // Frame `index` of the sequence (0 first, then in order).
    Result run(const capture::Frame& frame, std::uint32_t index);

  private:
    std::optional<ShadowRunner> runner_;
    std::vector<float> previousDepth_;
};

} // namespace glint::test
