// The reflections effect: SSSR (glint_sssr.h), then optionally the reflections denoiser
// (glint_reflections_denoiser.h) on SSSR's outputs, then optionally the composite. The
// denoiser runs between the intersection and the composite, so the composite applies the
// denoised reflection the denoiser writes over "sssr_radiance"; its variance is next frame's
// variance history for variance-guided tracing.
#include "core/effects/effect_tables.h"
#include "core/effects/reflections_settings.h"
#include "core/pass_model.h"
#include "core/sssr_table_images.h"

#include "glint/glint_effect.h"
#include "glint/glint_reflections.h"
#include "glint/glint_reflections_denoiser.h"
#include "glint/glint_sssr.h"
#include "glint/glint_sssr_tables.h"
#include "glint/sssr/glint_sssr_constants.h"

#include <algorithm>
#include <memory>

namespace glint {
namespace core {

EffectEvaluation reflectionsEvaluation() {
    EffectEvaluation evaluation;
    evaluation.scored = {{{"denoised", "noisy"},
                          "noisy",
                          ErrorMetric::RelativeLuminance,
                          {ErrorMask::Pixels::SurfaceAlphaBelow, "roughnessThreshold"}}};
    evaluation.previews = {
        {"ray_class", Preview::Categories},      {"tile_class", Preview::Categories},
        {"ray_list", Preview::Categories},       {"tile_list", Preview::Categories},
        {"mask", Preview::Categories},           {"iterations", Preview::HeatPercentile99},
        {"variance", Preview::HeatPercentile99}, {"hit_distance", Preview::HeatPercentile99},
        {"pyramid_mip", Preview::FiniteRange},   {"roughness", Preview::FiniteRange}};
    // Classification, inputs and the pyramid are exact; a hit may flip where a ray grazes a
    // depth edge and the GPUs round differently, and the flip carries into every float pass
    // after it.
    evaluation.tolerances = {{"classify"}, {"input"}, {"depth_pyramid"}, {"*", 1e-3, 1e-2, 0.01}};
    evaluation.reportImages = {"input", "noisy", "denoised", "composite", "reference", "error"};
    return evaluation;
}

std::vector<SettingDesc> reflectionsSettings() {
    const SssrDesc s;
    const ReflectionsDenoiserDesc d;
    return {
        floatSetting("roughnessThreshold", s.roughnessThreshold, 0, 1,
                     "GGX alpha at and above which no ray is traced (the environment instead); "
                     "the denoiser filters below it",
                     "SssrDesc, ReflectionsDenoiserDesc::roughnessThreshold"),
        floatSetting("mirrorThreshold", s.mirrorThreshold, 0, 1,
                     "GGX alpha below which a pixel is a mirror: always traced, never filtered",
                     "SssrDesc, ReflectionsDenoiserDesc::mirrorThreshold"),
        uintSetting("samplesPerQuad", s.samplesPerQuad, 1, 4, "rays per 2x2 quad: 1, 2 or 4",
                    "SssrDesc::samplesPerQuad"),
        uintSetting("maxTraversalIterations", s.maxTraversalIterations, 1, 4096,
                    "steps a ray may take through the depth pyramid", "SssrDesc::maxTraversalIterations"),
        uintSetting("mostDetailedMip", s.mostDetailedMip, 0, GLINT_SSSR_PYRAMID_LEVELS - 1,
                    "finest pyramid level non-mirror rays descend to", "SssrDesc::mostDetailedMip"),
        floatSetting("occupancyExitFraction", s.occupancyExitFraction, 0, 1,
                     "non-mirror rays stop once at most this fraction of their group is live (0 = off)",
                     "SssrDesc::occupancyExitFraction"),
        floatSetting("importanceSampleBias", s.importanceSampleBias, 0, 1,
                     "shrinks the sampled lobe: sharper, biased reflections",
                     "SssrDesc::importanceSampleBias"),
        floatSetting("thickness", s.thickness, 0, 1e6,
                     "assumed surface thickness, relative to its view depth", "SssrDesc::thickness"),
        boolSetting("thicknessAware", s.thicknessAware,
                    "rays pass behind thin objects (closest+farthest pyramid)", "SssrDesc::thicknessAware"),
        boolSetting("halfResolution", s.halfResolution, "one ray per 2x2 quad for every pixel",
                    "SssrDesc::halfResolution"),
        boolSetting("previousFrameColor", s.previousFrameColor,
                    "hits fetch last frame's final colour through motion", "SssrDesc::previousFrameColor"),
        boolSetting("varianceGuided", s.varianceGuided,
                    "extra rays where the denoiser's variance history is high", "SssrDesc::varianceGuided"),
        floatSetting("varianceThreshold", s.varianceThreshold, 0, 1e6,
                     "variance above which variance-guided tracing adds rays", "SssrDesc::varianceThreshold"),
        boolSetting("halfPrecisionStorage", s.halfPrecisionStorage,
                    "16-bit radiance, roughness, confidence and denoiser histories",
                    "SssrDesc, ReflectionsDenoiserDesc::halfPrecisionStorage"),
        boolSetting("debugOutput", s.debugOutput, "the intersection writes each ray's class and iterations",
                    "SssrDesc::debugOutput"),
        boolSetting("composite", s.composite, "adds the reflection to the lit colour (needs base colour)",
                    "SssrDesc::composite"),
        boolSetting("denoise", false, "runs the reflections denoiser on the traced samples",
                    "the denoiser's passes"),
        floatSetting("denoiser.historyClipScale", d.historyClipScale, 1e-6, 100,
                     "scale of the resolve's history clip box", "ReflectionsDenoiserDesc::historyClipScale"),
        uintSetting("denoiser.maxHistoryLength", d.maxHistoryLength, 8, 1024, "frames a history may average",
                    "ReflectionsDenoiserDesc::maxHistoryLength"),
        boolSetting("denoiser.antiLag", d.antiLag,
                    "shortens histories the neighbourhood's samples contradict beyond their noise",
                    "ReflectionsDenoiserDesc::antiLag"),
        core::choiceSetting("denoiser.spatialPath", 0, {"prefilter", "ratio"},
                            "spatial filter: edge-aware prefilter or ratio-estimator reuse of rays",
                            "ReflectionsDenoiserDesc::spatialPath"),
        floatSetting("denoiser.reconstructionRadius", d.reconstructionRadius, 1, 8,
                     "ratio path: reconstruction disk radius in pixels",
                     "ReflectionsDenoiserDesc::reconstructionRadius"),
        floatSetting("denoiser.cleanupSigma", d.cleanupSigma, 1e-6, 2,
                     "ratio path: spatial sigma of the cleanup in pixels",
                     "ReflectionsDenoiserDesc::cleanupSigma"),
    };
}

// The camera and G-buffer decoding both descs take from the frame (same field names in each).
template <typename Desc> Desc cameraDesc(const FrameInfo& frame) {
    Desc desc;
    desc.size = frame.size;
    desc.projection = frame.projection;
    desc.viewFromWorld = frame.viewFromWorld;
    desc.depth = frame.depth;
    desc.nearPlane = frame.nearPlane;
    desc.farPlane = frame.farPlane;
    desc.vulkanNdc = frame.vulkanNdc;
    desc.normalUnpackMul = frame.normalUnpackMul;
    desc.normalUnpackAdd = frame.normalUnpackAdd;
    desc.motionScaleX = frame.motionScaleX;
    desc.motionScaleY = frame.motionScaleY;
    desc.frameIndex = frame.frameIndex;
    return desc;
}

std::vector<InputDesc> reflectionsInputs() {
    return {{"depth", InputKind::Depth, ""},
            {"normals", InputKind::Normals, ""},
            {"material", InputKind::Material, ""},
            {"color", InputKind::Color, "", "input"},
            {"motion", InputKind::Motion, ""},
            {"environment", InputKind::Environment, ""},
            {"base_color_metallic", InputKind::BaseColorMetallic, "composite"}};
}

SssrDesc sssrDesc(const FrameInfo& frame, const SettingValues& settings) {
    SssrDesc desc = cameraDesc<SssrDesc>(frame);
    desc.materialChannel = frame.materialChannel;
    desc.roughnessIsPerceptual = frame.roughnessIsPerceptual;
    desc.environmentTexelSolidAngle = frame.environmentTexelSolidAngle;
    desc.environmentMaxLod = frame.environmentMaxLod;

    desc.roughnessThreshold = settings.real("roughnessThreshold");
    desc.mirrorThreshold = settings.real("mirrorThreshold");
    desc.samplesPerQuad = settings.count("samplesPerQuad");
    desc.maxTraversalIterations = settings.count("maxTraversalIterations");
    desc.mostDetailedMip = settings.count("mostDetailedMip");
    desc.occupancyExitFraction = settings.real("occupancyExitFraction");
    desc.importanceSampleBias = settings.real("importanceSampleBias");
    desc.thickness = settings.real("thickness");
    desc.thicknessAware = settings.flag("thicknessAware");
    desc.halfResolution = settings.flag("halfResolution");
    desc.previousFrameColor = settings.flag("previousFrameColor");
    desc.varianceGuided = settings.flag("varianceGuided");
    desc.varianceThreshold = settings.real("varianceThreshold");
    desc.halfPrecisionStorage = settings.flag("halfPrecisionStorage");
    desc.debugOutput = settings.flag("debugOutput");
    desc.composite = settings.flag("composite");
    desc.denoise = settings.flag("denoise");
    return desc;
}

ReflectionsDenoiserDesc reflectionsDenoiserDesc(const FrameInfo& frame, const SettingValues& settings,
                                                const SssrDesc& sssr) {
    ReflectionsDenoiserDesc desc = cameraDesc<ReflectionsDenoiserDesc>(frame);
    desc.previousClipFromWorld = frame.previousClipFromWorld;
    desc.resetHistory = frame.resetHistory;
    // Shared with SSSR: the classification decides which pixels the denoiser sees.
    desc.roughnessThreshold = sssr.roughnessThreshold;
    desc.mirrorThreshold = sssr.mirrorThreshold;
    desc.halfPrecisionStorage = sssr.halfPrecisionStorage;
    desc.historyClipScale = settings.real("denoiser.historyClipScale");
    desc.maxHistoryLength = settings.count("denoiser.maxHistoryLength");
    desc.antiLag = settings.flag("denoiser.antiLag");
    desc.spatialPath = static_cast<SpatialPath>(settings.choice("denoiser.spatialPath"));
    desc.reconstructionRadius = settings.real("denoiser.reconstructionRadius");
    desc.cleanupSigma = settings.real("denoiser.cleanupSigma");
    return desc;
}

} // namespace core
namespace {

using core::reflectionsDenoiserDesc;
using core::reflectionsSettings;
using core::sssrDesc;

void addOutputs(EffectPlan& plan, const SssrDesc& sssr, const ReflectionsDenoiserDesc* denoiser) {
    const char* denoisedBy =
        denoiser && denoiser->spatialPath == SpatialPath::RatioEstimator ? "cleanup" : "resolve";
    auto& out = plan.outputs;
    out.push_back({"noisy", "sssr_radiance", "intersect", OutputDecoder::Channels, 0, 3});
    if (denoiser) out.push_back({"denoised", "sssr_radiance", denoisedBy, OutputDecoder::Channels, 0, 3});
    if (sssr.composite) out.push_back({"composite", "composite", "composite", OutputDecoder::Channels, 0, 3});
    out.push_back({"confidence", "sssr_confidence", "intersect", OutputDecoder::Channels, 0, 1});
    const auto intermediate = [&](OutputDesc output) {
        output.intermediate = true;
        out.push_back(std::move(output));
    };
    intermediate({"hit_distance", "sssr_radiance", denoiser ? denoisedBy : "intersect",
                  OutputDecoder::Channels, 3, 1});
    intermediate({"roughness", "sssr_roughness", "classify", OutputDecoder::Channels, 0, 1});
    intermediate({"ray_list", "sssr_ray_list", "compact_noise_args", OutputDecoder::RayList, 0, 1, 0,
                  "traced_pixels"});
    intermediate(
        {"tile_list", "sssr_tile_list", "classify", OutputDecoder::TileList, 0, 1, 0, "listed_tiles"});
    if (sssr.debugOutput) {
        intermediate({"ray_class", "sssr_ray_info", "intersect", OutputDecoder::Channels, 2, 1});
        intermediate({"iterations", "sssr_ray_info", "intersect", OutputDecoder::Channels, 3, 1});
    }
    if (denoiser)
        intermediate({"variance", reflectionsDenoiserVariance(denoiser->frameIndex), "resolve",
                      OutputDecoder::Channels, 0, 1});
    intermediate({"pyramid_mip", "depth_pyramid", "depth_pyramid", OutputDecoder::MipChain, 0, 1, 1});
    plan.counters.push_back({"traced_pixels", "sssr_counters", 1, "traced_fraction"});
    plan.counters.push_back({"listed_tiles", "sssr_counters", 3, ""});
}

Result planFrame(const FrameInfo& frame, const SettingValues& settings, EffectPlan& plan,
                 std::string* error) {
    SssrDesc sssr = sssrDesc(frame, settings);
    const ReflectionsDenoiserDesc denoiser = reflectionsDenoiserDesc(frame, settings, sssr);
    sssr.storeRays = sssr.denoise && denoiser.spatialPath == SpatialPath::RatioEstimator;
    return planReflections(sssr, sssr.denoise ? &denoiser : nullptr, plan, error);
}

// One setting at a time around the defaults. "ratio_estimator" is the denoiser's alternative
// spatial path (ratio-estimator reconstruction + bilateral cleanup).
EffectEvaluation evaluation() {
    EffectEvaluation evaluation = core::reflectionsEvaluation();
    // The reflections' classification is exact up to the last bits of its float roughness.
    evaluation.tolerances.front() = {"classify", 1e-6, 1e-6, 0.0};
    EffectStudy study;
    // SSSR alone leaves one noisy ray per quad; the effect an engine ships includes the denoiser.
    study.baseSettings = {"denoise=true"};
    study.points = {{"defaults", {}, true},
                    {"no_denoiser", {"denoise=false"}, true},
                    {"ratio_estimator", {"denoiser.spatialPath=ratio"}, true},
                    {"iterations_32", {"maxTraversalIterations=32"}},
                    {"iterations_64", {"maxTraversalIterations=64"}},
                    {"iterations_256", {"maxTraversalIterations=256"}},
                    {"occupancy_4of64", {"occupancyExitFraction=0.0625"}},
                    {"occupancy_8of64", {"occupancyExitFraction=0.125"}},
                    {"mip_1", {"mostDetailedMip=1"}},
                    {"mip_2", {"mostDetailedMip=2"}},
                    {"spq_2", {"samplesPerQuad=2"}},
                    {"spq_4", {"samplesPerQuad=4"}, true},
                    {"threshold_0.1", {"roughnessThreshold=0.1"}},
                    {"threshold_0.3", {"roughnessThreshold=0.3"}},
                    {"thickness_aware", {"thicknessAware=true"}},
                    {"half_res", {"halfResolution=true"}},
                    {"bias_0.3", {"importanceSampleBias=0.3"}},
                    {"bias_0.6", {"importanceSampleBias=0.6"}},
                    {"full_storage", {"halfPrecisionStorage=false"}}};
    study.scenes = {"harness/scenes/glossy_room.toml", "harness/scenes/mirror_corridor.toml",
                    "harness/scenes/thin_pillars.toml"};
    study.simulateAs = "reflections";
    study.scalingScene = "harness/scenes/glossy_room.toml";
    study.scalingInput = InputKind::Material;
    study.tracedCounter = "traced_fraction";
    evaluation.study = std::move(study);
    evaluation.bench = EffectBench{"harness/scenes/glossy_room.toml", "reflections"};
    return evaluation;
}

} // namespace

Result planReflections(const SssrDesc& sssr, const ReflectionsDenoiserDesc* denoiser, EffectPlan& plan,
                       std::string* error) {
    if (denoiser && !sssr.denoise) {
        if (error) *error = "reflections: a denoiser desc needs SssrDesc::denoise";
        return Result::InvalidArgument;
    }
    if (const Result result = planSssr(sssr, plan, error); result != Result::Ok) return result;
    plan.effect = "reflections";
    for (Pass& pass : plan.passes)
        if (pass.pipeline.rfind("depth_pyramid", 0) == 0) pass.name = "depth_pyramid";

    plan.images.push_back({"sssr_blue_noise_source", kSssrBlueNoiseSize, kSssrBlueNoiseSize, 1,
                           Format::RG32Float, core::sssrBlueNoiseTexels()});
    if (sssr.composite)
        plan.images.push_back({"sssr_brdf_lut", kSssrBrdfLutSize, kSssrBrdfLutSize, 1, Format::RG32Float,
                               core::sssrBrdfLutTexels()});
    if (!sssr.denoise) {
        // Without a denoiser there is no variance to guide by: a zero history.
        plan.images.push_back({"sssr_zero_variance", 1, 1, 1, Format::R32Float});
        core::renameResource(plan.passes, "sssr_variance_history", "sssr_zero_variance");
        addOutputs(plan, sssr, nullptr);
        return Result::Ok;
    }
    core::renameResource(plan.passes, "sssr_variance_history",
                         reflectionsDenoiserVariance(sssr.frameIndex + 1));
    // With denoise but no denoiser desc this frame: the denoiser's resources, none of its passes.
    ReflectionsDenoiserDesc resourcesOnly;
    resourcesOnly.size = sssr.size;
    resourcesOnly.halfPrecisionStorage = sssr.halfPrecisionStorage;
    EffectPlan denoiserPlan;
    if (const Result result =
            planReflectionsDenoiser(denoiser ? *denoiser : resourcesOnly, denoiserPlan, error);
        result != Result::Ok)
        return result;
    const auto composite = std::find_if(plan.passes.begin(), plan.passes.end(),
                                        [](const Pass& pass) { return pass.name == "composite"; });
    if (denoiser) plan.passes.insert(composite, denoiserPlan.passes.begin(), denoiserPlan.passes.end());
    plan.images.insert(plan.images.end(), denoiserPlan.images.begin(), denoiserPlan.images.end());
    plan.buffers.insert(plan.buffers.end(), denoiserPlan.buffers.begin(), denoiserPlan.buffers.end());
    addOutputs(plan, sssr, denoiser);
    return Result::Ok;
}

const EffectDescriptor& reflectionsEffect() {
    static const EffectDescriptor descriptor{
        "reflections",
        "stochastic screen-space reflections, optionally denoised and composited",
        reflectionsSettings(),
        core::reflectionsInputs(),
        planFrame,
        {"thicknessAware", "debugOutput", "composite", "halfPrecisionStorage", "denoise",
         "denoiser.spatialPath"},
        "debugOutput",
        "reflection",
        evaluation(),
    };
    return descriptor;
}

} // namespace glint
