// Mirrors stay sharp: on pixels with GGX alpha below the mirror threshold (roughness 0 in these
// scenes), SSSR traces the exact mirror direction with no noise, so the denoised reflection must
// be at least as close to the path-traced reference as SSSR's own sample, on the first frame
// (no history: the spatial footprint is zero there) and on every later one (a history follows
// the reflected point and is rejected where it disagrees, never smeared).
#include "reflections_denoiser/denoiser_scene.h"
#include "support/gpu_test_context.h"
#include "support/test_replay.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace glint;

namespace {

struct MirrorErrors {
    std::vector<double> denoised, noisy;
};

// Each frame through SSSR with the denoiser and through SSSR alone; both errors over mirror
// pixels against the frame's reference.
MirrorErrors mirrorErrors(const test::DenoiserScene& scene) {
    SssrDesc desc = scene.desc;
    desc.denoise = true;
    gpu::SssrRunner runner(test::testContext(), desc);
    gpu::SssrRunner rawRunner(test::testContext(), scene.desc);
    MirrorErrors errors;
    for (std::uint32_t index = 0; index < scene.frames.size(); ++index) {
        const capture::Frame& frame = scene.frames[index];
        gpu::SssrFrameInputs inputs;
        SssrDesc frameDesc = desc;
        replay::sssrFromFrame(frame, scene.environment, frameDesc, inputs);
        frameDesc.frameIndex = index;
        SssrDesc rawDesc = frameDesc;
        rawDesc.denoise = false;
        frameDesc.denoise = true;
        runner.upload(inputs);
        rawRunner.upload(inputs);
        const ReflectionsDenoiserDesc denoiser =
            replay::denoiserFromFrame(frame, frameDesc, index, index == 0);
        runner.run(frameDesc, nullptr, &denoiser);
        rawRunner.run(rawDesc);
        const gpu::SssrFrameOutputs out = runner.readback();
        for (float value : out.radiance) REQUIRE(std::isfinite(value));
        errors.denoised.push_back(test::glossyError(frame, out.radiance, desc.mirrorThreshold));
        errors.noisy.push_back(test::glossyError(frame, rawRunner.readback().radiance, desc.mirrorThreshold));
    }
    return errors;
}

std::string trace(const std::vector<double>& values) {
    std::string text;
    for (double v : values) text += std::to_string(v).substr(0, 6) + " ";
    return text;
}

void requireNoWorseThanNoisy(const MirrorErrors& errors) {
    INFO("denoised: " << trace(errors.denoised) << "\nnoisy:    " << trace(errors.noisy));
    WARN("denoised: " << trace(errors.denoised) << "\nnoisy:    " << trace(errors.noisy));
    for (std::size_t i = 0; i < errors.noisy.size(); ++i) {
        INFO("frame " << i);
        // Both errors are over the same pixels (glossyError returns -1 when there are none).
        REQUIRE(errors.noisy[i] > 0.0);
        // No tolerance: the denoised image may equal the noisy one (frame 0 must, bit for bit,
        // so the two means are the same double), never be farther from the reference.
        CHECK(errors.denoised[i] <= errors.noisy[i]);
    }
}

} // namespace

TEST_CASE("on a grazing mirror floor the denoised mirror error is at most the noisy input's on every frame",
          "[reflections_denoiser][mirror]") {
    const test::DenoiserScene scene = test::simulateDenoiserScene("mirror_floor", 160, 90, 6);
    const MirrorErrors errors = mirrorErrors(scene);
    requireNoWorseThanNoisy(errors);
    // Frame 0 has no history and mirrors have no spatial footprint: the output is the input.
    CHECK(errors.denoised[0] == errors.noisy[0]);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("a box spinning over a mirror: its moving reflection is not smeared by a stale history",
          "[reflections_denoiser][mirror]") {
    const test::DenoiserScene scene = test::simulateDenoiserScene("spinning_mirror", 160, 90, 6);
    const MirrorErrors errors = mirrorErrors(scene);
    requireNoWorseThanNoisy(errors);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
