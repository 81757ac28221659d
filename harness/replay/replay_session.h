// Runs the effects a capture declares (or the ones asked for) frame after frame, carrying
// every history across the sequence, and hands back named images, per-pass GPU times and
// counters. The engine of `glint run`, `glint dump`, `glint check`, `glint bench` on captures
// and `glint study`.
//
// Every effect is reached through its descriptor (glint_effect.h): the session plans each
// frame from the capture's camera and the settings, fills the effect's inputs by kind, runs the
// plan through one gpu::EffectRunner and returns the outputs the plan names. Image names are
// "<effect>/<output>" and each names the pass that produced it ("<effect>/input" for inputs
// and references), so that dump and check can select by pass.
#pragma once

#include "capture/capture_frame.h"
#include "capture/environment_io.h"
#include "replay/replay_settings.h"

#include "glint/glint_effect.h"
#include "report/report_image.h"
#include "scene/scene_types.h"

#include <gpu/gpu_context.h>
#include <gpu/gpu_input_images.h>

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace glint::scene {
class SceneBuffers;
}

namespace glint::replay {

// The effects replay knows (every registered effect), in the order they run.
std::vector<std::string> knownEffects();

// `requested` (or, when empty, the frame's declared effects), checked against what the frame
// can feed. Throws std::invalid_argument with one line naming the effect and the missing layer.
// A setting gates an input (composite needs the base colour), so the check sees the settings.
std::vector<std::string> effectsToRun(const capture::Frame& frame, const std::vector<std::string>& requested,
                                      const SettingValues& settings = defaultSettings(effectRegistry()));

// The first capture layer that one of `effects` (known names) reads with these settings and
// `frame` lacks; what effectsToRun reports.
struct MissingLayer {
    std::string effect;  // "reflections"
    std::string layer;   // "material"; empty: the roughness source
    std::string setting; // the setting that asks for it ("composite"), or empty
};
std::optional<MissingLayer> missingLayer(const capture::Frame& frame, const std::vector<std::string>& effects,
                                         const SettingValues& settings);
// "effect 'reflections' needs the capture layer 'material' (for composite), which this capture
// does not have".
std::string missingLayerMessage(const MissingLayer& missing);

struct NamedImage {
    std::string name; // "reflections/denoised"
    std::string pass; // "reflections/resolve": the pass that wrote it ("<effect>/input" for inputs)
    report::Image image;
};

struct PassTime {
    std::string pass; // "reflections/intersect"
    double milliseconds = 0.0;
};

struct Counter {
    std::string name; // "reflections/traced_pixels"
    double value = 0.0;
};

struct FrameResult {
    std::vector<NamedImage> images;
    std::vector<PassTime> timings; // empty when the queue has no timestamps
    std::vector<Counter> counters;

    const NamedImage* find(const std::string& name) const;
};

struct SustainedResult {
    std::vector<FrameResult> frames; // timings of every measured frame; counters with the last
    double wallMilliseconds = 0.0;   // of the measured frames, host clock
};

struct SessionOptions {
    std::vector<std::string> effects; // empty: the first frame's declared effects
    SettingValues settings = defaultSettings(effectRegistry());
    bool intermediates = false; // also every intermediate (glint dump)
    bool readback = true;       // false: timings and counters only (benchmarks)
    // The scene file the capture was simulated from (its manifest's "scene"): the geometry of
    // the effects that ray trace (InputKind::SceneGeometry). Empty, and no `geometry`: such
    // effects are refused.
    std::string scene;
    // The geometry given apart from the capture (glint run --geometry FILE:
    // scene::loadGeometryScene), in the capture's world space. Wins over `scene`.
    std::optional<scene::Scene> geometry;
    // The frame index the first run() gets (the random sequences and the histories' parity
    // follow it): a session that replaces another mid-sequence (glint view after a setting
    // that fixes resources) continues its numbering.
    std::uint32_t firstFrameIndex = 0;
    // Which images run() reads back, by name ("reflections/denoised"); empty: all of them.
    // Readback is what costs time in a frame loop (glint view reads only what it shows).
    std::function<bool(const std::string&)> readbackFilter;
};

class Session {
  public:
    // Validates the effects against `first` and creates their resources. Every later frame
    // must have the same size (std::invalid_argument otherwise).
    Session(const gpu::Context& context, const capture::Frame& first, const capture::Environment& environment,
            SessionOptions options);
    ~Session();
    Session(const Session&) = delete;
    Session& operator=(const Session&) = delete;

    // Runs one frame. The first frame and `cut` reset every history.
    FrameResult run(const capture::Frame& frame, bool cut = false);
    // The images of the last run() again, `frame` being the frame it ran, filtered by `wanted`
    // (all when empty) instead of the options' filter. Needs readback.
    FrameResult read(const capture::Frame& frame,
                     const std::function<bool(const std::string&)>& wanted) const;
    // New settings from the next frame on. False, with nothing changed, when one of them fixes
    // resources (EffectDescriptor::resourceSettings): that needs a new session.
    bool changeSettings(const SettingValues& settings);
    // The last frame again, as the next frame index, without uploading anything. Timings and
    // counters only; the camera is treated as static.
    FrameResult repeat();
    // Sustained repeats, as a frame loop keeps the GPU busy (gpu::timeSustained, its warm-up
    // included): `framesPerBuffer` repeats recorded into each of two command buffers, then
    // `submissions` measured submissions (at least 2). Without timestamps, that many plain
    // repeats. The two buffers hold 2 * framesPerBuffer consecutive frame indices, replayed as
    // a cycle (the ping-pong parity alternates across it).
    SustainedResult repeatSustained(std::uint32_t framesPerBuffer, std::uint32_t submissions);
    const std::vector<std::string>& effects() const { return effects_; }

    struct Running;

  private:
    void dispatch(Running& effect, const FrameInfo& info, FrameResult& result);
    FrameInfo nextRepeat(); // the last frame again, as the next frame index
    void uploadInputs(const capture::Frame& frame, bool reset);
    void readImages(const Running& effect, const capture::Frame& frame,
                    const std::function<bool(const std::string&)>& wanted, FrameResult& result) const;

    const gpu::Context& context_;
    const capture::Environment& environment_;
    SessionOptions options_;
    std::vector<std::string> effects_;
    std::vector<std::unique_ptr<Running>> running_;
    std::unique_ptr<gpu::InputImages> inputs_;
    std::unique_ptr<scene::SceneBuffers> scene_;       // with an effect that ray traces
    std::map<InputKind, std::vector<float>> uploaded_; // this frame's inputs, for the shown ones
    std::vector<float> previousDepth_;
    FrameInfo last_;
    std::uint32_t width_ = 0, height_ = 0, frame_ = 0;
};

} // namespace glint::replay
