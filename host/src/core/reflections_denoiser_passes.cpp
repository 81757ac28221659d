// The reflections denoiser as data: validation, constants, passes, resources.
#include "glint/glint_reflections_denoiser.h"

#include "core/camera.h"
#include "core/dispatch.h"
#include "core/plan_checks.h"
#include "glint/reflections_denoiser/glint_reflections_denoiser_constants.h"
#include "glint/reflections_denoiser/glint_reflections_denoiser_ratio_constants.h"

#include <cmath>

namespace glint {
namespace {

Result invalid(std::string* error, const std::string& message) {
    return core::invalidArgument(error, "reflections denoiser", message);
}

std::string checkDesc(const ReflectionsDenoiserDesc& desc) {
    if (!core::validExtent(desc.size)) return "size must be 1..16384 in each dimension";
    if (!(std::isfinite(desc.nearPlane) && desc.nearPlane > 0.0f))
        return "nearPlane must be positive and finite";
    const bool infiniteFar = desc.depth == DepthConvention::Reversed && desc.farPlane == 0.0f;
    if (!infiniteFar && !(std::isfinite(desc.farPlane) && desc.farPlane > desc.nearPlane))
        return "farPlane must be finite and beyond nearPlane (0 = infinite, reversed depth only)";
    if (!core::isFinite(desc.projection) || !core::isFinite(desc.viewFromWorld) ||
        !core::isFinite(desc.previousClipFromWorld))
        return "camera matrices must be finite";
    if (!std::isfinite(desc.normalUnpackMul) || !std::isfinite(desc.normalUnpackAdd))
        return "normal unpack factors must be finite";
    if (!std::isfinite(desc.motionScaleX) || !std::isfinite(desc.motionScaleY))
        return "motion scale must be finite";
    if (!(desc.roughnessThreshold >= 0.0f && desc.roughnessThreshold <= 1.0f))
        return "roughnessThreshold must be 0..1 (alpha)";
    if (!(desc.mirrorThreshold >= 0.0f && desc.mirrorThreshold <= 1.0f))
        return "mirrorThreshold must be 0..1 (alpha)";
    if (!(desc.historyClipScale > 0.0f && desc.historyClipScale <= 100.0f))
        return "historyClipScale must be in (0, 100]";
    if (desc.maxHistoryLength < 8 || desc.maxHistoryLength > 1024) return "maxHistoryLength must be 8..1024";
    if (desc.spatialPath != SpatialPath::Prefilter && desc.spatialPath != SpatialPath::RatioEstimator)
        return "spatialPath must be Prefilter or RatioEstimator";
    if (!(desc.reconstructionRadius >= 1.0f &&
          desc.reconstructionRadius <= static_cast<float>(GLINT_RD_RATIO_MAX_RADIUS)))
        return "reconstructionRadius must be 1..8 pixels";
    if (!(desc.cleanupSigma > 0.0f && desc.cleanupSigma <= 2.0f)) return "cleanupSigma must be in (0, 2]";
    return {};
}

// Every pass reads SSSR's tile list; those that read the surface also depth, normals and
// roughness (the resolve learns glossiness from the prefiltered image's alpha instead, and reads
// the roughness alone).
Pass tilePass(const char* name, const char* pipeline, const std::vector<std::byte>& constants,
              bool readsSurface = true) {
    Pass pass;
    pass.name = name;
    pass.pipeline = pipeline;
    pass.groupSize[0] = GLINT_RD_TILE;
    pass.groupSize[1] = GLINT_RD_TILE;
    pass.groupSize[2] = 1;
    pass.constantsBinding = "g_glint_constants";
    pass.constants = constants;
    pass.dispatch = IndirectDispatch{"sssr_indirect_args", 12};
    pass.uses = {{"g_glint_tile_list", "sssr_tile_list", Access::Read}};
    if (readsSurface)
        pass.uses.insert(pass.uses.end(), {{"g_glint_depth", "depth", Access::Read},
                                           {"g_glint_normals", "normals", Access::Read},
                                           {"g_glint_roughness", "sssr_roughness", Access::Read}});
    return pass;
}

} // namespace

std::string reflectionsDenoiserVariance(std::uint32_t frameIndex) {
    return (frameIndex & 1u) != 0 ? "rd_variance1" : "rd_variance0";
}

Result planReflectionsDenoiser(const ReflectionsDenoiserDesc& desc, EffectPlan& plan, std::string* error) {
    if (const std::string problem = checkDesc(desc); !problem.empty()) return invalid(error, problem);
    core::Matrix4 viewFromClip{}, worldFromView{};
    if (!core::invert(desc.projection, viewFromClip)) return invalid(error, "projection is singular");
    if (!core::invert(desc.viewFromWorld, worldFromView)) return invalid(error, "viewFromWorld is singular");

    shaders::GLINT_ReflectionsDenoiserConstants c{};
    c.inputSize = {desc.size.width, desc.size.height};
    c.inverseInputSize = {1.0f / static_cast<float>(desc.size.width),
                          1.0f / static_cast<float>(desc.size.height)};
    core::storeRows(viewFromClip, c.viewFromClip);
    core::storeRows(core::multiply(desc.previousClipFromWorld, worldFromView), c.previousClipFromView);
    const bool reversed = desc.depth == DepthConvention::Reversed;
    c.viewDepth = core::viewDepthCoefficients(reversed, desc.nearPlane, desc.farPlane);
    c.normalUnpack = {desc.normalUnpackMul, desc.normalUnpackAdd};
    c.ndcYSign = desc.vulkanNdc ? 1.0f : -1.0f;
    c.flags = (reversed ? GLINT_RD_FLAG_REVERSED_DEPTH : 0u) |
              (desc.resetHistory ? GLINT_RD_FLAG_RESET : 0u) | (desc.antiLag ? GLINT_RD_FLAG_ANTI_LAG : 0u);
    c.motionScale = {desc.motionScaleX, desc.motionScaleY};
    const std::uint32_t tilesX = core::divideRoundUp(desc.size.width, GLINT_RD_TILE);
    const std::uint32_t tilesY = core::divideRoundUp(desc.size.height, GLINT_RD_TILE);
    c.tiles = {tilesX, tilesY};
    c.roughnessThreshold = desc.roughnessThreshold;
    c.mirrorThreshold = desc.mirrorThreshold;
    c.historyClipScale = desc.historyClipScale;
    c.maxHistoryLength = desc.maxHistoryLength;
    const std::vector<std::byte> constants = core::packConstants(c);

    const std::uint32_t w = desc.size.width, h = desc.size.height;
    plan = EffectPlan{};
    plan.effect = "reflections_denoiser";
    plan.size = desc.size;
    const bool half = desc.halfPrecisionStorage;
    for (const char* name :
         {"rd_clamped", "rd_reprojected", "rd_prefiltered", "rd_radiance0", "rd_radiance1"})
        plan.images.push_back({name, w, h, 1, half ? Format::RGBA16Float : Format::RGBA32Float});
    for (const char* name : {"rd_guides0", "rd_guides1"})
        plan.images.push_back({name, w, h, 1, Format::RGBA32Float});
    for (const char* name : {"rd_variance0", "rd_variance1", "rd_length0", "rd_length1"})
        plan.images.push_back({name, w, h, 1, half ? Format::R16Float : Format::R32Float});
    plan.images.push_back({"rd_average", tilesX, tilesY, 1, Format::RGBA32Float});
    plan.buffers.push_back({"rd_tile_mask0", std::uint64_t{tilesX} * tilesY * 4u, false});
    plan.buffers.push_back({"rd_tile_mask1", std::uint64_t{tilesX} * tilesY * 4u, false});

    const bool odd = (desc.frameIndex & 1u) != 0;
    const std::string now = odd ? "1" : "0", before = odd ? "0" : "1";
    Pass reproject = tilePass("reproject", half ? "rd_reproject.half" : "rd_reproject", constants);
    reproject.uses.insert(reproject.uses.end(),
                          {{"g_glint_noisy", "sssr_radiance", Access::Read},
                           {"g_glint_motion", "motion", Access::Read},
                           {"g_glint_history_tile_mask", "rd_tile_mask" + before, Access::Read},
                           {"g_glint_history_guides", "rd_guides" + before, Access::Read},
                           // rgb and, in alpha, the final variance (the resolve writes both).
                           {"g_glint_history_radiance", "rd_radiance" + before, Access::Read},
                           {"g_glint_history_length", "rd_length" + before, Access::Read},
                           {"g_glint_clamped", "rd_clamped", Access::Write},
                           {"g_glint_reprojected", "rd_reprojected", Access::Write},
                           {"g_glint_variance", "rd_variance" + now, Access::Write},
                           {"g_glint_length", "rd_length" + now, Access::Write},
                           {"g_glint_guides", "rd_guides" + now, Access::Write},
                           {"g_glint_average", "rd_average", Access::Write},
                           {"g_glint_tile_mask", "rd_tile_mask" + now, Access::ReadWrite}});
    reproject.zeroBuffers = {"rd_tile_mask" + now};
    Pass prefilter = tilePass("prefilter", half ? "rd_prefilter.half" : "rd_prefilter", constants);
    // rd_clamped carries the temporal variance in alpha (and flags pixels that are not glossy).
    prefilter.uses.insert(prefilter.uses.end(), {{"g_glint_average", "rd_average", Access::Read},
                                                 {"g_glint_tile_mask", "rd_tile_mask" + now, Access::Read},
                                                 {"g_glint_clamped", "rd_clamped", Access::Read},
                                                 {"g_glint_prefiltered", "rd_prefiltered", Access::Write}});
    Pass resolve = tilePass("resolve", half ? "rd_resolve.half" : "rd_resolve", constants, false);
    // The resolve reads the roughness alone of the surface: mirrors are resolved differently.
    resolve.uses.insert(resolve.uses.end(), {{"g_glint_roughness", "sssr_roughness", Access::Read},
                                             {"g_glint_average", "rd_average", Access::Read},
                                             {"g_glint_tile_mask", "rd_tile_mask" + now, Access::Read},
                                             {"g_glint_prefiltered", "rd_prefiltered", Access::Read},
                                             {"g_glint_reprojected", "rd_reprojected", Access::Read},
                                             // Read, and written back shortened by the anti-lag.
                                             {"g_glint_length", "rd_length" + now, Access::ReadWrite},
                                             {"g_glint_output", "sssr_radiance", Access::ReadWrite},
                                             {"g_glint_radiance_history", "rd_radiance" + now, Access::Write},
                                             {"g_glint_variance", "rd_variance" + now, Access::ReadWrite}});
    if (desc.spatialPath == SpatialPath::Prefilter) {
        plan.passes = {reproject, prefilter, resolve};
        return Result::Ok;
    }

    // Ratio-estimator path: the reconstruction takes the prefilter's place (and its output image),
    // the cleanup follows the resolve.
    shaders::GLINT_ReflectionsDenoiserRatioConstants ratio{};
    ratio.common = c;
    for (std::size_t row = 0; row < 3; ++row)
        ratio.worldFromView[row] = {static_cast<float>(worldFromView[4 * row]),
                                    static_cast<float>(worldFromView[4 * row + 1]),
                                    static_cast<float>(worldFromView[4 * row + 2]), 0.0f};
    ratio.frameIndex = desc.frameIndex;
    ratio.reconstructionRadius = desc.reconstructionRadius;
    ratio.cleanupSigma = desc.cleanupSigma;
    const std::vector<std::byte> ratioConstants = core::packConstants(ratio);
    Pass reconstruct =
        tilePass("reconstruct", half ? "rd_reconstruct.half" : "rd_reconstruct", ratioConstants);
    reconstruct.uses.insert(reconstruct.uses.end(),
                            {{"g_glint_clamped", "rd_clamped", Access::Read},
                             {"g_glint_rays", "sssr_rays", Access::Read},
                             {"g_glint_variance", "rd_variance" + now, Access::Read},
                             {"g_glint_reconstructed", "rd_prefiltered", Access::Write}});
    Pass cleanup = tilePass("cleanup", half ? "rd_cleanup.half" : "rd_cleanup", ratioConstants);
    cleanup.uses.insert(cleanup.uses.end(), {{"g_glint_resolved", "rd_radiance" + now, Access::Read},
                                             {"g_glint_variance", "rd_variance" + now, Access::Read},
                                             {"g_glint_output", "sssr_radiance", Access::ReadWrite}});
    plan.passes = {reproject, reconstruct, resolve, cleanup};
    return Result::Ok;
}

} // namespace glint
