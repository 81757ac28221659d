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
        {},
    };
    return descriptor;
}

} // namespace glint
