// A box slides over a glossy floor (harness/scenes/disocclusion.toml, frames 0-5) and then
// rests. After it stops, the denoised error against each frame's reference recovers to the
// level a fresh run on the resting frame reaches, within a stated number of frames; and from
// the second frame on, while the box's reflection moves too, the denoised error is at most the
// noisy input's (the resolve's anti-lag).
#include "reflections_denoiser/denoiser_scene.h"
#include "support/gpu_test_context.h"

#include "support/test_replay.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace glint;

namespace {

// The error of each frame's output: the denoised reflection, or with `denoise` false SSSR's
// noisy input.
std::vector<double> frameErrors(const test::DenoiserScene& scene, const std::vector<std::size_t>& frameOrder,
                                bool denoise = true) {
    const std::vector<std::vector<float>> radiance = test::runDenoiserFrames(scene, frameOrder, denoise);
    std::vector<double> errors;
    for (std::size_t i = 0; i < frameOrder.size(); ++i)
        errors.push_back(
            test::glossyError(scene.frames.at(frameOrder[i]), radiance[i], scene.desc.roughnessThreshold));
    return errors;
}

std::string trace(const std::vector<double>& values) {
    std::string text;
    for (double v : values) text += std::to_string(v).substr(0, 5) + " ";
    return text;
}

} // namespace

TEST_CASE("after a moving box stops, the denoised error recovers within 8 frames, and it never exceeds the "
          "noisy input's from the second frame on",
          "[reflections_denoiser][ghosting]") {
    constexpr std::size_t kFrames = 16;
    // References of 8 samples on every frame: the resting frames' errors are compared with the
    // moving frames', so their references must be as noisy (accumulated ones would lower the
    // steady error and with it every bound below).
    const test::DenoiserScene scene = test::simulateDenoiserScene("disocclusion", 160, 90, kFrames, false);
    std::vector<std::size_t> animated, resting;
    for (std::size_t i = 0; i < kFrames; ++i) {
        animated.push_back(i);
        resting.push_back(kFrames - 1);
    }
    const std::vector<double> moving = frameErrors(scene, animated);
    const std::vector<double> fresh = frameErrors(scene, resting);
    const std::vector<double> noisy = frameErrors(scene, animated, false);
    INFO("moving then resting: " << trace(moving) << "\nfresh on the resting frame: " << trace(fresh)
                                 << "\nnoisy input: " << trace(noisy));
    WARN("moving then resting: " << trace(moving) << "\nfresh on the resting frame: " << trace(fresh)
                                 << "\nnoisy input: " << trace(noisy));
    // Measured on lavapipe (luminance relative error over glossy pixels against the scene's
    // reference, 2026-12-04), with the resolve's anti-lag: moving 0.091 0.078 0.111 0.119 0.112
    // 0.110 (box stops at frame 5) 0.108 0.107 0.102 0.106 0.103 0.102 0.100 0.102 0.100 0.100;
    // noisy input 0.121 0.103 0.130 0.138 0.124 0.132 0.140 0.129 0.126 0.135 0.132 0.137 0.124
    // 0.136 0.134 0.130; a fresh run on the resting frame settles at 0.099. With denoiser.antiLag
    // off the moving run is 0.091 0.084 0.135 0.174 0.152 0.138 0.128 0.123 0.117 0.121 0.115
    // 0.114 0.110 0.112 0.108 0.108: eight frames after the stop 1.13x the steady error (1.01x
    // with it), at most 1.76x while the box moves (1.20x with it), above the noisy input on frames
    // 2-5. Each bound sits at the geometric mean of the two runs' values, so each fails without
    // the anti-lag: within 1.07x eight frames after the stop, within 1.45x on every frame, and
    // from frame 1 on at most the noisy input's (closest: frame 4, 0.90x).
    const double steady = fresh.back();
    CHECK(moving[5 + 8] < 1.07 * steady);
    for (std::size_t i = 0; i < kFrames; ++i) CHECK(moving[i] < 1.45 * steady);
    for (std::size_t i = 1; i < kFrames; ++i) {
        INFO("frame " << i);
        CHECK(moving[i] <= noisy[i]);
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
