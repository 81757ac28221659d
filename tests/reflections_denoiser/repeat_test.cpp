// Two runs of the same frames give bit-identical outputs: SSSR with the low-occupancy exit on
// (its groups of 64 rays come from the ray list's fixed order, docs/sssr.md "The ray list")
// and the reflections denoiser after it, each frame and its histories.
#include "reflections_denoiser/denoiser_scene.h"
#include "support/gpu_test_context.h"
#include "support/test_replay.h"

#include <catch2/catch.hpp>

#include <cstring>
#include <memory>

using namespace glint;

TEST_CASE("SSSR with the occupancy exit and the denoiser repeat bit for bit on a second run",
          "[reflections_denoiser]") {
    test::DenoiserScene scene = test::simulateDenoiserScene("glossy_room", 96, 54, 1);
    const capture::Frame& frame = scene.frames.at(0);
    SssrDesc desc = scene.desc;
    desc.denoise = true;
    desc.occupancyExitFraction = 0.25f;
    gpu::Context& context = test::testContext();
    std::unique_ptr<gpu::SssrRunner> runs[2];
    for (auto& runner : runs) {
        runner = std::make_unique<gpu::SssrRunner>(context, desc);
        runner->upload(scene.inputs);
    }
    for (std::uint32_t index = 0; index < 3; ++index) {
        INFO("frame " << index);
        desc.frameIndex = index;
        const ReflectionsDenoiserDesc denoiser = replay::denoiserFromFrame(frame, desc, index, index == 0);
        gpu::SssrFrameOutputs out[2];
        for (int run = 0; run < 2; ++run) {
            runs[run]->run(desc, nullptr, &denoiser);
            out[run] = runs[run]->readback();
        }
        REQUIRE(!out[0].rayList.empty());
        CHECK(out[0].rayList == out[1].rayList);
        REQUIRE(out[0].radiance.size() == out[1].radiance.size());
        CHECK(std::memcmp(out[0].radiance.data(), out[1].radiance.data(),
                          out[0].radiance.size() * sizeof(float)) == 0);
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
