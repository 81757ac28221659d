// Static scene from the simulator: the denoised shadow's error against reference.shadow over
// penumbra pixels, frame by frame. The error must keep falling and end at the plain average of
// the input over the same frames (see the numbers below and docs/shadow_denoiser.md).
#include "shadow_denoiser/scene_replay.h"
#include "support/gpu_test_context.h"

#include "replay/replay_sssr.h"
#include "scene/scene_file.h"
#include "scene/scene_simulate.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace glint;

namespace {

constexpr std::uint32_t kFrames = 32;

// Mean absolute error over penumbra receivers (reference strictly between 0.05 and 0.95).
double penumbraError(const std::vector<float>& value, std::size_t stride,
                     const std::vector<float>& reference) {
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < reference.size(); ++i) {
        if (!(reference[i] > 0.05f && reference[i] < 0.95f)) continue;
        sum += std::abs(static_cast<double>(value[i * stride]) - static_cast<double>(reference[i]));
        ++count;
    }
    REQUIRE(count > 100u);
    return sum / static_cast<double>(count);
}

} // namespace

TEST_CASE("static courtyard: the penumbra error converges to the plain input average", "[convergence]") {
    scene::Scene scene = scene::loadScene(GLINT_SOURCE_DIR "/harness/scenes/courtyard_penumbra.toml");
    scene.frameCount = kFrames;
    scene.reference.shadows = true;
    scene.reference.samplesPerPixel = 64;
    scene::Simulation sim = scene::simulate(test::testContext(), scene);
    REQUIRE(sim.frames.size() == kFrames);

    test::SceneShadowReplay replayer;
    std::vector<float> average;
    double first = 0.0, last = 0.0, averaged = 0.0, early = 0.0, late = 0.0;
    for (std::uint32_t index = 0; index < kFrames; ++index) {
        const capture::Frame& frame = sim.frames[index];
        const auto [inputs, outputs] = replayer.run(frame, index);
        const std::vector<float> reference = replay::layerChannels(frame, "reference.shadow", 1);
        const double error = penumbraError(outputs.filtered, 2, reference);
        if (index == 0) first = error;
        if (index < 4) early += error / 4.0;
        if (index + 4 >= kFrames) late += error / 4.0;
        last = error;
        if (average.empty()) average.assign(inputs.visibility.size(), 0.0f);
        for (std::size_t i = 0; i < average.size(); ++i) average[i] += inputs.visibility[i] / float(kFrames);
        if (index + 1 == kFrames) averaged = penumbraError(average, 1, reference);
    }
    INFO("penumbra MAE: frame 0 " << first << ", frame " << kFrames - 1 << " " << last << ", plain "
                                  << kFrames << "-frame average of the input " << averaged);
    // Measured on lavapipe at 160x90 over 32 frames (the FidelityFX-style version before the
    // fix: 0.155 at frame 0, best 0.108 at frame 6, 0.155 at frame 15, 0.147 at frame 31):
    // frame 0 0.201, frames 0-3 mean 0.17, frame 15 0.085, frame 31 0.068 against 0.0663 for the
    // plain 32-frame average of the input. The error now falls monotonically (to within noise)
    // towards the plain average; it does NOT get below it at this size: only ~130 pixels are
    // penumbra and their penumbrae are 1-3 pixels wide, so even a 3x3 blur of the converged
    // reference itself has an error of 0.104 there, and any spatial filtering adds bias.
    CHECK(late < 0.6 * early);
    CHECK(last < 0.5 * first);
    CHECK(last < 1.05 * averaged);
    WARN("penumbra MAE: frame 0 " << first << ", frame " << kFrames - 1 << " " << last << ", input average "
                                  << averaged);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
