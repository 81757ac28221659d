// The tests' way from a capture frame to the SSSR, reflections-denoiser and shadow-denoiser
// descs and inputs of the test adapters (test_sssr_runner.h, test_shadow_runner.h), over the
// replay's frame reading (replay/replay_frame.h): what the replay hands every effect, in the
// per-effect form the tests drive the passes with.
#pragma once

#include "capture/capture_frame.h"
#include "capture/environment_io.h"
#include "replay/replay_frame.h"
#include "support/test_shadow_runner.h"
#include "support/test_sssr_runner.h"

#include "glint/glint_reflections_denoiser.h"
#include "glint/glint_shadow_denoiser.h"
#include "glint/glint_sssr.h"

#include <cstdint>
#include <vector>

namespace glint::replay {

// Fills the camera, size, decoding and environment fields of `desc` (the rest is kept) and
// every input the effect reads. Throws std::runtime_error naming the missing layer or the
// unsupported environment layout.
void sssrFromFrame(const capture::Frame& frame, const capture::Environment& environment, SssrDesc& desc,
                   gpu::SssrFrameInputs& inputs);

// The denoiser's desc for `frame` given the SSSR desc built from it: last frame's clip from
// the capture's previous view-projection; `reset` on the first frame or a camera cut.
ReflectionsDenoiserDesc denoiserFromFrame(const capture::Frame& frame, const SssrDesc& sssr,
                                          std::uint32_t frameIndex, bool reset);

// Fills the camera, size and history fields of `desc` (the tunables are kept). `index` is the
// frame's position in the replayed run; `reset` drops every history (first frame, camera cut).
void shadowDescFromFrame(const capture::Frame& frame, std::uint32_t index, bool reset,
                         ShadowDenoiserDesc& desc);

// The inputs the denoiser reads. `previousDepth` is last frame's depth (empty: this frame's,
// which with reset is never read). Throws std::runtime_error naming a missing layer.
gpu::ShadowInputs shadowInputsFromFrame(const capture::Frame& frame, const std::vector<float>& previousDepth);

} // namespace glint::replay
