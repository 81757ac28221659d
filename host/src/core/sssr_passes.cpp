// Stochastic screen-space reflections as data: validation, constants, passes, resources.
#include "glint/glint_sssr.h"

#include "core/camera.h"
#include "core/dispatch.h"
#include "core/plan_checks.h"
#include "core/sssr_constants.h"
#include "glint/common/glint_wire_formats.h"

#include <algorithm>
#include <cmath>

namespace glint {
namespace core {

std::string checkSssrDesc(const SssrDesc& desc) {
    if (!core::validExtent(desc.size) || desc.size.height > 16383)
        return "size must be 1..16384 wide and 1..16383 high (the ray list packs y in 14 bits)";
    if (!(std::isfinite(desc.nearPlane) && desc.nearPlane > 0.0f))
        return "nearPlane must be positive and finite";
    const bool infiniteFar = desc.depth == DepthConvention::Reversed && desc.farPlane == 0.0f;
    if (!infiniteFar && !(std::isfinite(desc.farPlane) && desc.farPlane > desc.nearPlane))
        return "farPlane must be finite and beyond nearPlane (0 = infinite, reversed depth only)";
    if (!core::isFinite(desc.projection) || !core::isFinite(desc.viewFromWorld))
        return "camera matrices must be finite";
    if (!std::isfinite(desc.normalUnpackMul) || !std::isfinite(desc.normalUnpackAdd))
        return "normal unpack factors must be finite";
    if (desc.materialChannel > 3) return "materialChannel must be 0..3";
    if (!std::isfinite(desc.motionScaleX) || !std::isfinite(desc.motionScaleY))
        return "motion scale must be finite";
    const auto finiteIn = [](float value, float low, float high) {
        return std::isfinite(value) && value >= low && value <= high;
    };
    if (!finiteIn(desc.roughnessThreshold, 0.0f, 1.0f)) return "roughnessThreshold must be 0..1 (alpha)";
    if (!finiteIn(desc.roughnessFadeBand, 0.0f, 1.0f)) return "roughnessFadeBand must be 0..1 (alpha)";
    if (!finiteIn(desc.mirrorThreshold, 0.0f, 1.0f)) return "mirrorThreshold must be 0..1 (alpha)";
    if (desc.samplesPerQuad != 1 && desc.samplesPerQuad != 2 && desc.samplesPerQuad != 4)
        return "samplesPerQuad must be 1, 2 or 4";
    if (!std::isfinite(desc.varianceThreshold)) return "varianceThreshold must be finite";
    if (desc.maxTraversalIterations < 1 || desc.maxTraversalIterations > 4096)
        return "maxTraversalIterations must be 1..4096";
    if (desc.mostDetailedMip >= GLINT_SSSR_PYRAMID_LEVELS) return "mostDetailedMip must be 0..6";
    if (!finiteIn(desc.occupancyExitFraction, 0.0f, 1.0f)) return "occupancyExitFraction must be 0..1";
    if (!finiteIn(desc.thickness, 0.0f, 1e6f) || !finiteIn(desc.thicknessFloor, 0.0f, 1e6f))
        return "thickness and thicknessFloor must be finite and >= 0";
    if (!finiteIn(desc.importanceSampleBias, 0.0f, 1.0f)) return "importanceSampleBias must be 0..1";
    if (!finiteIn(desc.iblFactor, 0.0f, 1e6f)) return "iblFactor must be finite and >= 0";
    if (!(std::isfinite(desc.environmentTexelSolidAngle) && desc.environmentTexelSolidAngle > 0.0f))
        return "environmentTexelSolidAngle must be positive and finite";
    if (!finiteIn(desc.environmentMaxLod, 0.0f, 16.0f)) return "environmentMaxLod must be 0..16";
    if (desc.composite && desc.compositeReflection.empty()) return "compositeReflection must name an image";
    return {};
}

shaders::GLINT_SssrConstants makeSssrConstants(const SssrDesc& desc, const core::Matrix4& viewFromClip,
                                               const core::Matrix4& worldFromView) {
    shaders::GLINT_SssrConstants c{};
    c.inputSize = {desc.size.width, desc.size.height};
    c.inverseInputSize = {1.0f / static_cast<float>(desc.size.width),
                          1.0f / static_cast<float>(desc.size.height)};
    core::storeRows(desc.projection, c.clipFromView);
    core::storeRows(viewFromClip, c.viewFromClip);
    core::storeRows(desc.viewFromWorld, c.viewFromWorld);
    core::storeRows(worldFromView, c.worldFromView);
    const bool reversed = desc.depth == DepthConvention::Reversed;
    c.viewDepth = core::viewDepthCoefficients(reversed, desc.nearPlane, desc.farPlane);
    c.normalUnpack = {desc.normalUnpackMul, desc.normalUnpackAdd};
    c.ndcYSign = desc.vulkanNdc ? 1.0f : -1.0f;
    c.flags = (reversed ? GLINT_SSSR_FLAG_REVERSED_DEPTH : 0u) |
              (desc.roughnessIsPerceptual ? GLINT_SSSR_FLAG_ROUGHNESS_PERCEPTUAL : 0u) |
              (desc.varianceGuided ? GLINT_SSSR_FLAG_VARIANCE_GUIDED : 0u) |
              (desc.previousFrameColor ? GLINT_SSSR_FLAG_PREVIOUS_FRAME_COLOR : 0u) |
              (desc.halfResolution ? GLINT_SSSR_FLAG_HALF_RESOLUTION : 0u) |
              (desc.thicknessAware ? GLINT_SSSR_FLAG_THICKNESS_AWARE : 0u);
    c.materialChannel = desc.materialChannel;
    c.samplesPerQuad = desc.samplesPerQuad;
    c.frameIndex = desc.frameIndex;
    c.maxIterations = desc.maxTraversalIterations;
    c.roughnessThreshold = desc.roughnessThreshold;
    c.mirrorThreshold = desc.mirrorThreshold;
    c.roughnessFadeBand = desc.roughnessFadeBand;
    c.varianceThreshold = desc.varianceThreshold;
    c.thickness = desc.thickness;
    c.thicknessFloor = desc.thicknessFloor;
    c.importanceSampleBias = desc.importanceSampleBias;
    c.iblFactor = desc.iblFactor;
    c.mostDetailedMip = desc.mostDetailedMip;
    c.minActiveRays = static_cast<std::uint32_t>(
        std::floor(desc.occupancyExitFraction * static_cast<float>(GLINT_SSSR_RAYS_PER_GROUP)));
    c.environmentTexelSolidAngle = desc.environmentTexelSolidAngle;
    c.environmentMaxLod = desc.environmentMaxLod;
    c.nearPlane = desc.nearPlane;
    c.farPlane = desc.farPlane;
    c.motionScale = {desc.motionScaleX, desc.motionScaleY};
    return c;
}

Pass sssrPass(const char* name, std::string pipeline, std::uint32_t groupX, std::uint32_t groupY,
              const std::vector<std::byte>& constants) {
    Pass pass;
    pass.name = name;
    pass.pipeline = std::move(pipeline);
    pass.groupSize[0] = groupX;
    pass.groupSize[1] = groupY;
    pass.groupSize[2] = 1;
    if (!constants.empty()) {
        pass.constantsBinding = "g_glint_constants";
        pass.constants = constants;
    }
    return pass;
}

std::vector<ResourceUse> sssrClassifyUses(const std::string& varianceHistory) {
    return {{"g_glint_depth", "depth", Access::Read},
            {"g_glint_normals", "normals", Access::Read},
            {"g_glint_material", "material", Access::Read},
            {"g_glint_motion", "motion", Access::Read},
            {"g_glint_variance_history", varianceHistory, Access::Read},
            {"g_glint_environment", "environment", Access::Read},
            {"g_glint_roughness", "sssr_roughness", Access::Write},
            {"g_glint_radiance", "sssr_radiance", Access::Write},
            {"g_glint_confidence", "sssr_confidence", Access::Write}};
}

std::vector<ResourceUse> sssrIntersectUses() {
    return {{"g_glint_depth", "depth", Access::Read},
            {"g_glint_depth_pyramid", "depth_pyramid", Access::Read},
            {"g_glint_normals", "normals", Access::Read},
            {"g_glint_roughness", "sssr_roughness", Access::Read},
            {"g_glint_blue_noise", "sssr_blue_noise", Access::Read},
            {"g_glint_color", "color", Access::Read},
            {"g_glint_motion", "motion", Access::Read},
            {"g_glint_environment", "environment", Access::Read},
            {"g_glint_radiance", "sssr_radiance", Access::ReadWrite},
            {"g_glint_confidence", "sssr_confidence", Access::ReadWrite}};
}

// Blue noise and the indirect arguments share one dispatch (see the entry file); with `tiles`
// (the SSSR plan) the ray-list compaction too, one group per block of 64 tiles.
Pass sssrBlueNoisePass(const std::vector<std::byte>& constants, const std::string& counters,
                       const std::string& arguments, std::uint32_t tiles) {
    constexpr std::uint32_t noiseGroups = GLINT_SSSR_BLUE_NOISE_SIZE / 8;
    Pass pass = sssrPass(tiles > 0 ? "compact_noise_args" : "blue_noise_args",
                         tiles > 0 ? "sssr_blue_noise.compact" : "sssr_blue_noise", 8, 8, constants);
    pass.dispatch = DirectDispatch{noiseGroups, noiseGroups, 1};
    pass.uses = {{"g_glint_blue_noise_source", "sssr_blue_noise_source", Access::Read},
                 {"g_glint_blue_noise", "sssr_blue_noise", Access::Write},
                 {"g_glint_counters", counters, Access::ReadWrite},
                 {"g_glint_arguments", arguments, Access::Write}};
    if (tiles > 0) {
        const std::uint32_t groups = std::max(noiseGroups * noiseGroups, shared::GLINT_WIRE_RayBlocks(tiles));
        pass.dispatch = DirectDispatch{std::min(groups, GLINT_SSSR_GROUPS_PER_ROW),
                                       core::divideRoundUp(groups, GLINT_SSSR_GROUPS_PER_ROW), 1};
        pass.uses.push_back({"g_glint_ray_scratch", "sssr_ray_scratch", Access::ReadWrite});
        pass.uses.push_back({"g_glint_ray_list", "sssr_ray_list", Access::Write});
    }
    return pass;
}

Pass sssrCompositePass(const SssrDesc& desc, const std::vector<std::byte>& constants) {
    Pass pass = sssrPass("composite", "sssr_composite", GLINT_SSSR_TILE, GLINT_SSSR_TILE, constants);
    pass.dispatch = core::gridFor(desc.size.width, desc.size.height, 1, pass.groupSize);
    pass.uses = {{"g_glint_color", "color", Access::Read},
                 {"g_glint_reflection", desc.compositeReflection, Access::Read},
                 {"g_glint_depth", "depth", Access::Read},
                 {"g_glint_normals", "normals", Access::Read},
                 {"g_glint_roughness", "sssr_roughness", Access::Read},
                 {"g_glint_base_color_metallic", "base_color_metallic", Access::Read},
                 {"g_glint_brdf_lut", "sssr_brdf_lut", Access::Read},
                 {"g_glint_composite", "composite", Access::Write}};
    return pass;
}

} // namespace core
namespace {

Result invalid(std::string* error, const std::string& message) {
    return core::invalidArgument(error, "sssr", message);
}

Pass classifyPass(const SssrDesc& desc, const std::vector<std::byte>& constants) {
    Pass pass = core::sssrPass("classify", desc.halfPrecisionStorage ? "sssr_classify.half" : "sssr_classify",
                               GLINT_SSSR_TILE, GLINT_SSSR_TILE, constants);
    pass.dispatch = core::gridFor(desc.size.width, desc.size.height, 1, pass.groupSize);
    pass.uses = core::sssrClassifyUses("sssr_variance_history");
    pass.uses.insert(pass.uses.end(), {{"g_glint_counters", "sssr_counters", Access::ReadWrite},
                                       {"g_glint_ray_scratch", "sssr_ray_scratch", Access::ReadWrite},
                                       {"g_glint_tile_list", "sssr_tile_list", Access::Write}});
    return pass;
}

Pass intersectPass(const SssrDesc& desc, const std::vector<std::byte>& constants) {
    const std::string suffix = std::string(desc.thicknessAware ? "_thick" : "") +
                               (desc.debugOutput ? "_debug" : "") + (desc.storeRays ? "_ray" : "") +
                               (desc.halfPrecisionStorage ? "_half" : "");
    const std::string pipeline = suffix.empty() ? "sssr_intersect" : "sssr_intersect." + suffix.substr(1);
    Pass pass = core::sssrPass("intersect", pipeline, GLINT_SSSR_RAYS_PER_GROUP, 1, constants);
    pass.dispatch = IndirectDispatch{"sssr_indirect_args", 0};
    pass.uses = core::sssrIntersectUses();
    pass.uses.insert(pass.uses.end(), {{"g_glint_counters", "sssr_counters", Access::Read},
                                       {"g_glint_ray_list", "sssr_ray_list", Access::Read}});
    if (desc.debugOutput) pass.uses.push_back({"g_glint_ray_info", "sssr_ray_info", Access::Write});
    if (desc.storeRays) pass.uses.push_back({"g_glint_rays", "sssr_rays", Access::Write});
    return pass;
}

} // namespace

Result planSssr(const SssrDesc& desc, EffectPlan& plan, std::string* error) {
    if (const std::string problem = core::checkSssrDesc(desc); !problem.empty())
        return invalid(error, problem);
    core::Matrix4 viewFromClip{};
    core::Matrix4 worldFromView{};
    if (!core::invert(desc.projection, viewFromClip)) return invalid(error, "projection is singular");
    if (!core::invert(desc.viewFromWorld, worldFromView)) return invalid(error, "viewFromWorld is singular");

    DepthPyramidDesc pyramid;
    pyramid.size = desc.size;
    pyramid.depth = desc.depth;
    pyramid.channels =
        desc.thicknessAware ? DepthPyramidChannels::ClosestAndFarthest : DepthPyramidChannels::Closest;
    pyramid.levelCount = GLINT_SSSR_PYRAMID_LEVELS;
    pyramid.copyLevel0 = false; // the intersection reads level 0 from "depth" itself
    // Small images have fewer levels than the traversal's 7: build them all.
    const DepthPyramidLayout layout = depthPyramidLayout(desc.size, 0);
    if (layout.fullLevelCount < GLINT_SSSR_PYRAMID_LEVELS) pyramid.levelCount = 0;
    if (const Result result = planDepthPyramid(pyramid, plan, error); result != Result::Ok) return result;
    plan.effect = "sssr";
    plan.size = desc.size;

    const std::vector<std::byte> constants =
        core::packConstants(core::makeSssrConstants(desc, viewFromClip, worldFromView));
    const std::uint32_t w = desc.size.width;
    const std::uint32_t h = desc.size.height;
    const std::uint64_t tiles =
        std::uint64_t{core::divideRoundUp(w, GLINT_SSSR_TILE)} * core::divideRoundUp(h, GLINT_SSSR_TILE);
    const bool half = desc.halfPrecisionStorage;
    plan.images.push_back({"sssr_roughness", w, h, 1, half ? Format::R16Float : Format::R32Float});
    plan.images.push_back({"sssr_radiance", w, h, 1, half ? Format::RGBA16Float : Format::RGBA32Float});
    plan.images.push_back({"sssr_confidence", w, h, 1, half ? Format::R16Float : Format::R32Float});
    plan.images.push_back(
        {"sssr_blue_noise", GLINT_SSSR_BLUE_NOISE_SIZE, GLINT_SSSR_BLUE_NOISE_SIZE, 1, Format::RG32Float});
    if (desc.debugOutput) plan.images.push_back({"sssr_ray_info", w, h, 1, Format::RGBA32Float});
    if (desc.storeRays)
        plan.images.push_back({"sssr_rays", w, h, 1, half ? Format::RGBA16Float : Format::RGBA32Float});
    plan.buffers.push_back({"sssr_ray_list", std::uint64_t{w} * h * 4u, false});
    plan.buffers.push_back(
        {"sssr_ray_scratch",
         std::uint64_t{shared::GLINT_WIRE_RayScratchWords(static_cast<std::uint32_t>(tiles))} * 4u, false});
    plan.buffers.push_back({"sssr_tile_list", tiles * 4u, false});
    plan.buffers.push_back({"sssr_counters", GLINT_SSSR_COUNTER_WORDS * 4u, false});
    plan.buffers.push_back({"sssr_indirect_args", GLINT_SSSR_ARGUMENT_WORDS * 4u, true});

    plan.passes.push_back(classifyPass(desc, constants));
    plan.passes.push_back(core::sssrBlueNoisePass(constants, "sssr_counters", "sssr_indirect_args",
                                                  static_cast<std::uint32_t>(tiles)));
    plan.passes.push_back(intersectPass(desc, constants));
    if (desc.composite) {
        plan.images.push_back({"composite", w, h, 1, Format::RGBA32Float});
        plan.passes.push_back(core::sssrCompositePass(desc, constants));
    }
    return Result::Ok;
}

} // namespace glint
