// The G-buffer preparation passes as data.
#include "glint/glint_gbuffer.h"

#include "core/dispatch.h"
#include "core/plan_checks.h"
#include "glint/gbuffer/glint_gbuffer_constants.h"

namespace glint {

namespace {
Result invalid(std::string* error, const std::string& message) {
    return core::invalidArgument(error, "roughness extraction", message);
}
} // namespace

Result planRoughnessExtraction(const RoughnessExtractionDesc& desc, EffectPlan& plan, std::string* error) {
    if (!core::validExtent(desc.size)) return invalid(error, "size must be 1..16384 in each dimension");
    if (desc.materialChannel > 3) return invalid(error, "materialChannel must be 0..3");

    shaders::GLINT_GBufferRoughnessConstants constants{};
    constants.size = {desc.size.width, desc.size.height};
    constants.materialChannel = desc.materialChannel;
    constants.inputIsPerceptual = desc.inputIsPerceptual ? 1u : 0u;

    Pass pass;
    pass.name = "extract_roughness";
    pass.pipeline = desc.halfPrecisionOutput ? "gbuffer_extract_roughness.fp16" : "gbuffer_extract_roughness";
    pass.uses = {{"g_glint_material", "material", Access::Read},
                 {"g_glint_alpha", "roughness", Access::Write}};
    pass.constantsBinding = "g_glint_constants";
    pass.constants = core::packConstants(constants);
    pass.dispatch = core::gridFor(desc.size.width, desc.size.height, 1, pass.groupSize);

    plan = EffectPlan{};
    plan.effect = "gbuffer";
    plan.size = desc.size;
    plan.images.push_back({"roughness", desc.size.width, desc.size.height, 1,
                           desc.halfPrecisionOutput ? Format::R16Float : Format::R32Float});
    plan.passes.push_back(std::move(pass));
    return Result::Ok;
}

} // namespace glint
