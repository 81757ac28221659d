// The shadow denoiser on the bundled scenes whose shadows move (harness/scenes): a sun of 0.27
// degrees over a walking caster, over pillars while it turns, and a camera cut, and a 5 cm lamp
// swinging over a table. Most of their penumbrae are narrower than a pixel at 160x90, where one
// sample is the answer, so the denoised shadow must be at or below its noisy input on every
// frame, from the first, in the mean error over
// receivers, its RMSE and the moving-edge error (receivers whose reference changed by more than
// 0.25 since the previous frame, docs/replay.md). Without the penumbra estimate (the temporal
// stage and the filter everywhere) the same scenes come out worse: the bounds see the trails.
#include "shadow_denoiser/scene_replay.h"
#include "support/gpu_test_context.h"

#include "replay/replay_frame.h"
#include "scene/scene_file.h"
#include "scene/scene_simulate.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace glint;

namespace {

struct Errors {
    double mean = 0.0, rmse = 0.0, movingEdge = 0.0;
};

struct FrameErrors {
    Errors noisy, denoised;
    std::size_t movingPixels = 0;
};

// |value - reference| over the receivers, and over those of them whose reference moved.
Errors errorsOf(const std::vector<float>& value, std::size_t stride, const std::vector<float>& reference,
                const std::vector<std::uint8_t>& receiver, const std::vector<std::uint8_t>& moved) {
    Errors e;
    std::size_t receivers = 0, movedCount = 0;
    for (std::size_t i = 0; i < reference.size(); ++i) {
        if (!receiver[i]) continue;
        const double error = std::abs(double{value[i * stride]} - double{reference[i]});
        e.mean += error;
        e.rmse += error * error;
        ++receivers;
        if (moved[i]) {
            e.movingEdge += error;
            ++movedCount;
        }
    }
    REQUIRE(receivers > 0u);
    e.mean /= static_cast<double>(receivers);
    e.rmse = std::sqrt(e.rmse / static_cast<double>(receivers));
    if (movedCount > 0) e.movingEdge /= static_cast<double>(movedCount);
    return e;
}

std::vector<FrameErrors> sceneErrors(const scene::Simulation& sim, bool penumbraAware) {
    std::vector<FrameErrors> errors;
    test::SceneShadowReplay replayer(penumbraAware);
    std::vector<float> previousReference;
    for (std::uint32_t index = 0; index < sim.frames.size(); ++index) {
        const capture::Frame& frame = sim.frames[index];
        const auto [inputs, outputs, hard] = replayer.run(frame, index);
        const std::vector<float> reference = replay::layerChannels(frame, "reference.shadow", 1);
        std::vector<std::uint8_t> receiver(reference.size()), moved(reference.size(), 0u);
        FrameErrors e;
        for (std::size_t i = 0; i < reference.size(); ++i) {
            const float d = inputs.depth[i];
            receiver[i] = std::isfinite(d) && d > 1e-6f && d < 1.0f - 1e-6f ? 1u : 0u;
            if (!previousReference.empty() && receiver[i] &&
                std::abs(reference[i] - previousReference[i]) > 0.25f)
                moved[i] = 1u;
            e.movingPixels += moved[i];
        }
        e.noisy = errorsOf(inputs.visibility, 1, reference, receiver, moved);
        e.denoised = errorsOf(outputs.filtered, 2, reference, receiver, moved);
        previousReference = reference;
        errors.push_back(e);
    }
    return errors;
}

// Frames on which the denoised shadow is above its input in any of the three errors.
std::size_t framesAboveInput(const std::vector<FrameErrors>& errors, std::string& table) {
    std::size_t above = 0;
    for (std::size_t f = 0; f < errors.size(); ++f) {
        const FrameErrors& e = errors[f];
        const bool worse = e.denoised.mean > e.noisy.mean || e.denoised.rmse > e.noisy.rmse ||
                           e.denoised.movingEdge > e.noisy.movingEdge;
        above += worse ? 1u : 0u;
        table += std::to_string(f) + ": mean " + std::to_string(e.noisy.mean) + " / " +
                 std::to_string(e.denoised.mean) + ", rmse " + std::to_string(e.noisy.rmse) + " / " +
                 std::to_string(e.denoised.rmse) + ", moving edge " + std::to_string(e.noisy.movingEdge) +
                 " / " + std::to_string(e.denoised.movingEdge) + " (" + std::to_string(e.movingPixels) +
                 " px)" + (worse ? " above" : "") + "\n";
    }
    return above;
}

} // namespace

TEST_CASE("moving shadows of small lights: denoised at or below the noisy input on every frame", "[moving]") {
    for (const char* name : {"sun_walker", "time_of_day", "shadow_cut", "swinging_lamp"}) {
        scene::Scene scene =
            scene::loadScene(std::string(GLINT_SOURCE_DIR "/harness/scenes/") + name + ".toml");
        // The reference's own noise enters noisy and denoised errors alike: 16 samples suffice.
        scene.reference.samplesPerPixel = 16;
        const scene::Simulation sim = scene::simulate(test::testContext(), scene);
        REQUIRE(sim.frames.size() == 32u);
        std::string table, without;
        const std::size_t above = framesAboveInput(sceneErrors(sim, true), table);
        const std::size_t aboveWithout = framesAboveInput(sceneErrors(sim, false), without);
        INFO(name << ", noisy / denoised per frame:\n"
                  << table << "without the penumbra estimate:\n"
                  << without);
        CHECK(above == 0u);
        CHECK(aboveWithout >= 8u);
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
