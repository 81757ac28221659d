// Hybrid reflections on a simulated scene against its reference.reflection: the mirror
// corridor's walls reflect each other and what is behind the camera, which screen space cannot
// see. SSSR and the hybrid trace the same samples (frame 0, mirrors and the glossy floor); the
// hybrid hands the rays screen space cannot answer to the ray tracer over the scene's own
// geometry (harness/scene/scene_buffers.h), so its error must be at least 2x lower (the issue's
// requirement), while on pixels where SSSR was confident the two agree.
#include "hybrid/hybrid_test_frame.h"
#include "support/gpu_test_context.h"
#include "support/test_replay.h"

#include <gpu/gpu_effect_runner.h>
#include <gpu/gpu_transfer.h>
#include <replay/replay_frame.h>
#include <scene/scene_buffers.h>
#include <scene/scene_file.h>
#include <scene/scene_shaders.h>
#include <scene/scene_simulate.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

using namespace glint;

namespace {

constexpr double kLuminance[3] = {0.2126, 0.7152, 0.0722}; // Rec. 709

// Mean over `mask` of the luminance-weighted absolute difference relative to the reference
// (floored at 0.05), each pixel capped at 1: one firefly cannot dominate.
double relativeError(const std::vector<float>& rgba, const std::vector<float>& reference,
                     const std::vector<bool>& mask) {
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < mask.size(); ++i) {
        if (!mask[i]) continue;
        double difference = 0.0, luminance = 0.0;
        for (std::size_t c = 0; c < 3; ++c) {
            difference += kLuminance[c] * std::abs(double(rgba[4 * i + c]) - double(reference[3 * i + c]));
            luminance += kLuminance[c] * double(reference[3 * i + c]);
        }
        sum += std::min(difference / std::max(luminance, 0.05), 1.0);
        ++count;
    }
    return count ? sum / double(count) : 0.0;
}

} // namespace

TEST_CASE("on the mirror corridor the hybrid's error is at least 2x lower than SSSR's", "[hybrid][scene]") {
    scene::Scene scene = scene::loadScene(GLINT_SOURCE_DIR "/harness/scenes/mirror_corridor.toml");
    scene.width = 160;
    scene.height = 90;
    scene.frameCount = 1;
    scene.reference.reflections = true;
    scene.reference.samplesPerPixel = 16;
    const scene::Simulation sim = scene::simulate(test::testContext(), scene);
    REQUIRE(sim.environment.has_value());
    test::SssrTestView view;
    view.desc.samplesPerQuad = 4;
    replay::sssrFromFrame(sim.frames[0], *sim.environment, view.desc, view.inputs);
    const std::vector<float> reference = replay::layerChannels(sim.frames[0], "reference.reflection", 3);

    gpu::SssrRunner sssr(test::testContext(), view.desc);
    sssr.upload(view.inputs);
    sssr.run(view.desc);
    const gpu::SssrFrameOutputs screenSpace = sssr.readback();

    HybridDesc desc;
    desc.sssr = view.desc;
    desc.feedback = false; // frame 0 has no statistics: every tile tries screen space first
    scene::SceneBuffers buffers(test::testContext(), scene);
    const std::uint32_t tiles = ((160 + 7) / 8) * ((90 + 7) / 8);
    const auto run = [&](const HybridDesc& d) {
        return test::runHybridFrame(d, view, std::vector<std::uint32_t>(tiles, 0u), {},
                                    [&](vk::ResourceTable& table) { buffers.addTo(table); });
    };
    // Screen-colour mode with SSSR's own thickness: its screen-space half is SSSR exactly.
    HybridDesc screenColour = desc;
    screenColour.reshade = false;
    screenColour.thicknessRoughnessGrowth = 0.0f;
    screenColour.thicknessDistanceGrowth = 0.0f;
    const test::HybridFrame hybrid = run(screenColour);
    const test::HybridFrame reshaded = run(desc); // the defaults

    // The glossy pixels (the ones both trace), from the capture alone.
    std::vector<bool> glossy(std::size_t{160} * 90, false), confident = glossy;
    std::size_t glossyCount = 0, confidentCount = 0;
    for (std::size_t i = 0; i < glossy.size(); ++i) {
        const float alpha = screenSpace.roughness[i];
        glossy[i] = alpha < view.desc.roughnessThreshold;
        confident[i] = glossy[i] && screenSpace.confidence[i] >= desc.confidenceThreshold;
        glossyCount += glossy[i];
        confidentCount += confident[i];
    }
    REQUIRE(glossyCount > 1000);
    const double sssrError = relativeError(screenSpace.radiance, reference, glossy);
    const double hybridError = relativeError(hybrid.radiance, reference, glossy);
    const double reshadedError = relativeError(reshaded.radiance, reference, glossy);
    const double sssrConfidentError = relativeError(screenSpace.radiance, reference, confident);
    const double reshadedConfidentError = relativeError(reshaded.radiance, reference, confident);
    INFO("glossy pixels " << glossyCount << ", SSSR error " << sssrError << ", hybrid error " << hybridError
                          << " (re-shaded " << reshadedError << "), ray traced " << hybrid.hwList.size()
                          << " (re-shaded run " << reshaded.hwList.size() << ", re-shaded hits "
                          << reshaded.reshadedList.size() << "), SSSR-confident " << confidentCount
                          << " at error " << sssrConfidentError << " (re-shaded " << reshadedConfidentError
                          << ")");
    CHECK(hybrid.hwList.size() > 0);
    CHECK(hybridError * 2.0 <= sssrError);
    CHECK(reshadedError * 2.0 <= sssrError);
    // Where SSSR was confident the screen-colour hybrid keeps its result: the same error there.
    CHECK(relativeError(hybrid.radiance, reference, confident) == Approx(sssrConfidentError).margin(1e-9));
    // Re-shading evaluates the reference's own shading at the surface the colour buffer shows, but
    // toward the reflection ray instead of the camera: no worse than the colour buffer there.
    CHECK(reshaded.reshadedList.size() > 0);
    CHECK(reshadedConfidentError <= sssrConfidentError);
    for (const float value : hybrid.radiance) REQUIRE(std::isfinite(value));
    for (const float value : reshaded.radiance) REQUIRE(std::isfinite(value));
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE(
    "on a static corridor, tiles where screen space fails turn to the ray tracer within two frames and stay",
    "[hybrid][scene][feedback]") {
    scene::Scene scene = scene::loadScene(GLINT_SOURCE_DIR "/harness/scenes/mirror_corridor.toml");
    scene.width = 160;
    scene.height = 90;
    scene.frameCount = 1;
    const scene::Simulation sim = scene::simulate(test::testContext(), scene);
    test::SssrTestView view;
    view.desc.samplesPerQuad = 4;
    replay::sssrFromFrame(sim.frames[0], *sim.environment, view.desc, view.inputs);
    scene::SceneBuffers buffers(test::testContext(), scene);

    HybridDesc desc;
    desc.sssr = view.desc;
    EffectPlan plan;
    std::string error;
    REQUIRE(planHybridReflections(desc, nullptr, plan, &error) == Result::Ok);
    const gpu::Context& context = test::testContext();
    gpu::EffectRunner runner(context, plan, scene::findShader);
    gpu::InputImages inputs(context, view.desc.size, false);
    vk::ResourceTable table = test::uploadInputs(inputs, view);
    buffers.addTo(table);
    const std::size_t tiles = std::size_t{(160 + 7) / 8} * ((90 + 7) / 8);
    std::vector<std::array<std::size_t, 3>> history; // tiles per class, per frame
    for (std::uint32_t frame = 0; frame < 12; ++frame) {
        desc.sssr.frameIndex = frame;
        REQUIRE(planHybridReflections(desc, nullptr, plan, &error) == Result::Ok);
        runner.run(plan, table);
        const std::vector<std::byte> bytes =
            gpu::readbackImageBytes(context, runner.image("hybrid_tile_class"));
        std::vector<std::uint32_t> words(bytes.size() / 4);
        std::memcpy(words.data(), bytes.data(), bytes.size());
        std::size_t counts[3] = {};
        for (const std::uint32_t c : words) ++counts[std::min(c, 2u)];
        INFO("frame " << frame << ": FULL_SW " << counts[0] << ", HALF_SW " << counts[1] << ", FULL_HW "
                      << counts[2]);
        REQUIRE(words.size() == tiles);
        history.push_back({counts[0], counts[1], counts[2]});
    }
    // Screen space was adopted where it works: most tiles end FULL_SW, some stay ray traced.
    CHECK(history[0][0] < tiles / 10);
    CHECK(history[11][0] > tiles / 2);
    CHECK(history[11][2] > 0);
    for (std::size_t frame = 8; frame < 12; ++frame)
        for (std::size_t c = 0; c < 3; ++c) {
            INFO("frame " << frame << " class " << c);
            CHECK(std::abs(static_cast<long>(history[frame][c]) - static_cast<long>(history[7][c])) <= 4);
        }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
