// Measurement, not a test (hidden: run it by its tag): the penumbra error of the denoiser after
// 32 static frames, next to the plain 32-frame average of its input, on the courtyard at a size
// and light angle given in the environment. For comparisons with published numbers, e.g.
//   GLINT_MEASURE_SIZE=640x360 GLINT_MEASURE_ANGLE=2 glint_tests_shadow_denoiser_scene "[.measure-penumbra]"
// The reference is rendered once (frame 0 of the same static scene, its own random numbers):
// rendering it for every frame costs most of the time at large sizes and only the last frame's
// error is wanted.
#include "shadow_denoiser/scene_replay.h"
#include "support/gpu_test_context.h"

#include "replay/replay_frame.h"
#include "scene/scene_file.h"
#include "scene/scene_simulate.h"

#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace glint;

namespace {

std::string environment(const char* name, const char* fallback) {
    const char* value = std::getenv(name);
    return value ? value : fallback;
}

// Mean absolute error over penumbra receivers (reference strictly between 0.05 and 0.95).
double penumbraError(const std::vector<float>& value, std::size_t stride, const std::vector<float>& reference,
                     std::size_t& count) {
    double sum = 0.0;
    count = 0;
    for (std::size_t i = 0; i < reference.size(); ++i) {
        if (!(reference[i] > 0.05f && reference[i] < 0.95f)) continue;
        sum += std::abs(static_cast<double>(value[i * stride]) - static_cast<double>(reference[i]));
        ++count;
    }
    return count ? sum / static_cast<double>(count) : -1.0;
}

} // namespace

TEST_CASE("penumbra error after 32 static frames at a given size and light", "[.measure-penumbra]") {
    constexpr std::uint32_t kFrames = 32;
    unsigned width = 160, height = 90;
    REQUIRE(std::sscanf(environment("GLINT_MEASURE_SIZE", "160x90").c_str(), "%ux%u", &width, &height) == 2);
    const float angle = std::stof(environment("GLINT_MEASURE_ANGLE", "3"));
    const auto spp = static_cast<std::uint32_t>(std::stoul(environment("GLINT_MEASURE_SPP", "64")));

    scene::Scene scene = scene::loadScene(GLINT_SOURCE_DIR "/harness/scenes/courtyard_penumbra.toml");
    scene.width = width;
    scene.height = height;
    scene.lights.at(scene.shadowLight).angularRadiusDegrees = angle;
    scene.frameCount = kFrames;
    scene.reference.shadows = false;
    const auto start = std::chrono::steady_clock::now();
    const scene::Simulation sim = scene::simulate(test::testContext(), scene);
    scene::Scene still = scene;
    still.frameCount = 1;
    still.reference.shadows = true;
    still.reference.samplesPerPixel = spp;
    const scene::Simulation referenceSim = scene::simulate(test::testContext(), still);
    const std::vector<float> reference =
        replay::layerChannels(referenceSim.frames.at(0), "reference.shadow", 1);
    const auto simulated = std::chrono::steady_clock::now();

    test::SceneShadowReplay replayer;
    std::vector<float> average;
    std::vector<float> last;
    for (std::uint32_t index = 0; index < kFrames; ++index) {
        const auto [inputs, outputs, hard] = replayer.run(sim.frames[index], index);
        if (average.empty()) average.assign(inputs.visibility.size(), 0.0f);
        for (std::size_t i = 0; i < average.size(); ++i)
            average[i] += inputs.visibility[i] / static_cast<float>(kFrames);
        if (index + 1 == kFrames) last = outputs.filtered;
    }
    std::size_t count = 0;
    const double denoised = penumbraError(last, 2, reference, count);
    const double plain = penumbraError(average, 1, reference, count);
    WARN(width << "x" << height << ", light " << angle << " deg, reference " << spp << " spp, " << count
               << " penumbra pixels: frame " << kFrames - 1 << " denoised " << denoised << ", plain "
               << kFrames << "-frame average " << plain << " (simulated in "
               << std::chrono::duration<double>(simulated - start).count() << " s, denoised in "
               << std::chrono::duration<double>(std::chrono::steady_clock::now() - simulated).count()
               << " s)");
    CHECK(count > 0u);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
