// Capture frame -> SSSR desc and inputs (docs/sssr.md, docs/capture-format.md): camera
// matrices and depth convention from the header, normals decoded to unit world vectors,
// roughness from the declared source, motion converted to convention A, the environment as
// an RGBA lat-long map.
#pragma once

#include "capture/capture_frame.h"
#include "capture/environment_io.h"

#include <gpu/gpu_sssr_runner.h>

#include "glint/glint_reflections_denoiser.h"
#include "glint/glint_sssr.h"

#include <string>

namespace glint::replay {

// Fills the camera, size, decoding and environment fields of `desc` (the rest is kept) and
// every input the effect reads. Throws std::runtime_error naming the missing layer or the
// unsupported environment layout.
void sssrFromFrame(const capture::Frame& frame, const capture::Environment& environment, SssrDesc& desc,
                   gpu::SssrFrameInputs& inputs);

// Interleaved copy of a layer's first `channels` channels (missing ones 0), or throws.
std::vector<float> layerChannels(const capture::Frame& frame, const std::string& name, std::size_t channels);

// The normal layer as RGBA world-space vectors: octahedral decoded here, unit and UNORM
// passed through (UNORM is decoded by the passes through normalUnpackMul/Add).
std::vector<float> decodedNormals(const capture::Frame& frame);
// The motion layer as RG in convention A (uv_prev = uv + mv).
std::vector<float> motionConventionA(const capture::Frame& frame);

// The denoiser's desc for `frame` given the SSSR desc built from it: last frame's clip from
// the capture's previous view-projection; `reset` on the first frame or a camera cut.
ReflectionsDenoiserDesc denoiserFromFrame(const capture::Frame& frame, const SssrDesc& sssr,
                                          std::uint32_t frameIndex, bool reset);

} // namespace glint::replay
