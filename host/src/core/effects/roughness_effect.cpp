// Roughness extraction as an effect (glint_gbuffer.h): the material channel holding roughness,
// converted to GGX alpha once.
#include "core/effects/effect_tables.h"

#include "glint/glint_effect.h"
#include "glint/glint_gbuffer.h"

namespace glint {
namespace {

std::vector<SettingDesc> roughnessSettings() {
    return {core::boolSetting("roughness.halfPrecisionOutput", false, "writes R16F instead of R32F",
                              "RoughnessExtractionDesc::halfPrecisionOutput")};
}

Result planRoughness(const FrameInfo& frame, const SettingValues& settings, EffectPlan& plan,
                     std::string* error) {
    RoughnessExtractionDesc desc;
    desc.size = frame.size;
    desc.materialChannel = frame.materialChannel;
    desc.inputIsPerceptual = frame.roughnessIsPerceptual;
    desc.halfPrecisionOutput = settings.flag("roughness.halfPrecisionOutput");
    if (const Result result = planRoughnessExtraction(desc, plan, error); result != Result::Ok) return result;
    plan.outputs.push_back({"alpha", "roughness", "extract_roughness", OutputDecoder::Channels, 0, 1});
    return Result::Ok;
}

// Not scored (no capture holds a reference roughness): checked, shown in a report, timed by
// glint study --effect roughness at full and half precision and by glint bench roughness.
EffectEvaluation roughnessEvaluation() {
    EffectEvaluation evaluation;
    // One multiply per pixel: exact in R32F; R16F output rounds to its 11-bit mantissa.
    evaluation.tolerances = {{"extract_roughness", 0.0, 1e-3, 0.0}};
    evaluation.reportImages = {"alpha"};
    EffectStudy study;
    study.points = {{"defaults", {}, true}, {"half_output", {"roughness.halfPrecisionOutput=true"}, true}};
    study.scenes = {"harness/scenes/glossy_room.toml"};
    study.simulateAs = "reflections"; // renders the material layer it reads
    evaluation.study = std::move(study);
    evaluation.bench = EffectBench{"harness/scenes/glossy_room.toml", "reflections"};
    return evaluation;
}

} // namespace

const EffectDescriptor& roughnessEffect() {
    static const EffectDescriptor descriptor{
        "roughness",
        "GGX alpha from the material's roughness channel",
        roughnessSettings(),
        {{"material", InputKind::Material, ""}},
        planRoughness,
        {"roughness.halfPrecisionOutput"},
        "",
        "",
        roughnessEvaluation(),
    };
    return descriptor;
}

} // namespace glint
