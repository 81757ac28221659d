// The hard cases of the long robustness sequences (long_sequence_test.cpp): one small analytic
// scene (a glossy floor, a mirror wall, a fully rough box, a glossy metal sphere, a sun and a
// sky) seen in many ways, each for kFrames frames, with what makes it hard: the camera's pose and
// motion, the depth convention, the size, the materials, camera cuts and teleports, degenerate
// or non-invertible matrices on some frames.
#pragma once

#include "capture/capture_frame.h"
#include "scene/scene_types.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace glint::test {

// 130 frames: one burst of injection starting by frame 34, followed by a window of at least 93
// frames, ten more than the slowest recovery bound (the hybrid's tile classes coupling, measured
// within 51 frames, plus its denoiser's 32). One frame of both runs (clean and poisoned, four
// effects, every output read back) takes about 0.13 s in the ASan debug build on lavapipe, so the
// length is CI time: the suite is the largest share of it (CONTRIBUTING.md, "Test time").
inline constexpr std::uint32_t kFrames = 130;

struct HardCase {
    std::string name;
    std::uint32_t width = 32, height = 18;
    std::function<void(scene::Scene&)> scene;                 // changes to the base scene
    std::function<void(std::vector<capture::Frame>&)> frames; // changes to the simulated frames
    std::vector<std::uint32_t> cuts;                          // frames run with a history reset
    std::vector<std::uint32_t> degenerate;                    // frames whose matrices `frames` broke
    bool refusedOnDegenerate = true; // the camera effects must refuse those frames (else: run, finite)
    std::uint32_t seed = 1;          // of the injection schedule
};

// The base scene at `width` x `height`, kFrames frames, the camera panning slowly over the
// floor toward the mirror, for reflections, shadows and hybrid reflections.
scene::Scene baseScene(std::uint32_t width, std::uint32_t height);

std::vector<HardCase> hardCases();

} // namespace glint::test
