// Hybrid reflections as data: validation, constants, passes, resources (docs/hybrid.md).
#include "glint/glint_hybrid.h"

#include "core/dispatch.h"
#include "core/plan_checks.h"
#include "core/sssr_constants.h"
#include "core/sssr_table_images.h"
#include "glint/glint_depth_pyramid.h"
#include "glint/glint_sssr_tables.h"
#include "glint/hybrid/glint_hybrid_constants.h"

#include <cmath>

namespace glint {
namespace {

Result invalid(std::string* error, const std::string& message) {
    return core::invalidArgument(error, "hybrid", message);
}

std::string checkHybrid(const HybridDesc& desc) {
    const auto finiteIn = [](float value, float low, float high) {
        return std::isfinite(value) && value >= low && value <= high;
    };
    if (!desc.screenSpace && !desc.rayTracing) return "screenSpace and rayTracing cannot both be off";
    if (!finiteIn(desc.spawnRate, 0.0f, 1.0f)) return "spawnRate must be 0..1";
    if (!finiteIn(desc.missWeight, 0.0f, 64.0f)) return "missWeight must be 0..64";
    if (!finiteIn(desc.rayTracingThreshold, 0.0f, 1.0f)) return "rayTracingThreshold must be 0..1 (alpha)";
    if (!finiteIn(desc.confidenceThreshold, 0.0f, 1.0f)) return "confidenceThreshold must be 0..1";
    if (!(std::isfinite(desc.maxRayDistance) && desc.maxRayDistance > 0.0f))
        return "maxRayDistance must be positive and finite";
    if (!finiteIn(desc.rayOffset, 0.0f, 1e3f)) return "rayOffset must be 0..1000";
    if (!finiteIn(desc.thicknessRoughnessGrowth, 0.0f, 1e3f))
        return "thicknessRoughnessGrowth must be 0..1000";
    if (!finiteIn(desc.thicknessDistanceGrowth, 0.0f, 1e3f)) return "thicknessDistanceGrowth must be 0..1000";
    if (desc.tracePipeline.empty() || desc.shadePipeline.empty())
        return "tracePipeline and shadePipeline must name modules";
    return {};
}

shaders::GLINT_HybridConstants makeConstants(const HybridDesc& desc) {
    shaders::GLINT_HybridConstants c{};
    c.tiles = {core::divideRoundUp(desc.sssr.size.width, GLINT_SSSR_TILE),
               core::divideRoundUp(desc.sssr.size.height, GLINT_SSSR_TILE)};
    c.flags = (desc.screenSpace ? GLINT_HYBRID_FLAG_SCREEN_SPACE : 0u) |
              (desc.rayTracing ? GLINT_HYBRID_FLAG_RAY_TRACING : 0u) |
              (desc.feedback ? GLINT_HYBRID_FLAG_FEEDBACK : 0u) |
              (desc.alternateCheckerboard ? GLINT_HYBRID_FLAG_ALTERNATE_CHECKER : 0u) |
              (desc.mirrorsRayTraced ? GLINT_HYBRID_FLAG_MIRRORS_RAY_TRACED : 0u) |
              (desc.reshade ? GLINT_HYBRID_FLAG_RESHADE : 0u);
    c.frameIndex = desc.sssr.frameIndex;
    c.spawnRate = desc.spawnRate;
    c.missWeight = desc.missWeight;
    c.rayTracingThreshold = desc.rayTracingThreshold;
    c.confidenceThreshold = desc.confidenceThreshold;
    c.maxRayDistance = desc.maxRayDistance;
    c.rayOffset = desc.rayOffset;
    c.thicknessRoughnessGrowth = desc.thicknessRoughnessGrowth;
    c.thicknessDistanceGrowth = desc.thicknessDistanceGrowth;
    return c;
}

// One cbuffer: the SSSR constants, then the hybrid ones (each a whole number of registers).
std::vector<std::byte> packConstants(const shaders::GLINT_SssrConstants& sssr,
                                     const shaders::GLINT_HybridConstants& hybrid) {
    std::vector<std::byte> bytes = core::packConstants(sssr);
    const std::vector<std::byte> tail = core::packConstants(hybrid);
    bytes.insert(bytes.end(), tail.begin(), tail.end());
    return bytes;
}

Pass classifyPass(const HybridDesc& desc, const std::vector<std::byte>& constants) {
    Pass pass = core::sssrPass("classify",
                               desc.sssr.halfPrecisionStorage ? "hybrid_classify.half" : "hybrid_classify",
                               GLINT_SSSR_TILE, GLINT_SSSR_TILE, constants);
    pass.dispatch = core::gridFor(desc.sssr.size.width, desc.sssr.size.height, 1, pass.groupSize);
    const auto [feedback, history] = hybridFeedbackImages(desc.sssr.frameIndex);
    // The denoiser's variance history joins with the denoiser (planHybridReflections).
    pass.uses = core::sssrClassifyUses("sssr_zero_variance");
    pass.uses.insert(pass.uses.end(), {{"g_glint_counters", "hybrid_counters", Access::ReadWrite},
                                       {"g_glint_sw_ray_list", "hybrid_sw_ray_list", Access::Write},
                                       {"g_glint_hw_ray_list", "hybrid_hw_ray_list", Access::Write},
                                       {"g_glint_tile_list", "sssr_tile_list", Access::Write},
                                       {"g_glint_feedback_history", history, Access::Read},
                                       {"g_glint_feedback", feedback, Access::Write},
                                       {"g_glint_tile_class", "hybrid_tile_class", Access::Write}});
    return pass;
}

Pass intersectPass(const HybridDesc& desc, const std::vector<std::byte>& constants) {
    Pass pass = core::sssrPass("intersect",
                               desc.sssr.halfPrecisionStorage ? "hybrid_intersect.half" : "hybrid_intersect",
                               GLINT_SSSR_RAYS_PER_GROUP, 1, constants);
    pass.dispatch = IndirectDispatch{"hybrid_indirect_args", 0};
    pass.uses = core::sssrIntersectUses();
    pass.uses.insert(pass.uses.end(), {{"g_glint_counters", "hybrid_counters", Access::ReadWrite},
                                       {"g_glint_ray_list", "hybrid_sw_ray_list", Access::Read},
                                       {"g_glint_hw_ray_list", "hybrid_hw_ray_list", Access::ReadWrite},
                                       {"g_glint_feedback", hybridFeedbackImages(desc.sssr.frameIndex).first,
                                        Access::ReadWrite},
                                       {"g_glint_hits", "hybrid_hits", Access::Write}});
    return pass;
}

Pass rayTracedArgumentsPass() {
    Pass pass = core::sssrPass("hw_args", "hybrid_hw_args", 1, 1, {});
    pass.dispatch = DirectDispatch{1, 1, 1};
    pass.uses = {{"g_glint_counters", "hybrid_counters", Access::ReadWrite},
                 {"g_glint_arguments", "hybrid_indirect_args", Access::ReadWrite}};
    return pass;
}

// The ray-traced passes read the listed pixels' surfaces again to draw the same samples.
std::vector<ResourceUse> rayTracedSurfaceUses() {
    return {{"g_glint_depth", "depth", Access::Read},
            {"g_glint_normals", "normals", Access::Read},
            {"g_glint_roughness", "sssr_roughness", Access::Read},
            {"g_glint_blue_noise", "sssr_blue_noise", Access::Read},
            {"g_glint_counters", "hybrid_counters", Access::Read},
            {"g_glint_hw_ray_list", "hybrid_hw_ray_list", Access::Read},
            {"g_scene_nodes", "scene_nodes", Access::Read},
            {"g_scene_primitives", "scene_primitives", Access::Read}};
}

Pass tracePass(const HybridDesc& desc, const std::vector<std::byte>& constants) {
    Pass pass = core::sssrPass("trace", desc.tracePipeline, GLINT_SSSR_RAYS_PER_GROUP, 1, constants);
    pass.dispatch = IndirectDispatch{"hybrid_indirect_args", GLINT_HYBRID_HW_ARGUMENTS_OFFSET};
    pass.uses = rayTracedSurfaceUses();
    if (desc.tracer == HybridTracer::RayQuery) {
        std::erase_if(pass.uses, [](const ResourceUse& use) { return use.resource.starts_with("scene_"); });
        pass.uses.push_back({"g_glint_scene", "scene_acceleration_structure", Access::Read});
    }
    pass.uses.push_back({"g_glint_hits", "hybrid_hits", Access::Write});
    return pass;
}

Pass shadePass(const HybridDesc& desc, const std::vector<std::byte>& constants) {
    Pass pass = core::sssrPass(
        "shade", desc.sssr.halfPrecisionStorage ? desc.shadePipeline + ".half" : desc.shadePipeline,
        GLINT_SSSR_RAYS_PER_GROUP, 1, constants);
    pass.dispatch = IndirectDispatch{"hybrid_indirect_args", GLINT_HYBRID_SHADE_ARGUMENTS_OFFSET};
    pass.uses = rayTracedSurfaceUses();
    pass.uses.insert(pass.uses.end(), {{"g_glint_hits", "hybrid_hits", Access::Read},
                                       {"g_glint_environment", "environment", Access::Read},
                                       {"g_glint_radiance", "sssr_radiance", Access::ReadWrite},
                                       {"g_glint_confidence", "sssr_confidence", Access::ReadWrite},
                                       {"g_scene_constants", "scene_constants", Access::Read},
                                       {"g_scene_materials", "scene_materials", Access::Read},
                                       {"g_scene_lights", "scene_lights", Access::Read}});
    return pass;
}

} // namespace

std::pair<std::string, std::string> hybridFeedbackImages(std::uint32_t frameIndex) {
    const bool odd = (frameIndex & 1u) != 0;
    return {odd ? "hybrid_feedback1" : "hybrid_feedback0", odd ? "hybrid_feedback0" : "hybrid_feedback1"};
}

Result planHybrid(const HybridDesc& desc, EffectPlan& plan, std::string* error) {
    if (const std::string problem = core::checkSssrDesc(desc.sssr); !problem.empty())
        return invalid(error, problem);
    if (const std::string problem = checkHybrid(desc); !problem.empty()) return invalid(error, problem);
    core::Matrix4 viewFromClip{};
    core::Matrix4 worldFromView{};
    if (!core::invert(desc.sssr.projection, viewFromClip)) return invalid(error, "projection is singular");
    if (!core::invert(desc.sssr.viewFromWorld, worldFromView))
        return invalid(error, "viewFromWorld is singular");

    DepthPyramidDesc pyramid;
    pyramid.size = desc.sssr.size;
    pyramid.depth = desc.sssr.depth;
    pyramid.channels = DepthPyramidChannels::Closest;
    pyramid.levelCount = GLINT_SSSR_PYRAMID_LEVELS;
    pyramid.copyLevel0 = false; // the intersection reads level 0 from "depth" itself
    if (depthPyramidLayout(desc.sssr.size, 0).fullLevelCount < GLINT_SSSR_PYRAMID_LEVELS)
        pyramid.levelCount = 0;
    plan = EffectPlan{};
    if (const Result result = planDepthPyramid(pyramid, plan, error); result != Result::Ok) return result;
    for (Pass& pass : plan.passes) pass.name = "depth_pyramid";
    plan.effect = "hybrid";
    plan.size = desc.sssr.size;
    const std::uint32_t w = desc.sssr.size.width;
    const std::uint32_t h = desc.sssr.size.height;
    const std::uint32_t tilesX = core::divideRoundUp(w, GLINT_SSSR_TILE);
    const std::uint32_t tilesY = core::divideRoundUp(h, GLINT_SSSR_TILE);
    const std::uint64_t tiles = std::uint64_t{tilesX} * tilesY;
    const bool half = desc.sssr.halfPrecisionStorage;
    plan.images.push_back({"sssr_roughness", w, h, 1, half ? Format::R16Float : Format::R32Float});
    plan.images.push_back({"sssr_radiance", w, h, 1, half ? Format::RGBA16Float : Format::RGBA32Float});
    plan.images.push_back({"sssr_confidence", w, h, 1, half ? Format::R16Float : Format::R32Float});
    plan.images.push_back({"sssr_blue_noise_source", kSssrBlueNoiseSize, kSssrBlueNoiseSize, 1,
                           Format::RG32Float, core::sssrBlueNoiseTexels()});
    plan.images.push_back(
        {"sssr_blue_noise", GLINT_SSSR_BLUE_NOISE_SIZE, GLINT_SSSR_BLUE_NOISE_SIZE, 1, Format::RG32Float});
    plan.images.push_back({"hybrid_feedback0", tilesX, tilesY, 1, Format::R32Uint});
    plan.images.push_back({"hybrid_feedback1", tilesX, tilesY, 1, Format::R32Uint});
    plan.images.push_back({"hybrid_tile_class", tilesX, tilesY, 1, Format::R32Uint});
    plan.images.push_back({"sssr_zero_variance", 1, 1, 1, Format::R32Float});
    // Padding to 32 or 64 entries per tile can exceed W H at sizes not divisible by 8
    // (docs/conventions.md, defect HR4): 64 entries per tile always fit.
    plan.buffers.push_back({"hybrid_sw_ray_list", tiles * 64u * 4u, false});
    plan.buffers.push_back({"hybrid_hw_ray_list", std::uint64_t{w} * h * 4u, false});
    plan.buffers.push_back({"sssr_tile_list", tiles * 4u, false});
    plan.buffers.push_back({"hybrid_counters", GLINT_HYBRID_COUNTER_WORDS * 4u, false});
    plan.buffers.push_back({"hybrid_indirect_args", GLINT_HYBRID_ARGUMENT_WORDS * 4u, true});
    plan.buffers.push_back({"hybrid_hits", std::uint64_t{w} * h * 16u, false});

    const shaders::GLINT_SssrConstants sssrConstants =
        core::makeSssrConstants(desc.sssr, viewFromClip, worldFromView);
    const std::vector<std::byte> constants = packConstants(sssrConstants, makeConstants(desc));
    plan.passes.push_back(classifyPass(desc, constants));
    const std::vector<std::byte> sssrOnly = core::packConstants(sssrConstants);
    // SSSR's blue-noise pass turns counters 0 and 2 (the screen-space list's length, padding
    // included, and the denoiser's tiles) into the intersection's and the denoiser's arguments:
    // the hybrid counters and arguments start with SSSR's layout.
    plan.passes.push_back(core::sssrBlueNoisePass(sssrOnly, "hybrid_counters", "hybrid_indirect_args"));
    plan.passes.push_back(intersectPass(desc, constants));
    plan.passes.push_back(rayTracedArgumentsPass());
    plan.passes.push_back(tracePass(desc, constants));
    plan.passes.push_back(shadePass(desc, constants));
    if (desc.sssr.composite) {
        plan.images.push_back({"sssr_brdf_lut", kSssrBrdfLutSize, kSssrBrdfLutSize, 1, Format::RG32Float,
                               core::sssrBrdfLutTexels()});
        plan.images.push_back({"composite", w, h, 1, Format::RGBA32Float});
        plan.passes.push_back(core::sssrCompositePass(desc.sssr, sssrOnly));
    }
    return Result::Ok;
}

} // namespace glint
