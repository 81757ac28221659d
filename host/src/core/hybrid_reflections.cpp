// The hybrid effect composed: planHybrid, the reflections denoiser over its result, the
// composite, and the plan's outputs and counters (glint_hybrid.h).
#include "glint/glint_hybrid.h"

#include "core/pass_model.h"
#include "core/plan_checks.h"
#include "glint/hybrid/glint_hybrid_constants.h"

#include <algorithm>

namespace glint {
namespace {

void addOutputs(EffectPlan& plan, const HybridDesc& desc, const ReflectionsDenoiserDesc* denoiser) {
    const char* denoisedBy =
        denoiser && denoiser->spatialPath == SpatialPath::RatioEstimator ? "cleanup" : "resolve";
    auto& out = plan.outputs;
    out.push_back({"noisy", "sssr_radiance", "shade", OutputDecoder::Channels, 0, 3});
    if (denoiser) out.push_back({"denoised", "sssr_radiance", denoisedBy, OutputDecoder::Channels, 0, 3});
    if (desc.sssr.composite)
        out.push_back({"composite", "composite", "composite", OutputDecoder::Channels, 0, 3});
    out.push_back({"confidence", "sssr_confidence", "shade", OutputDecoder::Channels, 0, 1});
    const auto intermediate = [&](OutputDesc output) {
        output.intermediate = true;
        out.push_back(std::move(output));
    };
    intermediate({"roughness", "sssr_roughness", "classify", OutputDecoder::Channels, 0, 1});
    intermediate({"screen_space_result", "sssr_radiance", "intersect", OutputDecoder::Channels, 0, 3});
    intermediate({"ray_traced_list", "hybrid_hw_ray_list", "shade", OutputDecoder::RayList, 0, 1, 0,
                  "ray_traced_rays"});
    intermediate(
        {"tile_list", "sssr_tile_list", "classify", OutputDecoder::TileList, 0, 1, 0, "listed_tiles"});
    intermediate({"pyramid_mip", "depth_pyramid", "depth_pyramid", OutputDecoder::MipChain, 0, 1, 1});
    plan.counters.push_back({"screen_space_entries", "hybrid_counters", 1, ""});
    plan.counters.push_back(
        {"ray_traced_rays", "hybrid_counters", GLINT_HYBRID_COUNTER_HW_RAYS_COPY, "ray_traced_fraction"});
    plan.counters.push_back({"listed_tiles", "hybrid_counters", 3, ""});
    plan.counters.push_back({"reshaded_hits", "hybrid_counters", GLINT_HYBRID_COUNTER_RESHADED_COPY, ""});
    // With ray_traced_rays: the share of the rays that went to the ray tracer.
    plan.counters.push_back(
        {"screen_space_answers", "hybrid_counters", GLINT_HYBRID_COUNTER_SCREEN_SPACE_ANSWERS_COPY, ""});
}

} // namespace

Result planHybridReflections(const HybridDesc& desc, const ReflectionsDenoiserDesc* denoiser,
                             EffectPlan& plan, std::string* error) {
    if (denoiser && !desc.sssr.denoise)
        return core::invalidArgument(error, "hybrid", "a denoiser desc needs SssrDesc::denoise");
    HybridDesc hybrid = desc;
    hybrid.sssr.compositeReflection = "sssr_radiance";
    if (const Result result = planHybrid(hybrid, plan, error); result != Result::Ok) return result;
    if (hybrid.sssr.denoise) {
        // The variance the denoiser resolved last frame guides classification (as SSSR's).
        core::renameResource(plan.passes, "sssr_zero_variance",
                             reflectionsDenoiserVariance(hybrid.sssr.frameIndex + 1));
        std::erase_if(plan.images, [](const ImageDesc& image) { return image.name == "sssr_zero_variance"; });
        // With denoise but no denoiser desc this frame: the denoiser's resources, none of its passes.
        ReflectionsDenoiserDesc resourcesOnly;
        resourcesOnly.size = hybrid.sssr.size;
        resourcesOnly.halfPrecisionStorage = hybrid.sssr.halfPrecisionStorage;
        EffectPlan denoiserPlan;
        if (const Result result =
                planReflectionsDenoiser(denoiser ? *denoiser : resourcesOnly, denoiserPlan, error);
            result != Result::Ok)
            return result;
        // The hybrid counters and arguments start with SSSR's layout: the denoiser's tile count
        // is word 3 and its arguments are at byte 12.
        core::renameResource(denoiserPlan.passes, "sssr_indirect_args", "hybrid_indirect_args");
        // Before the composite, which must read the denoised reflection.
        if (denoiser) {
            const auto composite = std::find_if(plan.passes.begin(), plan.passes.end(),
                                                [](const Pass& pass) { return pass.name == "composite"; });
            plan.passes.insert(composite, denoiserPlan.passes.begin(), denoiserPlan.passes.end());
        }
        plan.images.insert(plan.images.end(), denoiserPlan.images.begin(), denoiserPlan.images.end());
        plan.buffers.insert(plan.buffers.end(), denoiserPlan.buffers.begin(), denoiserPlan.buffers.end());
    }
    addOutputs(plan, hybrid, denoiser);
    return Result::Ok;
}

} // namespace glint
