// glint public API: the reflections denoiser (docs/reflections_denoiser.md).
//
// Turns SSSR's one noisy sample per traced pixel into a stable reflection: reproject (surface
// motion or reflection parallax, disocclusion, firefly clamp, history length, temporal
// variance, tile averages), prefilter (edge-aware, variance-guided) and temporal resolve
// (history clipping, blend by history length). Only the 8x8 tiles SSSR's classification
// listed are processed, indirectly from SSSR's arguments at byte offset 12. The result is
// written over "sssr_radiance" in place, so the effect's output is defined everywhere:
// unlisted tiles keep classification's environment or 0.
//
// Optional spatial path (spatialPath = RatioEstimator): reproject, then a ratio-estimator
// reconstruction from the neighbours' rays (Frostbite / DiligentFX) instead of the prefilter,
// the same resolve, then a small bilateral cleanup of the output. It needs SSSR's rays
// (SssrDesc::storeRays, "sssr_rays").
#pragma once

#include "glint/glint_depth_pyramid.h"
#include "glint/glint_pass.h"
#include "glint/glint_types.h"

#include <array>
#include <string>

namespace glint {

// The spatial filter between reproject and resolve.
enum class SpatialPath : std::uint8_t {
    Prefilter,      // edge-aware, variance-guided 15-tap filter of the samples (FidelityFX)
    RatioEstimator, // BRDF/pdf-weighted reuse of the neighbours' rays, plus a bilateral cleanup
};

struct ReflectionsDenoiserDesc {
    Extent2D size; // 1..16384 each
    // Camera, row-major 4x4 with column vectors (q = M p), unjittered, as in SssrDesc.
    std::array<double, 16> projection{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};    // view -> clip
    std::array<double, 16> viewFromWorld{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; // this frame
    std::array<double, 16> previousClipFromWorld{1, 0, 0, 0, 0, 1, 0, 0,
                                                 0, 0, 1, 0, 0, 0, 0, 1}; // VP of last frame
    DepthConvention depth = DepthConvention::Standard;
    float nearPlane = 0.1f;
    float farPlane = 1000.0f; // 0 = infinite (reversed depth only)
    bool vulkanNdc = true;
    float normalUnpackMul = 1.0f;
    float normalUnpackAdd = 0.0f;
    float motionScaleX = 1.0f, motionScaleY = 1.0f;
    float roughnessThreshold = 0.2f; // alpha: must equal SSSR's
    float mirrorThreshold = 1e-4f;   // alpha: no spatial filter below
    float historyClipScale = 0.7f;   // scale of the resolve's clip box (FidelityFX's "temporal stability")
    std::uint32_t maxHistoryLength = 32;
    // The resolve shortens a history that this frame's samples around the pixel contradict by
    // more than their noise explains (docs/reflections_denoiser.md, "Resolve"); mirrors excepted.
    bool antiLag = true;
    bool halfPrecisionStorage = true; // 16-bit radiance, variance and length; must match SSSR's
    bool resetHistory = false;        // first frame, camera cut or resize: every history is ignored
    std::uint32_t frameIndex = 0;     // histories ping-pong on its parity
    SpatialPath spatialPath = SpatialPath::Prefilter;
    // RatioEstimator only: the reconstruction's disk radius at perceptual roughness >= 0.2, in
    // pixels (1..8; smoother roughness scales it by 5 r), and the cleanup's spatial sigma in
    // pixels ((0, 2]; 0.9 gives a 3x3 footprint).
    float reconstructionRadius = 4.0f;
    float cleanupSigma = 0.9f;
};

// Resources (inputs first): "sssr_radiance" (read and overwritten), "depth", "normals",
// "sssr_roughness", "motion", "sssr_tile_list", "sssr_indirect_args" (from planSssr).
// Owned: "rd_clamped", "rd_reprojected", "rd_prefiltered" (RGBA32F; the clamped and
// prefiltered samples carry their variance in alpha, -1 for pixels that are not glossy),
// "rd_radiance0/1" (RGBA32F: resolved rgb, a = the final variance again), "rd_variance0/1", "rd_length0/1"
// (R32F), "rd_guides0/1" (RGBA32F: octahedral normal, view depth, alpha), "rd_average"
// (RGBA32F, one texel per tile) and
// "rd_tile_mask0/1" (4 bytes per tile). Parity p = frameIndex & 1 is written, 1 - p read.
// Every owned resource must start zeroed (a zero mask means "no history"). Reproject writes
// "rd_length", and the resolve writes it back after its anti-lag.
// RatioEstimator: the passes are reproject, reconstruct, resolve and cleanup; the same owned
// resources ("rd_prefiltered" holds the reconstruction) plus the input "sssr_rays" (SSSR's
// storeRays), and the camera's viewFromWorld rotation.
Result planReflectionsDenoiser(const ReflectionsDenoiserDesc& desc, EffectPlan& plan, std::string* error);

// The variance this frame's resolve wrote ("rd_variance0" or "rd_variance1"): next frame's
// SSSR variance history for variance-guided tracing.
std::string reflectionsDenoiserVariance(std::uint32_t frameIndex);

} // namespace glint
