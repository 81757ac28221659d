// Capture frame -> shadow denoiser desc and inputs (docs/shadow_denoiser.md): camera and
// depth convention from the header, the reprojection from last frame's view-projection, the
// `shadow` layer as the noisy visibility, motion converted to convention A.
#pragma once

#include "capture/capture_frame.h"

#include <gpu/gpu_shadow_runner.h>

#include "glint/glint_shadow_denoiser.h"

#include <cstdint>
#include <vector>

namespace glint::replay {

// Fills the camera, size and history fields of `desc` (the tunables are kept). `index` is the
// frame's position in the replayed run; `reset` drops every history (first frame, camera cut).
void shadowDescFromFrame(const capture::Frame& frame, std::uint32_t index, bool reset,
                         ShadowDenoiserDesc& desc);

// The inputs the denoiser reads. `previousDepth` is last frame's depth (empty: this frame's,
// which with reset is never read). Throws std::runtime_error naming a missing layer.
gpu::ShadowInputs shadowInputsFromFrame(const capture::Frame& frame, const std::vector<float>& previousDepth);

} // namespace glint::replay
