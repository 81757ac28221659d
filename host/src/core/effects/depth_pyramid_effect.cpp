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
                              "DepthPyramidDesc::channels")};
}

Result planPyramid(const FrameInfo& frame, const SettingValues& settings, EffectPlan& plan,
                   std::string* error) {
    DepthPyramidDesc desc;
    desc.size = frame.size;
    desc.depth = frame.depth;
    desc.channels = settings.flag("pyramid.closestAndFarthest") ? DepthPyramidChannels::ClosestAndFarthest
                                                                : DepthPyramidChannels::Closest;
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
        {"pyramid.closestAndFarthest"},
        "",
        "",
        {.previews = {{"mip", Preview::FiniteRange}}, .reportImages = {"mip1"}},
    };
    return descriptor;
}

} // namespace glint
