// Static scene from the simulator: the denoised shadow's error against reference.shadow over
// penumbra pixels, frame by frame. A regression bound for now: the error does not yet fall
// below the plain average of the input (see the numbers below and docs/shadow_denoiser.md).
#include "shadow_denoiser/shadow_runner.h"
#include "support/gpu_test_context.h"

#include "replay/replay_shadow.h"
#include "scene/scene_file.h"
#include "scene/scene_simulate.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

using namespace glint;

namespace {

constexpr std::uint32_t kFrames = 16;

std::vector<float> channels(const capture::Frame& frame, const char* name, std::size_t stride) {
    const capture::Layer* layer = capture::findLayer(frame, name);
    REQUIRE(layer != nullptr);
    const std::size_t count = std::size_t{frame.width} * frame.height;
    const std::size_t have = layer->channels.size();
    std::vector<float> out(count * stride, 0.0f);
    for (std::size_t i = 0; i < count; ++i)
        for (std::size_t c = 0; c < std::min(have, stride); ++c)
            out[i * stride + c] = layer->pixels[i * have + c];
    return out;
}

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

TEST_CASE("static courtyard: the penumbra error stays within the measured bound", "[convergence]") {
    scene::Scene scene = scene::loadScene(GLINT_SOURCE_DIR "/harness/scenes/courtyard_penumbra.toml");
    scene.frameCount = kFrames;
    scene.reference.shadows = true;
    scene.reference.samplesPerPixel = 64;
    scene::Simulation sim = scene::simulate(test::testContext(), scene);
    REQUIRE(sim.frames.size() == kFrames);

    std::optional<test::ShadowRunner> runner;
    std::vector<float> previousDepth;
    std::vector<float> average;
    double first = 0.0, last = 0.0, averaged = 0.0, worst = 0.0;
    for (std::uint32_t index = 0; index < kFrames; ++index) {
        const capture::Frame& frame = sim.frames[index];
        ShadowDenoiserDesc desc;
        replay::shadowDescFromFrame(frame, index, index == 0, desc);
        if (!runner) runner.emplace(desc);
        const test::ShadowInputs inputs = replay::shadowInputsFromFrame(frame, previousDepth);
        const test::ShadowOutputs outputs = runner->run(desc, inputs);
        const std::vector<float> reference = channels(frame, "reference.shadow", 1);
        const double error = penumbraError(outputs.filtered, 2, reference);
        if (index == 0) first = error;
        worst = std::max(worst, error);
        last = error;
        if (average.empty()) average.assign(inputs.visibility.size(), 0.0f);
        for (std::size_t i = 0; i < average.size(); ++i) average[i] += inputs.visibility[i] / float(kFrames);
        if (index + 1 == kFrames) averaged = penumbraError(average, 1, reference);
        previousDepth = inputs.depth;
    }
    INFO("penumbra MAE: frame 0 " << first << ", frame " << kFrames - 1 << " " << last << ", plain "
                                  << kFrames << "-frame average of the input " << averaged);
    // Measured on lavapipe at 160x90: frame 0 0.155, best 0.108 (frame 6), frame 15 0.155; the
    // plain 16-frame average of the input is 0.083. At 480x270: 0.089, best 0.067 (frame 7),
    // 0.088 at frame 23. The error dips while the variance boost still drives the spatial
    // filter, then returns as the boost wears off (n -> 16). The goal (the error falls below
    // the plain average) is NOT met yet; this guards against regressions beyond that level.
    CHECK(worst < 0.18);
    CHECK(last <= first + 0.01);
    WARN("penumbra MAE: frame 0 " << first << ", frame " << kFrames - 1 << " " << last << ", input average "
                                  << averaged);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
