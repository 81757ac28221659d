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
    const test::DenoiserScene scene = test::simulateDenoiserScene("disocclusion", 160, 90, kFrames);
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
    // 8-spp reference), with the resolve's anti-lag: moving 0.055 0.039 0.079 0.097 0.087 0.074
    // (box stops at frame 5) 0.071 0.063 0.062 0.064 0.063 0.059 0.058 0.060 0.058 0.062; noisy
    // input 0.090 0.071 0.099 0.111 0.094 0.102 0.111 0.096 0.095 0.102 0.100 0.102 0.096 0.104
    // 0.104 0.104; a fresh run settles at 0.062, with or without the anti-lag (the same values to
    // three digits on every frame). With denoiser.antiLag off the moving run is 0.055 0.044 0.097
    // 0.139 0.121 0.100 0.092 0.080 0.077 0.078 0.075 0.070 0.068 0.070 0.067 0.071, above the
    // noisy input on frames 3 and 4. Bounds: eight frames after the box stops the error is within
    // 1.25x of the fresh steady error (measured 0.97x); while it moves it never exceeds 3x
    // (measured 1.6x); and from frame 1 on it is at most the noisy input's (closest: frame 4,
    // 0.93x).
    const double steady = fresh.back();
    CHECK(moving[5 + 8] < 1.25 * steady);
    for (std::size_t i = 0; i < kFrames; ++i) CHECK(moving[i] < 3.0 * steady);
    for (std::size_t i = 1; i < kFrames; ++i) {
        INFO("frame " << i);
        CHECK(moving[i] <= noisy[i]);
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
