// glint view's playback: the sequence replayed frame after frame through replay::Session (the
// one road every verb takes to the effects), histories carried, looping with a reset; the
// settings and the effects that run changed between frames; the images shown read back on
// demand, only those, so that a frame loop does not pay for every intermediate.
#pragma once

#include "capture/capture_frame.h"
#include "capture/environment_io.h"
#include "replay/replay_error.h"
#include "replay/replay_session.h"

#include <gpu/gpu_context.h>

#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace glint::cli::view {

// The frames to play, however they were opened (a capture, a foreign capture through a map, a
// scene simulated in memory).
struct FrameSource {
    std::size_t count = 0;
    std::function<capture::Frame(std::size_t)> frame; // by index, 0..count-1
    capture::Environment environment;
    std::string description;
};

class Player {
  public:
    // `options.effects`: the effects that can be switched on (all of them on at first).
    // Runs frame 0. Throws std::invalid_argument with one line for what the session refuses.
    Player(const gpu::Context& context, const FrameSource& source, replay::SessionOptions options);
    ~Player();

    // The next frame (after the last: the first again with every history reset, when looping;
    // else nothing, and false). Pending settings and effect changes apply here.
    bool advance(bool loop);
    // The next frame starts every history again.
    void resetHistories() { cut_ = true; }
    // Back to the settings and effects of the last frame that ran, for a change the effects
    // refused when they planned the frame (the next frame then starts a new session).
    void revertChanges();

    // "name=value" from the next frame on; one line of error (nothing changed) when the setting
    // does not exist or its value is out of range.
    std::string setSetting(const std::string& assignment);
    const SettingValues& settings() const { return pending_.settings; }
    // Every effect that can be switched, and which run from the next frame on.
    const std::vector<std::string>& allEffects() const { return allEffects_; }
    bool effectOn(const std::string& effect) const;
    // Switches `effect` from the next frame on; one line of error for an unknown effect or the last one on.
    std::string toggleEffect(const std::string& effect);

    std::size_t frameIndex() const { return index_; } // the capture frame shown
    std::uint64_t framesRun() const { return framesRun_; }
    const std::vector<std::string>& runningEffects() const;
    const std::vector<replay::PassTime>& timings() const { return timings_; }
    const std::vector<replay::Counter>& counters() const { return counters_; }

    // What can be shown for the current frame: every output and intermediate of every running
    // effect, its inputs, its reference and "<effect>/error" against it where the capture has one.
    const std::vector<std::string>& viewNames() const { return viewNames_; }
    // The composite when an effect makes one, else the first effect's final output.
    std::string defaultView() const;
    // The image `name` of the current frame (read back once a frame); nullopt when there is none.
    std::optional<report::Image> image(const std::string& name);
    const capture::Frame& frame() const { return frame_; }
    // The mean errors of the current frame's "<effect>/error" images read so far (replay_error.h:
    // the metric of glint run), by effect.
    const std::map<std::string, replay::ReferenceError>& errors() const { return errors_; }

  private:
    void startSession(bool keepNumbering);
    void runFrame(bool cut);
    const gpu::Context& context_;
    const FrameSource& source_;
    replay::SessionOptions pending_; // the settings and effects of the next frame
    replay::SessionOptions ran_;     // those of the last frame that ran
    std::vector<std::string> allEffects_;
    bool sessionStale_ = false; // the pending settings or effects need a new session
    bool namesStale_ = true;    // viewNames_ to be listed again after the next frame
    std::unique_ptr<replay::Session> session_;
    capture::Frame frame_;
    std::size_t index_ = 0;
    std::uint64_t framesRun_ = 0;
    bool cut_ = false;
    std::vector<replay::PassTime> timings_;
    std::vector<replay::Counter> counters_;
    std::vector<std::string> viewNames_;
    std::map<std::string, report::Image> images_;          // read this frame
    std::map<std::string, replay::ReferenceError> errors_; // this frame's, without their maps
};

} // namespace glint::cli::view
