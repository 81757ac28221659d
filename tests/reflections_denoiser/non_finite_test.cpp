// NaN and Inf injected into every history and into the inputs never survive to the next
// frame's output: every output and every history the frame writes is finite.
#include "reflections_denoiser/denoiser_scene.h"
#include "support/gpu_test_context.h"
#include "support/test_replay.h"

#include <gpu/gpu_transfer.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace glint;

TEST_CASE("non-finite histories and inputs never reach the next frame's output",
          "[reflections_denoiser][hard]") {
    test::DenoiserScene scene = test::simulateDenoiserScene("glossy_room", 96, 54, 1);
    const capture::Frame& frame = scene.frames.at(0);
    for (const bool half : {false, true}) {
        INFO((half ? "16-bit storage" : "32-bit storage"));
        SssrDesc desc = scene.desc;
        desc.denoise = true;
        desc.halfPrecisionStorage = half;
        gpu::Context& context = test::testContext();
        gpu::SssrRunner runner(context, desc);
        runner.upload(scene.inputs);
        for (std::uint32_t index = 0; index < 4; ++index) {
            INFO("frame " << index);
            desc.frameIndex = index;
            // Every history this frame reads, and scattered inputs, poisoned on frames 1 and 2.
            test::uploadPoisonedFrame(runner, scene.inputs, index);
            ReflectionsDenoiserDesc denoiser = replay::denoiserFromFrame(frame, desc, index, index == 0);
            denoiser.halfPrecisionStorage = half;
            runner.run(desc, nullptr, &denoiser);
            const gpu::SssrFrameOutputs out = runner.readback();
            for (float value : out.radiance) REQUIRE(std::isfinite(value));
            // The histories this frame wrote, over the tiles it listed (the only texels the
            // denoiser writes, and the only ones next frame reads: the tile mask guards the rest).
            const char* written = (index & 1u) != 0 ? "1" : "0";
            for (const char* name : {"rd_radiance", "rd_variance", "rd_length", "rd_guides"})
                test::requireFiniteOverTiles(runner, out, std::string(name) + written);
            REQUIRE(!out.tileList.empty());
        }
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
