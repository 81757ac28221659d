// The shadow denoiser as data: sizes, passes, resources.
#include "glint/glint_shadow_denoiser.h"

#include "core/camera.h"
#include "core/dispatch.h"
#include "core/plan_checks.h"
#include "glint/shadow_denoiser/glint_shadow_denoiser_constants.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <string_view>

namespace glint {
namespace {

// Classification lists the tiles the filter works on (indirect dispatch) and writes the clear
// tiles' output itself.
bool usesTileList(const ShadowDenoiserDesc& desc) {
    return desc.classify && desc.filter && desc.skipClearedTiles;
}

Result invalid(std::string* error, const std::string& message) {
    return core::invalidArgument(error, "shadow denoiser", message);
}

bool supportedOutputFormat(Format format) {
    return format == Format::R8Unorm || format == Format::R16Float || format == Format::RG32Float;
}

// The permutation of `pipeline` that stores the final output in desc.outputFormat
// (hlsl/CMakeLists.txt): "_r16f"/"_r8" after a suffix, ".r16f"/".r8" on a bare module name.
// Only the passes that write "shadow_output" take it; the scratch images stay RG32F.
std::string outputPipeline(const ShadowDenoiserDesc& desc, const std::string& pipeline) {
    if (desc.outputFormat == Format::RG32Float) return pipeline;
    const char* format = desc.outputFormat == Format::R8Unorm ? "r8" : "r16f";
    return pipeline + (pipeline.find('.') == std::string::npos ? "." : "_") + format;
}

bool positiveFinite(float value) {
    return std::isfinite(value) && value > 0.0f;
}

shared::float4 viewDepthCoefficients(const ShadowDenoiserDesc& desc) {
    return core::viewDepthCoefficients(desc.depth == ShadowDenoiserDepth::Reversed, desc.nearPlane,
                                       desc.farPlane);
}

// The constants' penumbraScale: 2 tan(light radius) / pixel angle, or -1 without an estimate
// (glint_shadow_denoiser_penumbra.hlsli).
float penumbraScale(const ShadowDenoiserDesc& desc) {
    return shadowPenumbraKnown(desc) ? 2.0f * desc.lightTanHalfAngle / desc.pixelAngularSize : -1.0f;
}

// The blocker distance binding of classification and the filter: the shaders read it only with
// a light of positive size; otherwise the depth stands in.
ResourceUse blockerDistanceUse(const ShadowDenoiserDesc& desc) {
    return {"g_glint_blocker_distance",
            shadowPenumbraActive(desc) ? "shadow_blocker_distance" : "shadow_depth", Access::Read};
}

Pass preparePass(const ShadowDenoiserDesc& desc, Extent2D tiles) {
    Pass pass;
    pass.name = "prepare";
    pass.pipeline = "shadow_denoiser_prepare";
    pass.groupSize[0] = GLINT_SHADOW_DENOISER_PREPARE_GROUP_WIDTH;
    pass.groupSize[1] = GLINT_SHADOW_DENOISER_PREPARE_GROUP_HEIGHT;
    pass.groupSize[2] = 1;
    pass.dispatch =
        DirectDispatch{core::divideRoundUp(tiles.width, GLINT_SHADOW_DENOISER_PREPARE_GROUP_TILES_X),
                       core::divideRoundUp(tiles.height, GLINT_SHADOW_DENOISER_PREPARE_GROUP_HEIGHT), 1};
    shaders::GLINT_ShadowDenoiserPrepareConstants constants{};
    constants.inputSize = {desc.size.width, desc.size.height};
    constants.maskTilesX = tiles.width;
    constants.maskTilesY = tiles.height;
    pass.constantsBinding = "g_glint_constants";
    pass.constants = core::packConstants(constants);
    pass.uses = {{"g_glint_visibility", "shadow_visibility", Access::Read},
                 {"g_glint_shadow_mask", "shadow_mask", Access::Write}};
    if (usesTileList(desc)) {
        pass.pipeline = "shadow_denoiser_prepare.list";
        pass.uses.push_back({"g_glint_filter_args", "shadow_filter_args", Access::Write});
    }
    return pass;
}

Pass filterPass(const ShadowDenoiserDesc& desc, std::uint32_t index, const char* input, const char* output) {
    Pass pass;
    pass.name = "filter" + std::to_string(index);
    pass.pipeline = "shadow_denoiser_filter";
    pass.groupSize[0] = GLINT_SHADOW_DENOISER_FILTER_TILE;
    pass.groupSize[1] = GLINT_SHADOW_DENOISER_FILTER_TILE;
    pass.groupSize[2] = 1;
    pass.dispatch = core::gridFor(desc.size.width, desc.size.height, 1, pass.groupSize);
    shaders::GLINT_ShadowDenoiserFilterConstants constants{};
    constants.inputSize = {desc.size.width, desc.size.height};
    constants.step = 1u << index;
    constants.finalPass = index == 2 && desc.contrastRemap ? 1u : 0u;
    constants.viewDepth = viewDepthCoefficients(desc);
    constants.normalUnpack = {desc.normalUnpackMul, desc.normalUnpackAdd};
    constants.depthSigma = desc.depthSigma;
    constants.normalPower = desc.normalPower;
    constants.penumbraScale = penumbraScale(desc);
    pass.constantsBinding = "g_glint_constants";
    pass.constants = core::packConstants(constants);
    pass.uses = {{"g_glint_filter_input", input, Access::Read},
                 {"g_glint_depth", "shadow_depth", Access::Read},
                 {"g_glint_normals", "shadow_normals", Access::Read},
                 {"g_glint_filter_output", output, Access::Write}};
    if (desc.classify && desc.skipClearedTiles) {
        pass.uses.push_back({"g_glint_tile_metadata", shadowTileMetadataName(desc.frameIndex), Access::Read});
        pass.uses.push_back({"g_glint_filter_work", "shadow_filter_work", Access::ReadWrite});
        if (index == 0) pass.zeroBuffers = {"shadow_filter_work"};
    }
    // Tile skipping always goes through the tile list.
    if (usesTileList(desc)) {
        pass.pipeline = "shadow_denoiser_filter.list";
        pass.dispatch = IndirectDispatch{"shadow_filter_args", 0};
        pass.uses.push_back({"g_glint_filter_tiles", "shadow_filter_tiles", Access::Read});
        // Classification wrote the clear tiles of the output; this pass adds the listed ones.
        if (index == 2) pass.uses[3].access = Access::ReadWrite;
    }
    pass.uses.push_back(blockerDistanceUse(desc));
    if (std::string_view(output) == "shadow_output") pass.pipeline = outputPipeline(desc, pass.pipeline);
    return pass;
}

Pass classifyPass(const ShadowDenoiserDesc& desc, Extent2D tiles) {
    Pass pass;
    pass.name = "classify";
    pass.pipeline = "shadow_denoiser_classify";
    pass.dispatch = core::gridFor(desc.size.width, desc.size.height, 1, pass.groupSize);
    shaders::GLINT_ShadowDenoiserClassifyConstants constants{};
    constants.inputSize = {desc.size.width, desc.size.height};
    constants.maskTiles = {tiles.width, tiles.height};
    core::storeRows(desc.reprojection, constants.reproject);
    core::storeRows(desc.inverseViewProjection, constants.inverseViewProj);
    constants.eyePosition = {desc.eyePosition[0], desc.eyePosition[1], desc.eyePosition[2], 0.0f};
    constants.storedVarianceScale = shadowStoredVarianceScale(desc);
    constants.penumbraScale = penumbraScale(desc);
    constants.viewDepth = viewDepthCoefficients(desc);
    constants.normalUnpack = {desc.normalUnpackMul, desc.normalUnpackAdd};
    constants.ndcYSign = desc.vulkanNdc ? 1.0f : -1.0f;
    constants.flags = desc.resetHistory ? GLINT_SHADOW_DENOISER_CLASSIFY_FLAG_RESET : 0u;
    if (desc.antiLag) constants.flags |= GLINT_SHADOW_DENOISER_CLASSIFY_FLAG_ANTI_LAG;
    if (desc.rebuildClearHistory) constants.flags |= GLINT_SHADOW_DENOISER_CLASSIFY_FLAG_REBUILD_CLEAR;
    pass.constantsBinding = "g_glint_constants";
    pass.constants = core::packConstants(constants);
    const bool odd = (desc.frameIndex & 1u) != 0;
    pass.uses = {{"g_glint_shadow_mask", "shadow_mask", Access::Read},
                 {"g_glint_depth", "shadow_depth", Access::Read},
                 {"g_glint_previous_depth", "shadow_previous_depth", Access::Read},
                 {"g_glint_normals", "shadow_normals", Access::Read},
                 {"g_glint_motion", "shadow_motion", Access::Read},
                 {"g_glint_moments_history", odd ? "shadow_moments0" : "shadow_moments1", Access::Read},
                 {"g_glint_previous_metadata", shadowTileMetadataName(desc.frameIndex + 1), Access::Read},
                 {"g_glint_tile_metadata", shadowTileMetadataName(desc.frameIndex), Access::Write},
                 {"g_glint_shadow_variance", "shadow_scratch0", Access::Write},
                 {"g_glint_moments", odd ? "shadow_moments1" : "shadow_moments0", Access::Write},
                 blockerDistanceUse(desc)};
    if (usesTileList(desc)) {
        // It writes the clear tiles' final output.
        pass.pipeline = outputPipeline(desc, "shadow_denoiser_classify.list");
        pass.uses.push_back({"g_glint_filter_args", "shadow_filter_args", Access::ReadWrite});
        pass.uses.push_back({"g_glint_filter_tiles", "shadow_filter_tiles", Access::Write});
        pass.uses.push_back({"g_glint_filter_output", "shadow_output", Access::Write});
    }
    return pass;
}

// Keeps the uses of the named bindings only.
void keepBindings(Pass& pass, std::initializer_list<const char*> bindings) {
    std::erase_if(pass.uses, [&](const ResourceUse& use) {
        return std::none_of(bindings.begin(), bindings.end(),
                            [&](const char* name) { return use.binding == name; });
    });
}

// Classification in two dispatches (ShadowDenoiserDesc::splitClassify): "classify" tests every
// tile, 2 x 2 tiles a group, and writes the metadata, the tile list and the clear tiles'
// output; "temporal" runs the rest on the listed tiles, indirectly from the list.
void pushSplitClassify(const ShadowDenoiserDesc& desc, Extent2D tiles, EffectPlan& plan) {
    const Pass whole = classifyPass(desc, tiles);
    Pass classify = whole;
    classify.pipeline = outputPipeline(desc, "shadow_denoiser_classify.tiles");
    classify.groupSize[2] = GLINT_SHADOW_DENOISER_CLASSIFY_TILE_BLOCKS;
    classify.dispatch = DirectDispatch{
        core::divideRoundUp(desc.size.width, 8 * GLINT_SHADOW_DENOISER_CLASSIFY_TILE_BLOCKS_X),
        core::divideRoundUp(desc.size.height, 8 * GLINT_SHADOW_DENOISER_CLASSIFY_TILE_BLOCKS_Y), 1};
    keepBindings(classify,
                 {"g_glint_shadow_mask", "g_glint_depth", "g_glint_tile_metadata", "g_glint_moments",
                  "g_glint_filter_args", "g_glint_filter_tiles", "g_glint_filter_output"});
    Pass temporal = whole;
    temporal.name = "temporal";
    temporal.pipeline = "shadow_denoiser_classify.listed";
    temporal.dispatch = IndirectDispatch{"shadow_filter_args", 0};
    keepBindings(temporal, {"g_glint_shadow_mask", "g_glint_depth", "g_glint_previous_depth",
                            "g_glint_normals", "g_glint_motion", "g_glint_moments_history",
                            "g_glint_previous_metadata", "g_glint_shadow_variance", "g_glint_moments",
                            "g_glint_filter_tiles", "g_glint_blocker_distance"});
    for (ResourceUse& use : temporal.uses)
        if (use.binding == "g_glint_filter_tiles") use.access = Access::Read;
    plan.passes.push_back(std::move(classify));
    plan.passes.push_back(std::move(temporal));
}

} // namespace

std::string shadowTileMetadataName(std::uint32_t frameIndex) {
    return (frameIndex & 1u) != 0 ? "shadow_tile_metadata1" : "shadow_tile_metadata0";
}

Extent2D shadowMaskTiles(Extent2D size) {
    return {core::divideRoundUp(size.width, GLINT_SHADOW_DENOISER_MASK_TILE_WIDTH),
            core::divideRoundUp(size.height, GLINT_SHADOW_DENOISER_MASK_TILE_HEIGHT)};
}

bool shadowPenumbraKnown(const ShadowDenoiserDesc& desc) {
    return desc.penumbraAware && desc.lightTanHalfAngle >= 0.0f && desc.pixelAngularSize > 0.0f &&
           std::isfinite(2.0f * desc.lightTanHalfAngle / desc.pixelAngularSize);
}

bool shadowPenumbraActive(const ShadowDenoiserDesc& desc) {
    return shadowPenumbraKnown(desc) && desc.lightTanHalfAngle > 0.0f;
}

float shadowStoredVarianceScale(const ShadowDenoiserDesc& desc) {
    if (desc.storedVarianceScale > 0.0f) return desc.storedVarianceScale;
    // 1/16 up to 360 rows, where any more spatial filtering costs more in bias than it gains;
    // above, the filter's bias at a penumbra of a given angular size falls with the square of
    // its width in pixels (docs/shadow_denoiser.md, "The filter strength and the resolution").
    const float rows = static_cast<float>(desc.size.height) / 360.0f;
    return 0.0625f * std::max(rows * rows, 1.0f);
}

Result planShadowDenoiser(const ShadowDenoiserDesc& desc, EffectPlan& plan, std::string* error) {
    if (!core::validExtent(desc.size)) return invalid(error, "size must be 1..16384 in each dimension");
    if (!positiveFinite(desc.nearPlane)) return invalid(error, "nearPlane must be positive and finite");
    const bool infiniteFar = desc.depth == ShadowDenoiserDepth::Reversed && !(desc.farPlane > 0.0f);
    if (!infiniteFar && !(std::isfinite(desc.farPlane) && desc.farPlane > desc.nearPlane))
        return invalid(error, "farPlane must be finite and beyond nearPlane");
    if (!(desc.depthSigma >= 1e-6f && std::isfinite(desc.depthSigma)))
        return invalid(error, "depthSigma must be finite and >= 1e-6");
    if (!(desc.normalPower >= 1.0f && desc.normalPower <= 256.0f))
        return invalid(error, "normalPower must be 1..256");
    if (!(desc.storedVarianceScale >= 0.0f && std::isfinite(desc.storedVarianceScale)))
        return invalid(error, "storedVarianceScale must be finite and >= 0 (0: automatic)");
    if (!std::isfinite(desc.lightTanHalfAngle))
        return invalid(error, "lightTanHalfAngle must be finite (< 0: unknown)");
    if (!(desc.pixelAngularSize >= 0.0f && std::isfinite(desc.pixelAngularSize)))
        return invalid(error, "pixelAngularSize must be finite and >= 0 (0: unknown)");
    if (!std::isfinite(desc.normalUnpackMul) || !std::isfinite(desc.normalUnpackAdd))
        return invalid(error, "normal unpack factors must be finite");

    if (!supportedOutputFormat(desc.outputFormat))
        return invalid(error, "outputFormat must be R8Unorm, R16Float or RG32Float");

    if (!core::isFinite(desc.reprojection) || !core::isFinite(desc.inverseViewProjection))
        return invalid(error, "camera matrices must be finite");

    const Extent2D tiles = shadowMaskTiles(desc.size);
    plan = EffectPlan{};
    plan.effect = "shadow_denoiser";
    plan.size = desc.size;
    plan.buffers.push_back({"shadow_mask", std::uint64_t{tiles.width} * tiles.height * 4u, false});
    plan.passes.push_back(preparePass(desc, tiles));
    const std::uint32_t w = desc.size.width;
    const std::uint32_t h = desc.size.height;
    if (desc.classify || desc.filter) plan.images.push_back({"shadow_scratch0", w, h, 1, Format::RG32Float});
    if (desc.filter) plan.images.push_back({"shadow_scratch1", w, h, 1, Format::RG32Float});
    if (desc.classify) {
        const std::uint64_t tileCount =
            std::uint64_t{core::divideRoundUp(w, GLINT_SHADOW_DENOISER_FILTER_TILE)} *
            core::divideRoundUp(h, GLINT_SHADOW_DENOISER_FILTER_TILE);
        plan.buffers.push_back({"shadow_tile_metadata0", tileCount * 4u, false});
        plan.buffers.push_back({"shadow_tile_metadata1", tileCount * 4u, false});
        plan.images.push_back({"shadow_moments0", w, h, 1, Format::RGBA32Float});
        plan.images.push_back({"shadow_moments1", w, h, 1, Format::RGBA32Float});
        if (usesTileList(desc) && desc.splitClassify)
            pushSplitClassify(desc, tiles, plan);
        else
            plan.passes.push_back(classifyPass(desc, tiles));
    }
    if (!desc.filter) return Result::Ok;
    plan.images.push_back({"shadow_output", w, h, 1, desc.outputFormat});
    if (desc.classify && desc.skipClearedTiles) plan.buffers.push_back({"shadow_filter_work", 4, false});
    if (usesTileList(desc)) {
        const std::uint64_t tileCount =
            std::uint64_t{core::divideRoundUp(w, GLINT_SHADOW_DENOISER_FILTER_TILE)} *
            core::divideRoundUp(h, GLINT_SHADOW_DENOISER_FILTER_TILE);
        plan.buffers.push_back({"shadow_filter_tiles", tileCount * 4u, false});
        plan.buffers.push_back({"shadow_filter_args", 12, true});
    }
    const char* input = desc.classify ? "shadow_scratch0" : "shadow_filter_input";
    if (desc.pairedFilter) {
        // Steps 1 and 2 in one dispatch ("filter01"), into scratch 1; step 4 reads it.
        Pass pair = filterPass(desc, 0, input, "shadow_scratch1");
        pair.name = "filter01";
        pair.pipeline =
            usesTileList(desc) ? "shadow_denoiser_filter.pair_list" : "shadow_denoiser_filter.pair";
        plan.passes.push_back(std::move(pair));
        plan.passes.push_back(filterPass(desc, 2, "shadow_scratch1", "shadow_output"));
        return Result::Ok;
    }
    plan.passes.push_back(filterPass(desc, 0, input, "shadow_scratch1"));
    plan.passes.push_back(filterPass(desc, 1, "shadow_scratch1", "shadow_scratch0"));
    plan.passes.push_back(filterPass(desc, 2, "shadow_scratch0", "shadow_output"));
    return Result::Ok;
}

} // namespace glint
