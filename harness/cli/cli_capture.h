// What run, dump, check and bench share: opening a capture (a frame file, a sequence folder,
// or foreign EXRs through a channel map), choosing its frames, and a Vulkan context whose
// validation errors turn into exit code 1.
#pragma once

#include "cli_commands.h"

#include "capture/capture_frame.h"
#include "capture/environment_io.h"
#include "replay/replay_session.h"

#include <gpu/gpu_context.h>

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace glint::cli {

class CaptureSource {
  public:
    // `path`: a frame .exr, a sequence folder or its manifest.json; with `mapPath`, a foreign
    // EXR or a folder of them read through that channel map (docs/replay.md). Throws with one
    // line naming what is wrong.
    CaptureSource(const std::string& path, const std::string& mapPath = {});
    ~CaptureSource();

    std::size_t frameCount() const;
    capture::Frame frame(std::size_t index) const;
    // The file (or, for folder frames, the folder) of frame `index`.
    std::string framePath(std::size_t index) const;
    // The number output folders carry for frame `index` (frame_NNNN): the number that ends its
    // file name (Blender's 0001.exr is 1, glint's frame_0000.exr 0) when every frame's name
    // ends in a distinct one, else its position.
    std::size_t frameNumber(std::size_t index) const;
    // The capture's environment, or a black 16x8 lat-long one when it has none (reflection rays
    // that miss then return black, a defined result).
    const capture::Environment& environment() const { return environment_; }
    // The environment file as given, or "none" (with why, for an optional one that is missing).
    const std::string& environmentName() const { return environmentName_; }
    const std::string& description() const { return description_; }
    // The scene file a simulated capture was made from (its manifest's "scene"), or empty.
    std::string sceneFile() const;
    // The effects the first frame declares (a channel map's, for a foreign capture); reads
    // its header only.
    std::vector<std::string> declaredEffects() const;

    // The effects to run (replay::effectsToRun) on frame `index`, read as `frame`; a layer the
    // capture lacks is a one-line error naming the frame's file, the layer and what to do.
    std::vector<std::string> checkEffects(const capture::Frame& frame, std::size_t index,
                                          const replay::SessionOptions& options) const;

    // Checks frames first..last as far as can be done without reading their pixels (header,
    // camera, the layers the effects need, a file large enough for the pixel data it declares),
    // so that a bad frame late in a sequence fails at once, before anything is written: one
    // line naming its file. Depth stored as HALF (legal but lossy) gets one warning line.
    void checkFrames(std::size_t first, std::size_t last, const replay::SessionOptions& options) const;

  private:
    struct Impl;
    Impl* impl_ = nullptr;
    capture::Environment environment_;
    std::string environmentName_ = "none";
    std::string description_;
};

// What run, dump and check run with: --preset's settings for the effects named with --effects,
// or else those the capture declares, then --set (presetThenSettings, cli_presets.h).
std::vector<std::string> settingsWithPreset(const ReplayOptions& options, const CaptureSource& source);

// "frame_0001": the output folder of a frame number.
std::string frameFolderName(std::size_t number);

// A folder without manifest.json is a foreign capture or a mistake: one line saying what to do.
void requireManifest(const std::filesystem::path& folder);

// A black 16x8 lat-long environment, for captures and scenes without one.
capture::Environment blackEnvironment();

// The geometry the effects that ray trace see: `geometryPath` (--geometry, a glTF of the
// capture's scene in its world space) when given, which wins over the manifest's scene; else
// `manifestScene`, the scene file of a capture written by glint simulate. The file is read and
// checked here, before any device work (a SceneError of one line naming it); what it leaves out
// (an ambient light, a spot light's cone) is one warning line each on stderr.
void setGeometry(replay::SessionOptions& options, const std::string& manifestScene,
                 const std::string& geometryPath);

// "a..b" (inclusive), "a.." (to the end), "a" (one frame) or "" (all) -> [first, last] indices
// within `count` frames. Throws std::invalid_argument naming the range.
struct FrameRange {
    std::size_t first = 0, last = 0;
};
FrameRange parseFrames(const std::string& text, std::size_t count);

// Creates a context (with validation when asked), runs `body`, destroys the context. Returns
// body's exit code, or kExitCheckFailed when the validation layer reported errors.
// `configure` adjusts the options first (glint view: presentation to its window).
int withContext(bool validate, const std::function<int(const gpu::Context&)>& body,
                const std::function<void(gpu::ContextOptions&)>& configure = {});

// Replays frames 0..frame (histories build up as in `glint run`) with every intermediate and
// returns the last frame's result. `frameText` "" means the capture's last frame.
replay::FrameResult replayUntil(const gpu::Context& context, const CaptureSource& source,
                                const std::string& frameText, replay::SessionOptions options,
                                std::size_t* frameIndex = nullptr);

// Whether `pass` ("reflections/intersect") is selected by "all", "intersect" or "reflections/intersect".
bool passSelected(const std::string& selection, const std::string& pass);

// Where glint dump writes an image and glint check looks for it: <effect>/<pass>/<image>.
std::filesystem::path dumpPath(const replay::NamedImage& image);

// "reflections/denoised" -> "reflections_denoised".
std::string fileStem(const std::string& imageName);

} // namespace glint::cli
