// A low sun whose disc has radiance 1e5 reflected by a glossy metal floor and a chrome ball
// (harness/scenes/hdr_sun_glare.toml): the highlight carries most of the frame's energy, and a
// denoiser that weights bright samples down (the tile average does, to tame fireflies) loses it.
// On every frame the denoised RMSE against the reference is at most the noisy input's.
#include "reflections_denoiser/denoiser_scene.h"
#include "support/gpu_test_context.h"

#include <catch2/catch.hpp>

#include <string>

using namespace glint;

TEST_CASE("with highlights of radiance 1e5 the denoised RMSE is at most the noisy input's on every frame",
          "[reflections_denoiser][hdr]") {
    constexpr std::size_t kFrames = 4;
    const test::DenoiserScene scene = test::simulateDenoiserScene("hdr_sun_glare", 128, 72, kFrames);
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < kFrames; ++i) order.push_back(i);
    const std::vector<std::vector<float>> denoised = test::runDenoiserFrames(scene, order, true);
    const std::vector<std::vector<float>> noisy = test::runDenoiserFrames(scene, order, false);
    std::string trace;
    std::vector<double> denoisedRmse, noisyRmse;
    for (std::size_t i = 0; i < kFrames; ++i) {
        const capture::Frame& frame = scene.frames[i];
        denoisedRmse.push_back(test::glossyRmse(frame, denoised[i], scene.desc.roughnessThreshold));
        noisyRmse.push_back(test::glossyRmse(frame, noisy[i], scene.desc.roughnessThreshold));
        trace += std::to_string(denoisedRmse.back()) + "/" + std::to_string(noisyRmse.back()) + " ";
    }
    WARN("denoised/noisy RMSE per frame: " << trace);
    // Measured on lavapipe: see docs/reflections_denoiser.md, "Bright highlights".
    for (std::size_t i = 0; i < kFrames; ++i) {
        INFO("frame " << i << ": " << trace);
        REQUIRE(noisyRmse[i] > 1.0); // the highlight is in the frame: the reference's RMSE scale
        CHECK(denoisedRmse[i] <= noisyRmse[i]);
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
