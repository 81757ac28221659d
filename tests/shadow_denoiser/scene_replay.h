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
    // penumbraAware: ShadowDenoiserDesc::penumbraAware of every frame (false: no estimate).
    explicit SceneShadowReplay(bool penumbraAware = true) : penumbraAware_(penumbraAware) {}
    struct Result {
        ShadowInputs inputs;
        ShadowOutputs outputs;
        // Per pixel, 1 where docs/shadow_denoiser.md's hard-shadow rule passes the receiver
        // through: penumbra widths 2 tan(light radius) b / (z pixel angle) of at most one pixel
        // over its 9 x 9 neighbourhood (clamped to the image; lit samples imply none), computed
        // here from the frame's blocker layer; all 0 without a penumbra estimate.
        std::vector<std::uint8_t> hard;
    };
    // Frame `index` of the sequence (0 first, then in order).
    Result run(const capture::Frame& frame, std::uint32_t index);

  private:
    bool penumbraAware_ = true;
    std::optional<ShadowRunner> runner_;
    std::vector<float> previousDepth_;
};

} // namespace glint::test
