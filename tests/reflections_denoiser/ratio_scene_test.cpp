// The ratio-estimator path on simulated scenes: SSSR's stored rays, static convergence on the
// glossy room next to the default (prefilter) path, and non-finite histories and inputs.
#include "glint/common/glint_wire_formats.h"
#include "reflections_denoiser/denoiser_scene.h"
#include "support/gpu_test_context.h"
#include "support/test_replay.h"

#include <gpu/gpu_transfer.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

using namespace glint;

namespace {

ReflectionsDenoiserDesc ratioDenoiser(const capture::Frame& frame, const SssrDesc& desc,
                                      std::uint32_t index) {
    ReflectionsDenoiserDesc denoiser = replay::denoiserFromFrame(frame, desc, index, index == 0);
    denoiser.spatialPath = SpatialPath::RatioEstimator;
    return denoiser;
}

std::string traceOf(const std::vector<double>& values) {
    std::string trace;
    for (double e : values) trace += std::to_string(e).substr(0, 5) + " ";
    return trace;
}

} // namespace

TEST_CASE("SSSR's stored rays: the radiance is unchanged, every glossy pixel has a unit direction and a "
          "positive pdf, and copies carry their donor's ray",
          "[reflections_denoiser][ratio]") {
    test::DenoiserScene scene = test::simulateDenoiserScene("glossy_room", 96, 54, 1);
    for (const bool half : {false, true}) {
        INFO((half ? "16-bit storage" : "32-bit storage"));
        SssrDesc plain = scene.desc;
        plain.halfPrecisionStorage = half;
        SssrDesc storing = plain;
        storing.storeRays = true;
        gpu::SssrRunner plainRunner(test::testContext(), plain), storingRunner(test::testContext(), storing);
        plainRunner.upload(scene.inputs);
        storingRunner.upload(scene.inputs);
        for (std::uint32_t index = 0; index < 2; ++index) {
            plain.frameIndex = storing.frameIndex = index;
            plainRunner.run(plain);
            storingRunner.run(storing);
            const gpu::SssrFrameOutputs a = plainRunner.readback(), b = storingRunner.readback();
            REQUIRE(a.rays.empty());
            REQUIRE(b.rays.size() == a.radiance.size());
            REQUIRE(std::memcmp(a.radiance.data(), b.radiance.data(), a.radiance.size() * sizeof(float)) ==
                    0);
            const std::uint32_t w = b.width;
            std::size_t glossy = 0;
            for (std::size_t i = 0; i < b.roughness.size(); ++i) {
                const float depth = scene.inputs.depth[i];
                if (!(b.roughness[i] < storing.roughnessThreshold) || !(depth < 1.0f - 1e-6f)) continue;
                ++glossy;
                const float* ray = &b.rays[4 * i];
                const double length =
                    std::sqrt(double{ray[0]} * double{ray[0]} + double{ray[1]} * double{ray[1]} +
                              double{ray[2]} * double{ray[2]});
                INFO("pixel " << i % w << ", " << i / w);
                REQUIRE(std::abs(length - 1.0) < (half ? 2e-3 : 1e-5));
                REQUIRE(std::isfinite(ray[3]));
                REQUIRE(ray[3] > 0.0f);
            }
            REQUIRE(glossy > 500u);
            std::size_t copies = 0;
            for (std::uint32_t entry : b.rayList) {
                const std::uint32_t x = shared::GLINT_WIRE_RayEntryX(entry),
                                    y = shared::GLINT_WIRE_RayEntryY(entry);
                const std::uint32_t flips[3][2] = {{1, 0}, {0, 1}, {1, 1}};
                for (std::uint32_t k = 0; k < 3; ++k) {
                    if ((entry & (0x20000000u << k)) == 0) continue;
                    const std::size_t donor = std::size_t{y} * w + x,
                                      target = std::size_t{y ^ flips[k][1]} * w + (x ^ flips[k][0]);
                    for (std::size_t c = 0; c < 4; ++c)
                        REQUIRE(b.rays[4 * target + c] == b.rays[4 * donor + c]);
                    ++copies;
                }
            }
            CHECK(copies > 100u);
        }
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("static glossy room: both spatial paths' errors fall over frames and end far below one raw frame",
          "[reflections_denoiser][ratio][static]") {
    test::DenoiserScene scene = test::simulateDenoiserScene("glossy_room", 160, 90, 1);
    const capture::Frame& frame = scene.frames.at(0);
    SssrDesc raw = scene.desc;
    gpu::SssrRunner rawRunner(test::testContext(), raw);
    rawRunner.upload(scene.inputs);
    rawRunner.run(raw);
    const double rawError = test::glossyError(frame, rawRunner.readback().radiance, raw.roughnessThreshold);
    // SSSR's own expectation: the mean of 256 raw frames (the denoisers' noise-free target,
    // without the bias SSSR has against the path-traced reference).
    constexpr std::uint32_t kFrames = 24, kConvergedFrames = 256;
    // The mean change of the output from one frame to the next over the last kChangeFrames frames
    // (a static scene: only the samples change).
    constexpr std::uint32_t kChangeFrames = 8;
    // And the plain average of the first kFrames raw frames: what accumulation without any filter
    // reaches.
    std::vector<float> converged(rawRunner.readback().radiance.size(), 0.0f), average(converged.size(), 0.0f);
    // The last two of the first kFrames raw frames: how much one frame's samples change.
    std::vector<float> rawBeforeLast, rawLast;
    for (std::uint32_t index = 0; index < kConvergedFrames; ++index) {
        raw.frameIndex = index;
        rawRunner.run(raw);
        const std::vector<float> radiance = rawRunner.readback().radiance;
        if (index + 2 == kFrames) rawBeforeLast = radiance;
        if (index + 1 == kFrames) rawLast = radiance;
        for (std::size_t i = 0; i < converged.size(); ++i) {
            if (index < kFrames) average[i] += radiance[i] / static_cast<float>(kFrames);
            converged[i] += radiance[i] / static_cast<float>(kConvergedFrames);
        }
    }
    const double averageError = test::glossyError(frame, average, raw.roughnessThreshold);

    // Both paths on the same frames: errors against the reference and against SSSR's mean, and
    // how much the output changes from one frame to the next at the end.
    std::vector<double> errors[2], noise[2];
    double change[2] = {0.0, 0.0};
    for (const SpatialPath path : {SpatialPath::Prefilter, SpatialPath::RatioEstimator}) {
        const std::size_t p = path == SpatialPath::RatioEstimator ? 1 : 0;
        SssrDesc desc = scene.desc;
        desc.denoise = true;
        desc.storeRays = path == SpatialPath::RatioEstimator;
        gpu::SssrRunner runner(test::testContext(), desc);
        runner.upload(scene.inputs);
        std::vector<float> previous;
        for (std::uint32_t index = 0; index < kFrames; ++index) {
            desc.frameIndex = index;
            ReflectionsDenoiserDesc denoiser = ratioDenoiser(frame, desc, index);
            denoiser.spatialPath = path;
            runner.run(desc, nullptr, &denoiser);
            const gpu::SssrFrameOutputs out = runner.readback();
            for (float value : out.radiance) REQUIRE(std::isfinite(value));
            errors[p].push_back(test::glossyError(frame, out.radiance, desc.roughnessThreshold));
            noise[p].push_back(test::glossyError(frame, out.radiance, converged, desc.roughnessThreshold));
            if (index + kChangeFrames >= kFrames)
                change[p] += test::glossyError(frame, out.radiance, previous, desc.roughnessThreshold) /
                             static_cast<double>(kChangeFrames);
            previous = out.radiance;
        }
    }
    const double convergedError = test::glossyError(frame, converged, raw.roughnessThreshold);
    const double rawChange = test::glossyError(frame, rawLast, rawBeforeLast, raw.roughnessThreshold);
    WARN("raw single frame " << rawError << ", plain average of " << kFrames << " frames " << averageError
                             << ", SSSR's converged mean " << convergedError
                             << "\nagainst the reference per frame, prefilter: " << traceOf(errors[0])
                             << "\n                                  ratio:     " << traceOf(errors[1])
                             << "\nagainst SSSR's converged mean,    prefilter: " << traceOf(noise[0])
                             << "\n                                  ratio:     " << traceOf(noise[1])
                             << "\nmean change from one frame to the next over the last " << kChangeFrames
                             << " frames: raw " << rawChange << ", prefilter " << change[0] << ", ratio "
                             << change[1]);
    REQUIRE(rawError > 0.0);
    // The figures are in docs/reflections_denoiser.md ("Tests"); the warnings print them. What is
    // left against the reference is SSSR's own bias (its 256-frame mean's distance from the
    // reference: off-screen geometry, the box-filtered environment), which no denoiser removes.
    // The default path (prefilter) ends far below one raw frame and below the plain average.
    // Absolute bounds: the largest of eight sample sequences (frame indices offset by 0, 1000, ...,
    // 7000; lavapipe, 2026-12-04) plus the larger of 4 standard deviations and 5 % of it (the
    // rule of tests/sssr/convergence_test.cpp). Prefilter at frame 23: error against the
    // reference 0.2079-0.2149 (sd 0.0023), against SSSR's mean 0.0763-0.0809 (sd 0.0017); ratio
    // path: 0.2102-0.2276 (sd 0.0051) and 0.0785-0.0856 (sd 0.0028).
    CHECK(errors[0].back() < 0.6 * rawError);
    CHECK(errors[0].back() < averageError);
    CHECK(errors[0].back() < 0.226);
    CHECK(noise[0].back() < 0.75 * noise[0].front());
    CHECK(noise[0].back() < 0.088);
    // The ratio path must end below SSSR's own mean.
    const std::vector<double>& ratioErrors = errors[1];
    const std::vector<double>& ratioNoise = noise[1];
    CHECK(ratioErrors.back() < ratioErrors.front());
    CHECK(ratioErrors.back() < 0.7 * rawError);
    CHECK(ratioErrors.back() < convergedError);
    CHECK(ratioErrors.back() < 0.248);
    CHECK(ratioNoise.back() < 0.75 * ratioNoise.front());
    CHECK(ratioNoise.back() < 0.097);
    // The histories average the samples over frames: the output changes far less from frame to
    // frame than a filtered single frame does. Eight sample sequences (lavapipe, 2026-12-04), the
    // mean change over frames 16-23: prefilter 0.0070-0.0081 (sd 0.00039), ratio 0.0097-0.0113
    // (sd 0.00054); bounds by the rule above. A resolve that keeps no history (its length held
    // at 1) changes by 0.0150-0.0156 and 0.0194-0.0203 (three sequences), so it fails both; the
    // errors above do not see it (the spatial filters alone reach them on this static view).
    CHECK(change[0] < 0.0097);
    CHECK(change[1] < 0.0135);
    CHECK(change[0] < 0.05 * rawChange);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("non-finite histories and inputs never reach the ratio path's next output",
          "[reflections_denoiser][ratio][hard]") {
    test::DenoiserScene scene = test::simulateDenoiserScene("glossy_room", 96, 54, 1);
    const capture::Frame& frame = scene.frames.at(0);
    for (const bool half : {false, true}) {
        INFO((half ? "16-bit storage" : "32-bit storage"));
        SssrDesc desc = scene.desc;
        desc.denoise = true;
        desc.storeRays = true;
        desc.halfPrecisionStorage = half;
        gpu::Context& context = test::testContext();
        gpu::SssrRunner runner(context, desc);
        for (std::uint32_t index = 0; index < 4; ++index) {
            INFO("frame " << index);
            desc.frameIndex = index;
            test::uploadPoisonedFrame(runner, scene.inputs, index);
            ReflectionsDenoiserDesc denoiser = ratioDenoiser(frame, desc, index);
            denoiser.halfPrecisionStorage = half;
            runner.run(desc, nullptr, &denoiser);
            const gpu::SssrFrameOutputs out = runner.readback();
            for (float value : out.radiance) REQUIRE(std::isfinite(value));
            const char* written = (index & 1u) != 0 ? "1" : "0";
            for (const char* name : {"rd_radiance", "rd_variance", "rd_prefiltered"})
                test::requireFiniteOverTiles(
                    runner, out, std::string(name) + (std::string(name) == "rd_prefiltered" ? "" : written));
            REQUIRE(!out.tileList.empty());
        }
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
