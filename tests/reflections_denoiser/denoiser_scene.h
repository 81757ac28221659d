// Shared by the reflections-denoiser GPU tests: a simulated scene's frame as SSSR inputs, the
// denoiser desc for a frame, and the error of a radiance image against the capture's
// reference over glossy pixels.
#pragma once

#include "capture/capture_frame.h"
#include "capture/environment_io.h"
#include "glint/glint_reflections_denoiser.h"
#include "glint/glint_sssr.h"

#include "support/test_sssr_runner.h"

#include <string>
#include <vector>

namespace glint::test {

struct DenoiserScene {
    std::vector<capture::Frame> frames;
    SssrDesc desc;               // frame 0's
    gpu::SssrFrameInputs inputs; // frame 0's
    capture::Environment environment;
};

// Simulates harness/scenes/<name>.toml at width x height for `frames` frames with references;
// `accumulateReferences` false gives every frame a reference of the scene's own sample count
// (ReferenceDesc::accumulate), so that errors of moving and still frames are measured against
// references of the same noise.
DenoiserScene simulateDenoiserScene(const std::string& name, std::uint32_t width, std::uint32_t height,
                                    std::uint32_t frames, bool accumulateReferences = true);

// Runs the scene's frames in `frameOrder` (frame index 0, 1, ... in that order, a history reset on
// the first) through SSSR, denoised or not, and returns each frame's radiance (RGBA); requires
// every value to be finite.
std::vector<std::vector<float>> runDenoiserFrames(const DenoiserScene& scene,
                                                  const std::vector<std::size_t>& frameOrder, bool denoise);

// Mean of |value - reference| / max(reference luma, 0.05) over pixels whose alpha is below the
// threshold and whose depth is not background (luminance, Rec. 709).
double glossyError(const capture::Frame& frame, const std::vector<float>& radianceRgba,
                   float roughnessThreshold);
// The same metric against another RGBA image (e.g. SSSR's own converged mean) instead of the
// capture's reference.
double glossyError(const capture::Frame& frame, const std::vector<float>& radianceRgba,
                   const std::vector<float>& targetRgba, float roughnessThreshold);

// Root mean square of the colour channels' difference from the capture's reference over the
// same pixels as glossyError.
double glossyRmse(const capture::Frame& frame, const std::vector<float>& radianceRgba,
                  float roughnessThreshold);

// Frame `index` of the non-finite tests: frames 1 and 2 fill every history the denoiser reads
// that frame with NaN (frame 1) or Inf (frame 2) and upload `clean` with that value scattered
// over colour, normals, depth, motion and roughness; other frames upload `clean` as it is.
// Requires every channel of the runner's image `name` to be finite over the 8x8 tiles of
// out.tileList (the only texels the denoiser writes).
void requireFiniteOverTiles(const gpu::SssrRunner& runner, const gpu::SssrFrameOutputs& out,
                            const std::string& name);

void uploadPoisonedFrame(gpu::SssrRunner& runner, const gpu::SssrFrameInputs& clean, std::uint32_t index);

} // namespace glint::test
