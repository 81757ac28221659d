// Static camera on a simulated scene: SSSR plus the denoiser, frame by frame, against
// reference.reflection over glossy pixels. The error must fall over the frames and end below
// the raw single-frame error and below a stated bound.
#include "reflections_denoiser/denoiser_scene.h"
#include "support/gpu_test_context.h"
#include "support/test_replay.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace glint;

TEST_CASE("static glossy room: the denoised error falls over frames and ends far below one raw frame",
          "[reflections_denoiser][static]") {
    test::DenoiserScene scene = test::simulateDenoiserScene("glossy_room", 160, 90, 1);
    const capture::Frame& frame = scene.frames.at(0);
    SssrDesc desc = scene.desc;
    desc.denoise = true;
    gpu::SssrRunner runner(test::testContext(), desc);
    runner.upload(scene.inputs);

    SssrDesc raw = scene.desc;
    gpu::SssrRunner rawRunner(test::testContext(), raw);
    rawRunner.upload(scene.inputs);
    rawRunner.run(raw);
    const double rawError = test::glossyError(frame, rawRunner.readback().radiance, desc.roughnessThreshold);

    constexpr std::uint32_t kFrames = 24;
    // The plain average of kFrames raw frames (what accumulation without any filter reaches)
    // and of 256 frames (SSSR's own expectation, nearly noise-free: the denoiser's target
    // without the bias SSSR has against the path-traced reference).
    constexpr std::uint32_t kConvergedFrames = 256;
    std::vector<float> average(rawRunner.readback().radiance.size(), 0.0f), converged(average.size(), 0.0f);
    for (std::uint32_t index = 0; index < kConvergedFrames; ++index) {
        raw.frameIndex = index;
        rawRunner.run(raw);
        const std::vector<float> radiance = rawRunner.readback().radiance;
        for (std::size_t i = 0; i < average.size(); ++i) {
            if (index < kFrames) average[i] += radiance[i] / static_cast<float>(kFrames);
            converged[i] += radiance[i] / static_cast<float>(kConvergedFrames);
        }
    }
    const double averageError = test::glossyError(frame, average, desc.roughnessThreshold);

    std::vector<double> errors, noise;
    for (std::uint32_t index = 0; index < kFrames; ++index) {
        desc.frameIndex = index;
        const ReflectionsDenoiserDesc denoiser = replay::denoiserFromFrame(frame, desc, index, index == 0);
        runner.run(desc, nullptr, &denoiser);
        const gpu::SssrFrameOutputs out = runner.readback();
        for (float value : out.radiance) REQUIRE(std::isfinite(value));
        errors.push_back(test::glossyError(frame, out.radiance, desc.roughnessThreshold));
        noise.push_back(test::glossyError(frame, out.radiance, converged, desc.roughnessThreshold));
    }
    std::string trace, noiseTrace;
    for (double e : errors) trace += std::to_string(e).substr(0, 5) + " ";
    for (double e : noise) noiseTrace += std::to_string(e).substr(0, 5) + " ";
    WARN("against SSSR's converged mean per frame: " << noiseTrace);
    INFO("raw single frame " << rawError << ", plain average of " << kFrames << " frames " << averageError
                             << "; denoised per frame: " << trace);
    WARN("raw single frame " << rawError << ", plain average of " << kFrames << " frames " << averageError
                             << "; denoised per frame: " << trace);
    REQUIRE(rawError > 0.0);
    // The figures are in docs/reflections_denoiser.md ("Tests"); the warnings print them. The
    // error left against the reference is SSSR's bias (off-screen geometry, the box-filtered
    // environment), which no denoiser can remove.
    CHECK(errors.back() < 0.6 * rawError);
    CHECK(errors.back() < averageError);
    CHECK(noise.back() < 0.75 * noise.front());
    CHECK(noise.back() < 0.12);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
