// Runs the effects a capture declares (or the ones asked for) frame after frame, carrying
// every history across the sequence, and hands back named images, per-pass GPU times and
// counters. The engine of `glint run`, `glint dump`, `glint check`, `glint bench` on captures
// and `glint study`.
//
// Image names are "<effect>/<image>" and each names the pass that produced it, so that dump and
// check can select by pass. Effects and what they return:
//   depth_pyramid  mip<k> (closest depth per level, the pyramid SSSR would read)
//   reflections    input (lit colour), noisy (SSSR radiance), denoised (with denoise),
//                  composite (with composite), confidence, reference (when the capture has one)
//                  + intermediates: pyramid_mip<k>, roughness, ray_list (1 traced, 0 not),
//                  tile_list (1 listed 8x8 tile), ray_class, iterations (debugOutput), variance
//   shadows        noisy (visibility), denoised, variance, reference (when the capture has one)
//                  + intermediates: mask (the packed bits), tile_class (0 filtered, 1 cleared
//                  shadow, 3 cleared lit), moments (mean, M2, n)
#pragma once

#include "capture/capture_frame.h"
#include "capture/environment_io.h"
#include "replay/replay_settings.h"
#include "report/report_image.h"

#include <gpu/gpu_context.h>

#include <memory>
#include <string>
#include <vector>

namespace glint::replay {

// The effects replay knows, in the order they run.
const std::vector<std::string>& knownEffects();

// `requested` (or, when empty, the frame's declared effects), checked against what the frame
// can feed. Throws std::invalid_argument with one line naming the effect and the missing layer.
std::vector<std::string> effectsToRun(const capture::Frame& frame, const std::vector<std::string>& requested);

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

struct SessionOptions {
    std::vector<std::string> effects; // empty: the first frame's declared effects
    EffectSettings settings;
    bool intermediates = false; // also every intermediate (glint dump)
    bool readback = true;       // false: timings and counters only (benchmarks)
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
    // The last frame again, as the next frame index, without uploading anything: back-to-back
    // GPU work for benchmarks (uploads between timed frames let the GPU clock down). Timings
    // and counters only; the camera is treated as static.
    FrameResult repeat();
    const std::vector<std::string>& effects() const { return effects_; }

    struct Reflections;
    struct Shadows;
    struct Pyramid;

  private:
    const gpu::Context& context_;
    SessionOptions options_;
    std::vector<std::string> effects_;
    std::uint32_t width_ = 0, height_ = 0, frame_ = 0;
    std::unique_ptr<Pyramid> pyramid_;
    std::unique_ptr<Reflections> reflections_;
    std::unique_ptr<Shadows> shadows_;
};

} // namespace glint::replay
