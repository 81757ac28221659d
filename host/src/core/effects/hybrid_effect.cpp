// The hybrid effect (glint_hybrid.h): screen space first, the application's ray tracer for the
// rays screen space cannot answer, chosen per 8x8 tile from last frame's feedback; then
// optionally the reflections denoiser and the composite, with the reflections effect's
// settings for the shared parts.
#include "core/effects/effect_tables.h"
#include "core/effects/reflections_settings.h"

#include "glint/glint_effect.h"
#include "glint/glint_hybrid.h"

namespace glint {
namespace {

using core::boolSetting;
using core::floatSetting;

std::vector<SettingDesc> hybridSettings() {
    std::vector<SettingDesc> settings = core::reflectionsSettings();
    const HybridDesc h;
    const std::vector<SettingDesc> own = {
        boolSetting("hybrid.screenSpace", h.screenSpace,
                    "rays try screen space first (off: ray tracing only)", "HybridDesc::screenSpace"),
        boolSetting("hybrid.rayTracing", h.rayTracing,
                    "rays screen space cannot answer are ray traced (off: SSSR)", "HybridDesc::rayTracing"),
        boolSetting("hybrid.feedback", h.feedback,
                    "tiles choose screen space or ray tracing from last frame's hits",
                    "HybridDesc::feedback"),
        boolSetting("hybrid.alternateCheckerboard", h.alternateCheckerboard,
                    "half-and-half tiles flip their checkerboard every frame",
                    "HybridDesc::alternateCheckerboard"),
        boolSetting("hybrid.mirrorsRayTraced", h.mirrorsRayTraced, "mirrors are always ray traced",
                    "HybridDesc::mirrorsRayTraced"),
        boolSetting("hybrid.reshade", h.reshade,
                    "screen-space hits are shaded like ray-traced ones (off: the colour buffer)",
                    "HybridDesc::reshade"),
        boolSetting("hybrid.rayQuery", h.tracer == HybridTracer::RayQuery,
                    "rays are traced by hybrid_trace_rayquery over the scene's acceleration structure "
                    "(a device with ray queries; the module from GLINT_SHADER_DIR)",
                    "HybridDesc::tracer"),
        floatSetting("hybrid.spawnRate", h.spawnRate, 0, 1,
                     "chance a tile without statistics tries screen space", "HybridDesc::spawnRate"),
        floatSetting("hybrid.missWeight", h.missWeight, 0, 64,
                     "a screen-space miss against a hit in the tile rule", "HybridDesc::missWeight"),
        floatSetting("hybrid.rayTracingThreshold", h.rayTracingThreshold, 0, 1,
                     "GGX alpha at and above which rays stay in screen space",
                     "HybridDesc::rayTracingThreshold"),
        floatSetting("hybrid.confidenceThreshold", h.confidenceThreshold, 0, 1,
                     "screen-space results below this confidence are ray traced",
                     "HybridDesc::confidenceThreshold"),
        floatSetting("hybrid.maxRayDistance", h.maxRayDistance, 1e-3, 1e9,
                     "world units a ray-traced ray reaches (the environment beyond)",
                     "HybridDesc::maxRayDistance"),
        floatSetting("hybrid.rayOffset", h.rayOffset, 0, 1e3,
                     "world units the ray tracer's origin leaves the surface", "HybridDesc::rayOffset"),
        floatSetting("hybrid.thicknessRoughnessGrowth", h.thicknessRoughnessGrowth, 0, 1e3,
                     "screen-space thickness grows by this times alpha (relative)",
                     "HybridDesc::thicknessRoughnessGrowth"),
        floatSetting("hybrid.thicknessDistanceGrowth", h.thicknessDistanceGrowth, 0, 1e3,
                     "screen-space thickness grows by this per world unit of ray length",
                     "HybridDesc::thicknessDistanceGrowth"),
    };
    settings.insert(settings.end(), own.begin(), own.end());
    return settings;
}

// The reflections' images and the scene the ray tracer traces.
std::vector<InputDesc> hybridInputs() {
    std::vector<InputDesc> inputs = core::reflectionsInputs();
    inputs.push_back({"scene_primitives", InputKind::SceneGeometry, ""});
    inputs.push_back(
        {"scene_acceleration_structure", InputKind::SceneAccelerationStructure, "hybrid.rayQuery"});
    return inputs;
}

Result planFrame(const FrameInfo& frame, const SettingValues& settings, EffectPlan& plan,
                 std::string* error) {
    HybridDesc desc;
    desc.sssr = core::sssrDesc(frame, settings);
    desc.screenSpace = settings.flag("hybrid.screenSpace");
    desc.rayTracing = settings.flag("hybrid.rayTracing");
    desc.feedback = settings.flag("hybrid.feedback");
    desc.alternateCheckerboard = settings.flag("hybrid.alternateCheckerboard");
    desc.mirrorsRayTraced = settings.flag("hybrid.mirrorsRayTraced");
    desc.spawnRate = settings.real("hybrid.spawnRate");
    desc.missWeight = settings.real("hybrid.missWeight");
    desc.rayTracingThreshold = settings.real("hybrid.rayTracingThreshold");
    desc.confidenceThreshold = settings.real("hybrid.confidenceThreshold");
    desc.maxRayDistance = settings.real("hybrid.maxRayDistance");
    desc.rayOffset = settings.real("hybrid.rayOffset");
    desc.reshade = settings.flag("hybrid.reshade");
    if (settings.flag("hybrid.rayQuery")) {
        desc.tracer = HybridTracer::RayQuery;
        desc.tracePipeline = "hybrid_trace_rayquery";
    }
    desc.thicknessRoughnessGrowth = settings.real("hybrid.thicknessRoughnessGrowth");
    desc.thicknessDistanceGrowth = settings.real("hybrid.thicknessDistanceGrowth");
    if (desc.sssr.debugOutput || desc.sssr.thicknessAware) {
        if (error)
            *error = "hybrid: debugOutput and thicknessAware are not supported by the hybrid effect yet";
        return Result::InvalidArgument;
    }
    const ReflectionsDenoiserDesc denoiser = core::reflectionsDenoiserDesc(frame, settings, desc.sssr);
    if (desc.sssr.denoise && denoiser.spatialPath == SpatialPath::RatioEstimator) {
        if (error)
            *error =
                "hybrid: the denoiser's ratio path needs stored rays, which the hybrid does not write yet";
        return Result::InvalidArgument;
    }
    return planHybridReflections(desc, desc.sssr.denoise ? &denoiser : nullptr, plan, error);
}

} // namespace

namespace {

// The three paths an engine with ray tracing chooses between, then the hybrid's own trade-offs
// (the share of rays ray traced in study.csv's traced_fraction). Not scaled: its cost follows
// that share, which the sweep reports.
EffectEvaluation hybridEvaluation() {
    EffectEvaluation evaluation = core::reflectionsEvaluation();
    EffectStudy study;
    study.baseSettings = {"denoise=true"};
    study.points = {{"defaults", {}, true},
                    {"ss_only", {"hybrid.rayTracing=false"}, true},
                    {"rt_only", {"hybrid.screenSpace=false"}, true},
                    {"no_denoiser", {"denoise=false"}},
                    {"screen_colour", {"hybrid.reshade=false"}},
                    {"mirrors_rt", {"hybrid.mirrorsRayTraced=true"}},
                    {"confidence_0.5", {"hybrid.confidenceThreshold=0.5"}},
                    {"rt_threshold_0.1", {"hybrid.rayTracingThreshold=0.1"}},
                    {"no_feedback", {"hybrid.feedback=false"}}};
    study.scenes = {"harness/scenes/glossy_room.toml", "harness/scenes/mirror_corridor.toml",
                    "harness/scenes/thin_pillars.toml"};
    study.simulateAs = "hybrid";
    study.tracedCounter = "ray_traced_rays";
    study.answeredCounter = "screen_space_answers";
    evaluation.study = std::move(study);
    evaluation.bench = EffectBench{"harness/scenes/glossy_room.toml", "hybrid"};
    return evaluation;
}

} // namespace

const EffectDescriptor& hybridEffect() {
    static const EffectDescriptor descriptor{
        "hybrid",
        "reflections traced in screen space first and by the scene's ray tracer where that fails, per tile",
        hybridSettings(),
        hybridInputs(),
        planFrame,
        {"composite", "halfPrecisionStorage", "denoise"},
        "",
        "reflection",
        hybridEvaluation(),
    };
    return descriptor;
}

} // namespace glint
