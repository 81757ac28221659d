// The hierarchical depth pyramid as an effect (glint_depth_pyramid.h): the whole min/max chain
// of the frame's depth, every level an output.
#include "core/effects/effect_tables.h"

#include "glint/glint_depth_pyramid.h"
#include "glint/glint_effect.h"

namespace glint {
namespace {

std::vector<SettingDesc> pyramidSettings() {
    return {core::boolSetting("pyramid.closestAndFarthest", false,
                              "RG32F pyramid: closest depth in R, farthest in G",
                              "DepthPyramidDesc::channels"),
            core::uintSetting("pyramid.levelCount", 0, 0, 16, "levels built; 0: the full chain down to 1x1",
                              "DepthPyramidDesc::levelCount"),
            core::boolSetting("pyramid.copyLevel0", true,
                              "copy the depth into level 0; false: level 0 is left unwritten",
                              "DepthPyramidDesc::copyLevel0")};
}

Result planPyramid(const FrameInfo& frame, const SettingValues& settings, EffectPlan& plan,
                   std::string* error) {
    DepthPyramidDesc desc;
    desc.size = frame.size;
    desc.depth = frame.depth;
    desc.channels = settings.flag("pyramid.closestAndFarthest") ? DepthPyramidChannels::ClosestAndFarthest
                                                                : DepthPyramidChannels::Closest;
    desc.levelCount = settings.count("pyramid.levelCount");
    desc.copyLevel0 = settings.flag("pyramid.copyLevel0");
    if (const Result result = planDepthPyramid(desc, plan, error); result != Result::Ok) return result;
    plan.outputs.push_back({"mip", "depth_pyramid", "build", OutputDecoder::MipChain, 0, 1, 0});
    return Result::Ok;
}

} // namespace

const EffectDescriptor& depthPyramidEffect() {
    static const EffectDescriptor descriptor{
        "depth_pyramid",
        "hierarchical min/max depth pyramid",
        pyramidSettings(),
        {{"depth", InputKind::Depth, ""}},
        planPyramid,
        {"pyramid.closestAndFarthest", "pyramid.levelCount", "pyramid.copyLevel0"},
        "",
        "",
        {.previews = {{"mip", Preview::FiniteRange}},
         .reportImages = {"mip1"},
         .bench = EffectBench{"harness/scenes/glossy_room.toml", "reflections"}},
    };
    return descriptor;
}

} // namespace glint
