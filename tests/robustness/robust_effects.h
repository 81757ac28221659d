// Every effect over a sequence of capture frames, as the replay session runs them
// (harness/replay/replay_session.h: descriptors, FrameInfo from the frame, inputs by kind, one
// gpu::EffectRunner per effect, histories carried from frame to frame), with what the long
// robustness sequences need and the session does not expose: the runners' history images, to
// poison and to read back; a hook that changes any input's texels before they are uploaded; and
// a frame an effect refuses (its planner's InvalidArgument) recorded instead of thrown, so that
// the sequence goes on.
#pragma once

#include "capture/capture_frame.h"
#include "capture/environment_io.h"
#include "scene/scene_types.h"

#include "glint/glint_effect.h"

#include <gpu/gpu_context.h>
#include <gpu/gpu_effect_runner.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace glint::scene {
class SceneBuffers;
}
namespace glint::gpu {
class InputImages;
}

namespace glint::test {

// A history an effect carries from frame to frame: an image, or a buffer of words.
struct HistoryResource {
    std::string name;
    bool buffer = false;
    bool floats = true; // float image (checked finite, poisoned with NaN/Inf/denormals); else words
};

// The histories of an effect (both ping-pong copies), by the plans' names.
std::vector<HistoryResource> effectHistories(const std::string& effect, const SettingValues& settings);

struct EffectFrame {
    std::string effect;
    bool refused = false;
    std::string error; // the planner's line when refused
    std::vector<gpu::DecodedOutput> outputs;
};

class EffectSet {
  public:
    // `geometry`: the scene the hybrid effect ray traces (needed only with "hybrid").
    EffectSet(const gpu::Context& context, const capture::Frame& first,
              const capture::Environment& environment, std::vector<std::string> effects,
              SettingValues settings, const scene::Scene* geometry);
    ~EffectSet();
    EffectSet(const EffectSet&) = delete;
    EffectSet& operator=(const EffectSet&) = delete;

    // Changes the texels of one input (not PreviousDepth, which is last frame's uploaded depth) before
    // they are uploaded on the next run(); cleared by run().
    using InputHook = std::function<void(InputKind kind, std::vector<float>& texels, std::uint32_t channels)>;
    void poisonInputs(InputHook hook) { hook_ = std::move(hook); }
    // The environment for the next run() only (the clean one is uploaded again after it).
    void poisonEnvironment(std::vector<float> rgba);

    // Runs one frame through every effect; the first frame and `cut` reset every history. With
    // `read`, every final output is read back.
    std::vector<EffectFrame> run(const capture::Frame& frame, bool cut, bool read);

    const std::vector<std::string>& effects() const { return names_; }
    gpu::EffectRunner& runner(const std::string& effect);
    bool ran(const std::string& effect) const; // whether the effect's runner exists (planned once)

  private:
    struct Running;
    const gpu::Context& context_;
    const capture::Environment& environment_;
    std::vector<std::string> names_;
    SettingValues settings_;
    std::vector<std::unique_ptr<Running>> running_;
    std::unique_ptr<gpu::InputImages> inputs_;
    std::unique_ptr<scene::SceneBuffers> scene_;
    std::vector<float> previousDepth_;
    std::vector<float> poisonedEnvironment_;
    bool environmentPoisoned_ = false, environmentDirty_ = true;
    InputHook hook_;
    std::uint32_t frame_ = 0;
};

} // namespace glint::test
