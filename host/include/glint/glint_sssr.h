// glint public API: stochastic screen-space reflections (docs/sssr.md).
//
// One noisy GGX sample per traced pixel, marched through the depth pyramid, with an
// environment fallback blended by confidence; output radiance plus world-space hit distance
// for the reflections denoiser. The plan holds, in order: the depth pyramid (7 levels, no
// level-0 copy), tile classification, blue noise, indirect arguments, intersection and,
// optionally, the composite.
#pragma once

#include "glint/glint_depth_pyramid.h"
#include "glint/glint_pass.h"
#include "glint/glint_types.h"

#include <array>
#include <string>

namespace glint {

struct SssrDesc {
    Extent2D size; // 1..16384 each (the ray list packs x in 15 bits and y in 14: 16383 rows)

    // Camera. Matrices are row-major 4x4 with column vectors (q = M p), unjittered; inverses
    // are computed on the host in double. The projection must be a perspective one whose
    // clip w is the view depth (every standard and reversed projection is).
    std::array<double, 16> projection{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};    // view -> clip
    std::array<double, 16> viewFromWorld{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; // rigid
    DepthConvention depth = DepthConvention::Standard;
    float nearPlane = 0.1f;   // view depth of the near plane
    float farPlane = 1000.0f; // view depth of the far plane; 0 = infinite (reversed depth only)
    bool vulkanNdc = true;    // y_n = 2v - 1 (true) or 1 - 2v (D3D-style)

    // G-buffer decoding.
    float normalUnpackMul = 1.0f; // n = normalize(raw.xyz * mul + add); (2, -1) for UNORM normals
    float normalUnpackAdd = 0.0f;
    std::uint32_t materialChannel = 0; // channel of "material" holding roughness
    bool roughnessIsPerceptual = true; // true: the channel holds r (squared once); false: alpha
    float motionScaleX = 1.0f;         // uv_prev = uv + scale * mv (convention A after scaling)
    float motionScaleY = 1.0f;

    // Classification. Thresholds are GGX alpha.
    float roughnessThreshold = 0.2f; // no ray at or above; the environment instead
    float roughnessFadeBand =
        0.05f; // traced results fade to the environment over [threshold - band, threshold)
    float mirrorThreshold = 1e-4f;    // below: mirror (always traced, finest level, no copies)
    std::uint32_t samplesPerQuad = 1; // 1, 2 or 4 rays per 2x2 quad
    bool halfResolution = false;      // one ray per quad for every pixel (mirrors too), rotating each frame
    bool varianceGuided = false;      // TVGT: extra rays where the reprojected variance history is high
    float varianceThreshold = 0.0f;

    // Intersection.
    std::uint32_t maxTraversalIterations = 128;
    std::uint32_t mostDetailedMip = 0; // finest level for non-mirror rays, 0..6
    float occupancyExitFraction =
        0.0f; // non-mirror rays stop once at most this fraction of their group of 64 is live; 0 = off
    float thickness = 0.02f;           // assumed surface thickness, relative to its view depth
    float thicknessFloor = 0.01f;      // absolute minimum thickness, view-depth units
    bool thicknessAware = false;       // rays pass behind thin objects (RG32F closest+farthest pyramid)
    float importanceSampleBias = 0.0f; // 0..1 (Frostbite; DiligentFX uses 0.3): sharper, biased
    bool previousFrameColor = false;   // "color" is last frame's final colour, fetched through motion
    bool debugOutput = false;          // writes "sssr_ray_info": (hit x, hit y, class, iterations)
    bool storeRays = false; // writes "sssr_rays": direction and pdf (the denoiser's ratio-estimator path)
    // Roughness, radiance and confidence stored in 16-bit float (radiance clamped to 65504),
    // arithmetic in 32 bits; false stores them in 32 bits (the CPU references' permutation).
    bool halfPrecisionStorage = true;

    // Environment (the application's prefiltered map behind GLINT_SSSR_SampleEnvironment).
    float iblFactor = 1.0f;
    float environmentTexelSolidAngle = 4.0f * 3.14159265f / (6.0f * 128.0f * 128.0f); // level 0, steradians
    float environmentMaxLod = 7.0f;                                                   // its last level

    bool composite = false; // adds "composite": "color" + reflection x split-sum specular
    bool denoise = false;   // planReflections (glint_reflections.h) adds the reflections denoiser's resources
    std::string compositeReflection = "sssr_radiance"; // the image the composite applies

    std::uint32_t frameIndex = 0;
};

// Resources of the plan (the application's inputs first; every image is W x H unless said):
//   "depth"                  R32F device depth, sampled
//   "normals"                RGBA float, stored normals (see normalUnpack)
//   "material"               RGBA, roughness in materialChannel
//   "color"                  RGBA float lit colour (this frame's, or last frame's final one)
//   "motion"                 RG float motion vectors
//   "environment"            RGBA float environment, mip-mapped (the harness: lat-long)
//   "sssr_variance_history"  R32F last frame's reflection variance (read with varianceGuided only)
//   "sssr_blue_noise_source" RG32F 128 x 128: glint::sssrBlueNoise() (glint_sssr_tables.h), uploaded once
//   "sssr_brdf_lut"          RG32F glint::sssrBrdfLut(), with composite only
//   "base_color_metallic"    RGBA, with composite only
// Owned (plan.images / plan.buffers):
//   "depth_pyramid", "depth_pyramid_counter"   see glint_depth_pyramid.h (7 levels)
//   "sssr_roughness"         R32F (R16F with halfPrecisionStorage) GGX alpha (for the denoiser)
//   "sssr_radiance"          RGBA32F (RGBA16F) rgb radiance, a = world hit distance (65504: miss)
//   "sssr_confidence"        R32F (R16F) confidence of the screen-space hit (DiligentFX compositing)
//   "sssr_blue_noise"        RG32F 128 x 128, this frame's sample
//   "sssr_ray_list"          4 bytes per pixel; "sssr_tile_list" 4 bytes per 8 x 8 tile
//   "sssr_counters"          16 bytes, zero at creation, kept zero between frames by the passes
//   "sssr_indirect_args"     24 bytes: intersection (offset 0), denoiser (offset 12)
//   "sssr_ray_info"          RGBA32F, with debugOutput
//   "sssr_rays"              RGBA32F (RGBA16F), with storeRays: world unit direction of each glossy
//                            pixel's sample (its quad donor's for a copy), a = its bias-free pdf
//   "composite"              RGBA32F, with composite
Result planSssr(const SssrDesc& desc, EffectPlan& plan, std::string* error);

} // namespace glint
