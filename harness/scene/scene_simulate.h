// Renders a scene's frames on the GPU into capture frames (format v1), computing only the
// layers and passes its declared effects call for (docs/scenes.md, "What gets computed").
#pragma once

#include "capture/capture_frame.h"
#include "capture/environment_io.h"
#include "scene/scene_types.h"

#include <gpu/gpu_context.h>

#include <optional>
#include <string>
#include <vector>

namespace glint::scene {

struct PassTime {
    std::string pass;        // e.g. "gbuffer", "shade", "shadow", "reference.reflection"
    double milliseconds = 0; // GPU time summed over all frames; < 0 when not measured
};

struct Simulation {
    std::vector<capture::Frame> frames;
    std::optional<capture::Environment> environment; // only for reflections
    std::vector<std::string> layers;                 // layers written into every frame
    std::vector<PassTime> passes;                    // passes run for every frame, in order
    std::size_t primitives = 0;                      // of the first frame
    // Per frame, the samples per pixel behind its references: the scene's spp times the frames
    // of the run of unchanged frames it ends (ReferenceDesc::accumulate).
    std::vector<std::uint32_t> referenceSamples;
    // Surface pixels (over all frames) whose device depth the background test (within 1e-6 of
    // the far value, docs/conventions.md §2.2) takes for the sky: they replay as sky.
    std::size_t surfacesAtBackgroundDepth = 0;
    std::vector<std::string> warnings; // one line each, naming the scene file; for stderr
};

// Throws SceneError for scene problems (missing model...), std::runtime_error for GPU ones.
Simulation simulate(const gpu::Context& context, const Scene& scene);

// The one-line warning for `pixels` surface pixels at the background depth on `frames` frames
// (empty when there are none).
std::string backgroundDepthWarning(const Scene& scene, std::size_t pixels, std::uint32_t frames);

// The effect names the capture declares: hybrid reflections read the reflection layers, so
// "hybrid" is written as "reflections".
std::vector<std::string> captureEffects(const Scene& scene);

} // namespace glint::scene
