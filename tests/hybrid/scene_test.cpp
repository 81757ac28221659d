// Hybrid reflections on a simulated scene against its reference.reflection: the mirror
// corridor's walls reflect each other and what is behind the camera, which screen space cannot
// see. SSSR and the hybrid trace the same samples (frame 0, mirrors and the glossy floor); the
// hybrid hands the rays screen space cannot answer to the ray tracer over the scene's own
// geometry (harness/scene/scene_buffers.h), so its error must be at least 2x lower (the issue's
// requirement), while on pixels where SSSR was confident the two agree.
#include "hybrid/hybrid_test_frame.h"
#include "support/gpu_test_context.h"
#include "support/test_replay.h"

#include <replay/replay_frame.h>
#include <scene/scene_buffers.h>
#include <scene/scene_file.h>
#include <scene/scene_simulate.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

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
    const test::HybridFrame hybrid =
        test::runHybridFrame(desc, view, std::vector<std::uint32_t>(tiles, 0u), {},
                             [&](vk::ResourceTable& table) { buffers.addTo(table); });

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
    INFO("glossy pixels " << glossyCount << ", SSSR error " << sssrError << ", hybrid error " << hybridError
                          << ", ray traced " << hybrid.hwList.size() << ", SSSR-confident "
                          << confidentCount);
    CHECK(hybrid.hwList.size() > 0);
    CHECK(hybridError * 2.0 <= sssrError);
    // Where SSSR was confident the hybrid keeps its result: the same error there.
    CHECK(relativeError(hybrid.radiance, reference, confident) ==
          Approx(relativeError(screenSpace.radiance, reference, confident)).margin(1e-9));
    for (const float value : hybrid.radiance) REQUIRE(std::isfinite(value));
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
