// A box slides over a glossy floor (harness/scenes/disocclusion.toml, frames 0-5) and then
// rests. After it stops, the denoised error against each frame's reference recovers to the
// level a fresh run on the resting frame reaches, within a stated number of frames.
#include "reflections_denoiser/denoiser_scene.h"
#include "support/gpu_test_context.h"

#include "support/test_replay.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace glint;

namespace {

std::vector<double> denoisedErrors(const test::DenoiserScene& scene,
                                   const std::vector<std::size_t>& frameOrder) {
    SssrDesc desc = scene.desc;
    desc.denoise = true;
    gpu::SssrRunner runner(test::testContext(), desc);
    std::vector<double> errors;
    for (std::uint32_t index = 0; index < frameOrder.size(); ++index) {
        const capture::Frame& frame = scene.frames.at(frameOrder[index]);
        gpu::SssrFrameInputs inputs;
        SssrDesc frameDesc = desc;
        replay::sssrFromFrame(frame, scene.environment, frameDesc, inputs);
        frameDesc.denoise = true;
        frameDesc.frameIndex = index;
        runner.upload(inputs);
        const ReflectionsDenoiserDesc denoiser =
            replay::denoiserFromFrame(frame, frameDesc, index, index == 0);
        runner.run(frameDesc, nullptr, &denoiser);
        const gpu::SssrFrameOutputs out = runner.readback();
        for (float value : out.radiance) REQUIRE(std::isfinite(value));
        errors.push_back(test::glossyError(frame, out.radiance, desc.roughnessThreshold));
    }
    return errors;
}

std::string trace(const std::vector<double>& values) {
    std::string text;
    for (double v : values) text += std::to_string(v).substr(0, 5) + " ";
    return text;
}

} // namespace

TEST_CASE("after a moving box stops, the denoised error recovers within 8 frames",
          "[reflections_denoiser][ghosting]") {
    constexpr std::size_t kFrames = 16;
    const test::DenoiserScene scene = test::simulateDenoiserScene("disocclusion", 160, 90, kFrames);
    std::vector<std::size_t> animated, resting;
    for (std::size_t i = 0; i < kFrames; ++i) {
        animated.push_back(i);
        resting.push_back(kFrames - 1);
    }
    const std::vector<double> moving = denoisedErrors(scene, animated);
    const std::vector<double> fresh = denoisedErrors(scene, resting);
    INFO("moving then resting: " << trace(moving) << "\nfresh on the resting frame: " << trace(fresh));
    WARN("moving then resting: " << trace(moving) << "\nfresh on the resting frame: " << trace(fresh));
    // Measured on lavapipe, 2026-11-22 (luminance relative error over glossy pixels):
    // moving 0.056 0.045 0.095 0.133 0.122 0.105 (box stops at frame 5) 0.095 0.081 0.082
    // 0.081 0.075 0.072 0.071 0.072 0.069 0.070; fresh run settles at 0.061. Bounds: eight
    // frames after the box stops the error is within 1.25x of the fresh steady error (measured
    // 1.18x), and while it moves it never exceeds 3x (measured 2.2x).
    const double steady = fresh.back();
    CHECK(moving[5 + 8] < 1.25 * steady);
    for (std::size_t i = 0; i < kFrames; ++i) CHECK(moving[i] < 3.0 * steady);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
