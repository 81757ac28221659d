// The shadow denoiser as an effect (glint_shadow_denoiser.h): the frame's camera gives the
// reprojection, the inverse view-projection and the eye position the classification needs.
#include "core/camera.h"
#include "core/effects/effect_tables.h"

#include "glint/glint_effect.h"
#include "glint/glint_shadow_denoiser.h"

#include <algorithm>
#include <cmath>

namespace glint {
namespace {

using core::boolSetting;
using core::floatSetting;

std::vector<SettingDesc> shadowSettings() {
    const ShadowDenoiserDesc s;
    return {
        boolSetting("shadows.filter", s.filter, "runs the a-trous filter passes",
                    "ShadowDenoiserDesc::filter"),
        boolSetting("shadows.classify", s.classify,
                    "temporal tile classification (a capture replay needs it)",
                    "ShadowDenoiserDesc::classify"),
        boolSetting("shadows.skipClearedTiles", s.skipClearedTiles,
                    "the filter skips tiles classification cleared", "ShadowDenoiserDesc::skipClearedTiles"),
        boolSetting("shadows.pairedFilter", s.pairedFilter, "filter iterations 1 and 2 in one dispatch",
                    "ShadowDenoiserDesc::pairedFilter"),
        boolSetting("shadows.splitClassify", s.splitClassify,
                    "classification in two dispatches (every tile, then listed tiles)",
                    "ShadowDenoiserDesc::splitClassify"),
        core::choiceSetting("shadows.outputFormat", 0, {"r8", "r16f", "rg32f"},
                            "format of the denoised shadow (rg32f adds its variance)",
                            "ShadowDenoiserDesc::outputFormat"),
        boolSetting("shadows.antiLag", s.antiLag, "shortens histories their neighbourhood contradicts",
                    "ShadowDenoiserDesc::antiLag"),
        boolSetting("shadows.rebuildClearHistory", s.rebuildClearHistory,
                    "clear tiles' histories rebuilt from tile metadata instead of stored",
                    "ShadowDenoiserDesc::rebuildClearHistory"),
        boolSetting("shadows.penumbraAware", s.penumbraAware,
                    "the filter's footprint follows the penumbra width (light size, blocker distance); "
                    "false: the full filter everywhere",
                    "ShadowDenoiserDesc::penumbraAware"),
        boolSetting("shadows.contrastRemap", s.contrastRemap, "contrast recovery in the last filter pass",
                    "ShadowDenoiserDesc::contrastRemap"),
        floatSetting("shadows.storedVarianceScale", s.storedVarianceScale, 0, 1e6,
                     "scale of the variance classification stores for the filter's edge stop (0: automatic "
                     "for the size)",
                     "ShadowDenoiserDesc::storedVarianceScale"),
        floatSetting("shadows.depthSigma", s.depthSigma, 1e-6, 1e6, "relative depth edge stop of the filter",
                     "ShadowDenoiserDesc::depthSigma"),
        floatSetting("shadows.normalPower", s.normalPower, 1, 256, "normal edge stop exponent of the filter",
                     "ShadowDenoiserDesc::normalPower"),
    };
}

const Format kOutputFormats[] = {Format::R8Unorm, Format::R16Float, Format::RG32Float};

Result invalid(std::string* error, const std::string& message) {
    if (error) *error = "shadows: " + message;
    return Result::InvalidArgument;
}

Result planShadows(const FrameInfo& frame, const SettingValues& settings, EffectPlan& plan,
                   std::string* error) {
    // The shadow denoiser reads motion in convention A as it is (ShadowDenoiserDesc has no
    // scale): refuse a scaled frame rather than reproject it wrongly.
    if (frame.motionScaleX != 1.0f || frame.motionScaleY != 1.0f)
        return invalid(error, "motion must be unscaled convention A (FrameInfo::motionScale 1, 1)");
    ShadowDenoiserDesc desc;
    desc.size = frame.size;
    desc.depth = frame.depth == DepthConvention::Standard ? ShadowDenoiserDepth::Standard
                                                          : ShadowDenoiserDepth::Reversed;
    desc.nearPlane = frame.nearPlane;
    desc.farPlane = frame.farPlane;
    desc.normalUnpackMul = frame.normalUnpackMul;
    desc.normalUnpackAdd = frame.normalUnpackAdd;
    desc.vulkanNdc = frame.vulkanNdc;
    desc.resetHistory = frame.resetHistory;
    desc.frameIndex = frame.frameIndex;
    const core::Matrix4 clipFromWorld = core::multiply(frame.projection, frame.viewFromWorld);
    core::Matrix4 worldFromClip{}, worldFromView{};
    if (!core::invert(clipFromWorld, worldFromClip) || !core::invert(frame.viewFromWorld, worldFromView))
        return invalid(error, "the camera's view-projection is not invertible");
    desc.inverseViewProjection = worldFromClip;
    desc.reprojection = core::multiply(frame.previousClipFromWorld, worldFromClip);
    desc.eyePosition = {static_cast<float>(worldFromView[3]), static_cast<float>(worldFromView[7]),
                        static_cast<float>(worldFromView[11])};

    desc.filter = settings.flag("shadows.filter");
    desc.classify = settings.flag("shadows.classify");
    desc.skipClearedTiles = settings.flag("shadows.skipClearedTiles");
    desc.pairedFilter = settings.flag("shadows.pairedFilter");
    desc.splitClassify = settings.flag("shadows.splitClassify");
    desc.outputFormat = kOutputFormats[settings.choice("shadows.outputFormat")];
    desc.antiLag = settings.flag("shadows.antiLag");
    desc.rebuildClearHistory = settings.flag("shadows.rebuildClearHistory");
    desc.contrastRemap = settings.flag("shadows.contrastRemap");
    desc.storedVarianceScale = settings.real("shadows.storedVarianceScale");
    desc.depthSigma = settings.real("shadows.depthSigma");
    desc.normalPower = settings.real("shadows.normalPower");
    desc.penumbraAware = settings.flag("shadows.penumbraAware");
    // The penumbra estimate's light and pixel sizes; either unknown (light < 0, pixel 0) keeps
    // the full temporal stage and filter; a light of size 0 passes every receiver through.
    desc.lightTanHalfAngle =
        std::isfinite(frame.shadowLightTanHalfAngle) && frame.shadowLightTanHalfAngle >= 0.0f
            ? frame.shadowLightTanHalfAngle
            : -1.0f;
    const double focalY = std::abs(frame.projection[5]); // 1 / tan(fovY / 2)
    const double pixelAngle = 2.0 / (focalY * static_cast<double>(frame.size.height));
    desc.pixelAngularSize =
        std::isfinite(pixelAngle) && pixelAngle > 0.0 ? static_cast<float>(pixelAngle) : 0.0f;
    if (!desc.classify)
        return invalid(error, "needs shadows.classify=true (the filter alone reads a (mean, variance) image "
                              "no frame carries)");
    if (const Result result = planShadowDenoiser(desc, plan, error); result != Result::Ok) return result;
    plan.effect = "shadows";

    const std::uint32_t parity = frame.frameIndex & 1u;
    const std::string moments = parity != 0 ? "shadow_moments1" : "shadow_moments0";
    if (desc.filter) {
        const char* last = "filter2";
        plan.outputs.push_back({"denoised", "shadow_output", last, OutputDecoder::Channels, 0, 1});
        if (desc.outputFormat == Format::RG32Float)
            plan.outputs.push_back({"variance", "shadow_output", last, OutputDecoder::Channels, 1, 1});
    } else {
        plan.outputs.push_back({"denoised", "shadow_scratch0", "classify", OutputDecoder::Channels, 0, 1});
        plan.outputs.push_back({"variance", "shadow_scratch0", "classify", OutputDecoder::Channels, 1, 1});
    }
    OutputDesc mask{"mask", "shadow_mask", "prepare", OutputDecoder::ShadowMask};
    OutputDesc classes{"tile_class", shadowTileMetadataName(frame.frameIndex), "classify",
                       OutputDecoder::ShadowTileClass};
    // With the classification split, its "temporal" part writes the listed tiles' moments after
    // "classify": read them there, or a dump shows last frame's.
    const bool split = std::any_of(plan.passes.begin(), plan.passes.end(),
                                   [](const Pass& pass) { return pass.name == "temporal"; });
    OutputDesc history{"moments", moments, split ? "temporal" : "classify", OutputDecoder::Channels, 0, 3};
    for (OutputDesc* output : {&mask, &classes, &history}) {
        output->intermediate = true;
        plan.outputs.push_back(*output);
    }
    if (desc.filter && desc.skipClearedTiles)
        plan.counters.push_back({"filtered_tiles", "shadow_filter_work", 0, ""});
    return Result::Ok;
}

// Scored against reference.shadow over every receiver (a pixel with a surface); its previews
// show the non-receivers lit, the value the visibility input and the denoiser give them
// (docs/shadow_denoiser.md, "Non-receivers"). The sweep changes one setting at a time: the
// neighbourhood size is fixed in the shader, and the filter's only control is on or off.
EffectEvaluation shadowsEvaluation() {
    EffectEvaluation evaluation;
    evaluation.scored = {{.final = {"denoised"},
                          .noisy = "noisy",
                          .metric = ErrorMetric::Visibility,
                          .mask = {ErrorMask::Pixels::Surface, ""},
                          .errorHeatScale = 0.5f,
                          .outsideMaskShownAs = {"noisy", "denoised", "reference"},
                          .outsideMaskValue = 1.0f,
                          .maskInWords = "every pixel with a surface; the sky, where nothing receives a "
                                         "shadow, is left out and drawn lit in the shadow images"}};
    evaluation.previews = {{"tile_class", Preview::Categories},
                           {"mask", Preview::Categories},
                           {"variance", Preview::HeatPercentile99}};
    // Classification and the filter are float arithmetic that compilers round differently in
    // the last bits; preparation and the inputs are exact.
    evaluation.tolerances = {{"classify", 1e-4, 1e-3, 0.001}, {"filter*", 1e-4, 1e-3, 0.001}};
    evaluation.reportImages = {"input", "noisy", "denoised", "composite", "reference", "error"};
    EffectStudy study;
    study.points = {{"defaults", {}, true},
                    {"filter_off", {"shadows.filter=false"}, true},
                    {"no_tile_skip", {"shadows.skipClearedTiles=false"}},
                    {"no_anti_lag", {"shadows.antiLag=false"}},
                    {"no_penumbra_aware", {"shadows.penumbraAware=false"}},
                    {"filter_variance_0.0625", {"shadows.storedVarianceScale=0.0625"}},
                    {"filter_variance_4", {"shadows.storedVarianceScale=4"}},
                    {"depth_sigma_0.01", {"shadows.depthSigma=0.01"}},
                    {"depth_sigma_0.05", {"shadows.depthSigma=0.05"}},
                    {"normal_power_8", {"shadows.normalPower=8"}},
                    {"normal_power_64", {"shadows.normalPower=64"}}};
    study.scenes = {"harness/scenes/courtyard_penumbra.toml", "harness/scenes/glossy_room.toml",
                    "harness/scenes/thin_pillars.toml"};
    study.simulateAs = "shadows";
    // Binary visibility needs many samples (a 64-sample penumbra is still ~0.06 off), and
    // shadows are cheap enough for them.
    study.referenceSpp = 256;
    study.quickReferenceSpp = 16;
    study.scalingScene = "harness/scenes/courtyard_penumbra.toml";
    study.scalingInput = InputKind::ShadowVisibility;
    evaluation.study = std::move(study);
    evaluation.bench = EffectBench{"harness/scenes/courtyard_penumbra.toml", "shadows"};
    return evaluation;
}

} // namespace

const EffectDescriptor& shadowsEffect() {
    static const EffectDescriptor descriptor{
        "shadows",
        "ray-traced shadow denoiser: one visibility sample per pixel in, a stable shadow mask out",
        shadowSettings(),
        {{"shadow_visibility", InputKind::ShadowVisibility, "", "noisy"},
         {"shadow_depth", InputKind::Depth, ""},
         {"shadow_previous_depth", InputKind::PreviousDepth, ""},
         {"shadow_normals", InputKind::Normals, ""},
         {"shadow_motion", InputKind::Motion, ""},
         {"shadow_blocker_distance", InputKind::ShadowBlockerDistance, "shadows.penumbraAware"}},
        planShadows,
        {"shadows.filter", "shadows.classify", "shadows.skipClearedTiles", "shadows.pairedFilter",
         "shadows.splitClassify", "shadows.outputFormat", "shadows.rebuildClearHistory",
         "shadows.penumbraAware"},
        "",
        "shadow",
        shadowsEvaluation(),
    };
    return descriptor;
}

} // namespace glint
