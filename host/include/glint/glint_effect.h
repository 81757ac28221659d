// glint public API: every effect as one descriptor.
//
// A descriptor is all a tool needs to run an effect without knowing it: its settings table,
// the application images it reads (by what they hold, so a capture reader or an engine knows
// what to bind), and a plan builder that turns a frame and the settings into passes and
// resources (glint_pass.h). The plan also names the effect's outputs and counters and how to
// decode them, so replay, dumps and tests read every effect the same way. Its evaluation says
// how the effect is scored, checked, previewed, reported and studied. Effects compose by
// resource name: the reflections effect runs the reflections denoiser on SSSR's outputs, and a
// value both share (the roughness threshold) is one setting. Nothing here touches a graphics API.
#pragma once

#include "glint/glint_depth_pyramid.h"
#include "glint/glint_pass.h"
#include "glint/glint_settings.h"
#include "glint/glint_types.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace glint {

// What a frame gives every effect: size, camera and how the G-buffer is encoded. Matrices are
// row-major 4x4 with column vectors (q = M p), unjittered (docs/conventions.md).
struct FrameInfo {
    Extent2D size;
    std::array<double, 16> projection{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};    // view -> clip
    std::array<double, 16> viewFromWorld{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; // this frame
    std::array<double, 16> previousClipFromWorld{1, 0, 0, 0, 0, 1, 0, 0,
                                                 0, 0, 1, 0, 0, 0, 0, 1}; // last frame's projection * view
    DepthConvention depth = DepthConvention::Standard;
    float nearPlane = 0.1f;
    float farPlane = 1000.0f;     // 0 = infinite (reversed depth only)
    bool vulkanNdc = true;        // y_n = 2v - 1 (true) or 1 - 2v (D3D-style)
    float normalUnpackMul = 1.0f; // n = normalize(raw.xyz * mul + add)
    float normalUnpackAdd = 0.0f;
    std::uint32_t materialChannel = 0;              // channel of the material image holding roughness
    bool roughnessIsPerceptual = true;              // true: r (squared once); false: GGX alpha
    float motionScaleX = 1.0f, motionScaleY = 1.0f; // uv_prev = uv + scale * mv
    // The environment behind the reflections' misses: solid angle of a level-0 texel and the
    // last mip level.
    float environmentTexelSolidAngle = 4.0f * 3.14159265f / (6.0f * 128.0f * 128.0f);
    float environmentMaxLod = 7.0f;
    std::uint32_t frameIndex = 0; // histories ping-pong on its parity
    bool resetHistory = false;    // first frame, camera cut or resize
    // tan of the angular radius of the light ShadowVisibility samples; 0: a light of size 0 (hard
    // shadows); negative: unknown.
    float shadowLightTanHalfAngle = -1.0f;
};

// What an application image holds. A tool fills each input from its own data by this kind.
enum class InputKind : std::uint8_t {
    Depth,                 // R: device depth
    PreviousDepth,         // R: last frame's device depth (this frame's on the first)
    Normals,               // RGBA: world-space normals, encoded as FrameInfo::normalUnpack says
    Material,              // RGBA: roughness in FrameInfo::materialChannel
    Color,                 // RGBA: lit colour
    Motion,                // RG: motion vectors, FrameInfo::motionScale
    Environment,           // RGBA: lat-long environment with its whole mip chain
    BaseColorMetallic,     // RGBA: base colour and metallic
    ShadowVisibility,      // R: one binary visibility sample (1 = lit)
    ShadowBlockerDistance, // R: distance along ShadowVisibility's ray to its closest blocker; 0 when lit,
                           // < 0 unknown (optional: a capture without it reads as unknown)
    SceneGeometry,         // buffers: the application's scene for its ray tracing and shading modules
                           // (glint's harness: "scene_constants", "scene_nodes", "scene_primitives",
                           // "scene_materials", "scene_lights"; harness/scene/scene_buffers.h)
    SceneAccelerationStructure, // a top-level acceleration structure over the same scene, for a RayQuery
                                // ray tracing module (glint's harness: "scene_acceleration_structure",
                                // harness/scene/scene_acceleration.h; docs/hybrid.md)
};

struct InputDesc {
    std::string resource; // the plan's name for it, e.g. "shadow_depth"
    InputKind kind = InputKind::Depth;
    std::string setting; // empty: always read; else only while this Bool setting is true
    std::string shownAs; // non-empty: a tool shows this input as the effect's output of that name
};

// How a tool judges and shows an effect (glint's harness reads it the way it reads the settings
// rows; docs/replay.md, docs/accuracy-vs-time.md). Plain data: nothing here runs.

// How an output's error against its reference is measured per pixel.
enum class ErrorMetric : std::uint8_t {
    RelativeLuminance, // luminance of |out - ref| over max(luminance(ref), 0.05): radiance
    Absolute,          // luminance of |out - ref|
    Visibility,        // |out - ref| of values in [0, 1], with the error over penumbrae
                       // (reference in (0.05, 0.95)) and over moving edges
};

// The pixels an output's error is measured over.
struct ErrorMask {
    enum class Pixels : std::uint8_t {
        Surface,           // depth short of the background value
        SurfaceAlphaBelow, // a surface whose GGX alpha is below the Float setting `setting`
    };
    Pixels pixels = Pixels::Surface;
    std::string setting; // SurfaceAlphaBelow: the setting holding the threshold
};

// One scored output: the effect's output "final" against the capture's reference layer
// (EffectDescriptor::reference, the output "reference"), with the output "noisy" scored alongside.
struct ScoredOutput {
    std::vector<std::string> final; // the first of these the frame has is scored ("denoised", "noisy")
    std::string noisy;              // the noisy input, scored alongside (empty: none)
    ErrorMetric metric = ErrorMetric::RelativeLuminance;
    ErrorMask mask;
    float errorHeatScale = 1.0f; // the error map's preview: heat from 0 to this
    // Previews of these outputs show the pixels outside the mask as this value (the value the
    // effect gives them), so that noisy, output and reference differ only inside it.
    std::vector<std::string> outsideMaskShownAs;
    float outsideMaskValue = 1.0f;
    // The mask in words for a report ("over ..."); empty: said from its kind and threshold.
    std::string maskInWords;
};

// How a tool previews an output as an 8-bit image.
enum class Preview : std::uint8_t {
    Colour,           // tone-mapped when it has 3 or more channels, else grey over [0, 1]
    FiniteRange,      // grey over the range of its finite values (depths, roughness)
    Categories,       // one colour per value (classes, lists)
    Heat,             // heat map from 0 to `scale`
    HeatPercentile99, // heat map from 0 to its 99th percentile of |value|
};

struct OutputPreview {
    std::string output; // an output's name; one followed by digits (mip levels) matches too
    Preview preview = Preview::Colour;
    float scale = 1.0f; // Heat
};

// The tolerance of `glint check` for a pass: a pixel differs when |a - b| > absolute + relative
// * |b|; the pass fails when more than `fraction` of its pixels differ.
struct PassTolerance {
    std::string pass; // the pass's name; one ending in '*' matches every pass it begins
    double absolute = 0.0, relative = 0.0, fraction = 0.0;
};

// One point of the study's sweep: settings changed from the effect's base settings.
struct StudyPointDesc {
    std::string label; // also an image's file name
    std::vector<std::string> settings;
    bool quick = false; // in the --quick sweep
};

struct EffectStudy {
    std::vector<std::string> baseSettings; // the effect as an engine ships it
    std::vector<StudyPointDesc> points;    // the first is the base ("defaults")
    std::vector<std::string> scenes;       // scene files, relative to the repository root
    std::size_t quickScenes = 1;           // --quick studies the first this many
    std::string simulateAs;                // the scene effect whose inputs are rendered
    std::uint32_t referenceSpp = 64, quickReferenceSpp = 4;
    // --scaling: the scene, and the input whose rows it rewrites to sweep the fraction of pixels
    // the effect works on (Material: glossy rows; ShadowVisibility: penumbra rows). No scene:
    // not scaled.
    std::string scalingScene;
    InputKind scalingInput = InputKind::Material;
    // The share of rays traced, for study.csv's traced_fraction: the counter `traced` alone, or
    // with `answered`, traced / (traced + answered).
    std::string tracedCounter, answeredCounter;
};

// What `glint bench <effect>` times: the effect alone on a bundled scene, simulated at the
// bench's size without references, with the inputs of the scene effect `simulateAs` rendered.
struct EffectBench {
    std::string scene;      // scene file, relative to the repository root
    std::string simulateAs; // "reflections", "shadows" or "hybrid" (a scene file's `effects`)
};

struct EffectEvaluation {
    std::vector<ScoredOutput> scored;      // empty: the effect is not scored
    std::vector<OutputPreview> previews;   // outputs not listed: Preview::Colour
    std::vector<PassTolerance> tolerances; // first match wins; passes not listed: exact
    // The images of the last frame a report shows, by output name ("denoised", "mip1"; also
    // "reference", "error" and inputs shown as outputs).
    std::vector<std::string> reportImages;
    std::optional<EffectStudy> study; // none: glint study does not sweep it
    std::optional<EffectBench> bench; // none: glint bench times it only on captures
};

struct EffectDescriptor {
    std::string name; // as --effects spells it
    std::string help; // one line
    std::vector<SettingDesc> settings;
    std::vector<InputDesc> inputs;
    // The plan of one frame; InvalidArgument with one line in `error` for a frame or settings
    // the effect cannot run.
    Result (*plan)(const FrameInfo& frame, const SettingValues& settings, EffectPlan& plan,
                   std::string* error) = nullptr;
    // The settings that fix resources (formats, which images exist): a change needs a new
    // instance. Everything else may change from frame to frame.
    std::vector<std::string> resourceSettings;
    // The Bool setting a tool turns on when it wants every intermediate (empty: none needed).
    std::string debugSetting;
    // The reference a capture may carry for the effect's final output ("reflection": the
    // capture layer "reference.reflection"), shown and scored as the output "reference".
    std::string reference;
    EffectEvaluation evaluation;
};

// Every effect glint ships, in the order a tool runs them.
const std::vector<const EffectDescriptor*>& effectRegistry();
const EffectDescriptor* findEffect(std::string_view name);

// Every effect's settings in one table (a setting two effects share appears once).
std::vector<const SettingDesc*> allSettings();

// The settings of `effects` at their defaults.
SettingValues defaultSettings(const std::vector<const EffectDescriptor*>& effects);

} // namespace glint
