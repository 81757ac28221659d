// glint public API: hybrid reflections (docs/hybrid.md), screen space first and a ray-traced
// fallback chosen per 8x8 tile from last frame's hit/miss feedback.
//
// planHybrid's plan holds the depth pyramid, the tile classification (feedback counters, tile
// classes, the screen-space and ray-traced ray lists, the denoiser's tile list), blue noise and
// arguments, the screen-space intersection with feedback, the ray tracer's arguments, ray
// tracing, deferred shading and, with sssr.composite, SSSR's composite. planHybridReflections
// adds the reflections denoiser before the composite; the effect "hybrid" (glint_effect.h)
// plans through it.
#pragma once

#include "glint/glint_pass.h"
#include "glint/glint_reflections_denoiser.h"
#include "glint/glint_sssr.h"

#include <cstdint>
#include <string>

namespace glint {

// What the trace module traces: the harness's BVH buffers ("scene_nodes", "scene_primitives" at
// g_scene_nodes, g_scene_primitives) or a top-level acceleration structure
// ("scene_acceleration_structure" at g_glint_scene, InputKind::SceneAccelerationStructure) for a
// RayQuery module such as hybrid_trace_rayquery (docs/hybrid.md, "Acceleration structures").
enum class HybridTracer : std::uint8_t { Bvh, RayQuery };

struct HybridDesc {
    // The screen-space half: camera, G-buffer decoding, SSSR classification and traversal.
    SssrDesc sssr;

    bool screenSpace = true;           // off: every ray is ray traced (the RT-only path)
    bool rayTracing = true;            // off: every ray stays in screen space (the SSSR path)
    bool feedback = true;              // off: every tile is FULL_SW (screen space first everywhere)
    bool alternateCheckerboard = true; // HALF_SW's checkerboard flips every frame
    bool mirrorsRayTraced = false;     // per-material override example: mirrors always ray traced
    // Screen-space hits are shaded by the shading module's GLINT_HYBRID_ShadeScreenHit, the same
    // lighting as ray-traced hits, so both paths agree; off: they take "color" as SSSR's do
    // (sssr.previousFrameColor: last frame's colour through the motion at the hit).
    bool reshade = true;

    float spawnRate = 0.02f;           // s: chance a tile without statistics tries screen space
    float missWeight = 0.5f;           // w: a miss against a hit in u <= s + h - w m
    float rayTracingThreshold = 0.22f; // alpha: at or above, rays stay in screen space
    float confidenceThreshold = 0.9f;  // screen-space hits below it are ray traced instead
    float maxRayDistance = 100.0f;     // world units, the ray tracer's t_max
    float rayOffset = 1e-3f;           // world units along the normal, the ray tracer's origin offset
    // A screen-space hit's thickness: SSSR's (sssr.thickness, thicknessFloor) times
    // (1 + thicknessRoughnessGrowth alpha), plus thicknessDistanceGrowth times the ray's length
    // to the hit (view-depth units per world unit): rough rays blur what they find, long rays
    // cross more depth per pixel.
    float thicknessRoughnessGrowth = 10.0f;
    float thicknessDistanceGrowth = 0.01f;

    // The application's modules for the two ray-traced passes: GLINT_HYBRID_TraceRay
    // (glint/hybrid/glint_hybrid_trace.hlsli) and GLINT_HYBRID_ShadeHit, _ShadeScreenHit
    // (_shade.hlsli; ".half" is appended with halfPrecisionStorage). glint's harness provides these over its
    // simulated scenes; their scene resources are the application's inputs.
    std::string tracePipeline = "hybrid_trace_bvh";
    std::string shadePipeline = "hybrid_shade_scene";
    // The trace module's scene resources. RayQuery goes with tracePipeline
    // "hybrid_trace_rayquery" (compiled by DXC only: loaded from GLINT_SHADER_DIR) or an
    // application module with its bindings.
    HybridTracer tracer = HybridTracer::Bvh;
};

// Resources (besides SSSR's inputs, glint_sssr.h):
//   "hybrid_feedback0", "hybrid_feedback1"  R32_UINT ceil(W/8) x ceil(H/8), ping-pong by frame
//                                          parity: frame f writes feedback[f & 1], reads the other
//   "hybrid_tile_class"   R32_UINT ceil(W/8) x ceil(H/8): GLINT_HYBRID_TILE_* of this frame
//   "hybrid_sw_ray_list"  ceil(W/8) ceil(H/8) 64 entries, padded per tile (0xFFFFFFFF)
//   "hybrid_hw_ray_list"  W H entries: ray-traced rays from the start, re-shaded hits from the end
//   "sssr_tile_list", "sssr_roughness", "sssr_radiance", "sssr_confidence" as in glint_sssr.h
//   "hybrid_counters"     10 words, "hybrid_indirect_args" 12 words (glint_hybrid_constants.h)
//   "sssr_blue_noise_source" (owned, glint::sssrBlueNoise()), "sssr_blue_noise", "depth_pyramid"
//   "hybrid_hits"         16 bytes per list entry (GLINT_HYBRID_PackHit, _PackScreenHit)
// and the application's scene for its trace and shade modules (the harness's: "scene_constants",
// "scene_nodes", "scene_primitives", "scene_materials", "scene_lights"; with HybridTracer::RayQuery
// the trace module reads "scene_acceleration_structure" instead of the first two).
Result planHybrid(const HybridDesc& desc, EffectPlan& plan, std::string* error);

// The hybrid result denoised by the reflections denoiser (glint_reflections_denoiser.h) when
// `denoiser` is given (desc.sssr.denoise must then be set), then composited with
// desc.sssr.composite: the hybrid counterpart of planReflections (glint_reflections.h). The
// denoiser's passes follow the shading pass and read the hybrid tile list and arguments; the
// classification reads the variance the denoiser resolved last frame. Names its outputs
// ("noisy", "denoised", "composite", ...) and counters ("ray_traced_rays", ...).
Result planHybridReflections(const HybridDesc& desc, const ReflectionsDenoiserDesc* denoiser,
                             EffectPlan& plan, std::string* error);

// The names of frame `frameIndex`'s feedback images: {written, read as history}.
std::pair<std::string, std::string> hybridFeedbackImages(std::uint32_t frameIndex);

} // namespace glint
