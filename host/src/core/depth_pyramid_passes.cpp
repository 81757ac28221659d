// The depth pyramid as data: sizes, the one pass, its resources.
#include "glint/glint_depth_pyramid.h"

#include "core/dispatch.h"
#include "core/plan_checks.h"
#include "glint/depth_pyramid/glint_depth_pyramid_constants.h"

#include <algorithm>
#include <bit>

namespace glint {
namespace {

constexpr std::uint32_t kTile = 64; // a group's tile of level 0: levels 1-6 need 2^6 texels

constexpr std::uint32_t roundUpToTile(std::uint32_t value) {
    return core::divideRoundUp(value, kTile) * kTile;
}

Result invalid(std::string* error, const std::string& message) {
    return core::invalidArgument(error, "depth pyramid", message);
}

const char* pipelineFor(const DepthPyramidDesc& desc) {
    const bool reversed = desc.depth == DepthConvention::Reversed;
    if (desc.channels == DepthPyramidChannels::ClosestAndFarthest)
        return reversed ? "depth_pyramid_build.reversed_farthest" : "depth_pyramid_build.farthest";
    return reversed ? "depth_pyramid_build.reversed" : "depth_pyramid_build";
}

} // namespace

DepthPyramidLayout depthPyramidLayout(Extent2D size, std::uint32_t requestedLevels) {
    DepthPyramidLayout layout;
    layout.level0 = {roundUpToTile(std::max(size.width, 1u)), roundUpToTile(std::max(size.height, 1u))};
    // The ordinary mip chain of a W0 x H0 image: 1 + floor(log2(max(W0, H0))) levels.
    layout.fullLevelCount =
        static_cast<std::uint32_t>(std::bit_width(std::max(layout.level0.width, layout.level0.height)));
    layout.levelCount =
        requestedLevels == 0 ? layout.fullLevelCount : std::min(requestedLevels, layout.fullLevelCount);
    return layout;
}

Result planDepthPyramid(const DepthPyramidDesc& desc, EffectPlan& plan, std::string* error) {
    if (!core::validExtent(desc.size)) return invalid(error, "size must be 1..16384 in each dimension");
    const DepthPyramidLayout layout = depthPyramidLayout(desc.size, desc.levelCount);
    if (desc.levelCount > layout.fullLevelCount)
        return invalid(error, "levelCount " + std::to_string(desc.levelCount) +
                                  " exceeds the full chain of " + std::to_string(layout.fullLevelCount) +
                                  " levels");
    static_assert(GLINT_DEPTH_PYRAMID_MAX_LEVELS >= 15,
                  "the shader must have a slot for every level of 16384");

    Pass pass;
    pass.name = "build";
    pass.pipeline = pipelineFor(desc);
    pass.groupSize[0] = 256;
    pass.groupSize[1] = 1;
    pass.groupSize[2] = 1;
    const DirectDispatch grid{layout.level0.width / kTile, layout.level0.height / kTile, 1};
    pass.dispatch = grid;

    shaders::GLINT_DepthPyramidConstants constants{};
    constants.inputSize = {desc.size.width, desc.size.height};
    constants.level0Size = {layout.level0.width, layout.level0.height};
    constants.levelCount = layout.levelCount;
    constants.groupCount = grid.groupsX * grid.groupsY;
    constants.farDepth = desc.depth == DepthConvention::Reversed ? 0.0f : 1.0f;
    constants.writeLevel0 = desc.copyLevel0 ? 1u : 0u;
    pass.constantsBinding = "g_glint_constants";
    pass.constants = core::packConstants(constants);

    pass.uses = {{"g_glint_depth", "depth", Access::Read},
                 {"g_glint_pyramid", "depth_pyramid", Access::Write}};

    plan = EffectPlan{};
    plan.effect = "depth_pyramid";
    plan.size = desc.size;
    plan.images.push_back(
        {"depth_pyramid", layout.level0.width, layout.level0.height, layout.levelCount,
         desc.channels == DepthPyramidChannels::ClosestAndFarthest ? Format::RG32Float : Format::R32Float});
    // The counter exists only for the last-group pattern; the shader binds it regardless, so
    // a 4-byte buffer is still needed, but it is only zeroed when it is used.
    plan.buffers.push_back({"depth_pyramid_counter", 4, false});
    pass.uses.push_back({"g_glint_counter", "depth_pyramid_counter", Access::ReadWrite});
    if (layout.levelCount > GLINT_DEPTH_PYRAMID_TILE_LEVELS) pass.zeroBuffers = {"depth_pyramid_counter"};
    plan.passes.push_back(std::move(pass));
    return Result::Ok;
}

} // namespace glint
