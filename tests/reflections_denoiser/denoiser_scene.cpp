#include "reflections_denoiser/denoiser_scene.h"

#include "capture/mat4.h"
#include "glint/common/glint_wire_formats.h"
#include "scene/scene_file.h"
#include "scene/scene_simulate.h"
#include "support/gpu_test_context.h"
#include "support/test_replay.h"

#include <gpu/gpu_transfer.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace glint::test {

DenoiserScene simulateDenoiserScene(const std::string& name, std::uint32_t width, std::uint32_t height,
                                    std::uint32_t frames, bool accumulateReferences) {
    scene::Scene scene =
        scene::loadScene(std::string(GLINT_SOURCE_DIR) + "/harness/scenes/" + name + ".toml");
    scene.width = width;
    scene.height = height;
    scene.frameCount = frames;
    scene.reference.reflections = true;
    scene.reference.accumulate = accumulateReferences;
    scene::Simulation simulation = scene::simulate(testContext(), scene);
    DenoiserScene out;
    out.frames = std::move(simulation.frames);
    out.environment = simulation.environment.value();
    replay::sssrFromFrame(out.frames.at(0), out.environment, out.desc, out.inputs);
    return out;
}

double glossyError(const capture::Frame& frame, const std::vector<float>& radiance,
                   float roughnessThreshold) {
    const capture::Layer* reference = capture::findLayer(frame, "reference.reflection");
    if (!reference) return -1.0;
    std::vector<float> target(4 * std::size_t{frame.width} * frame.height, 0.0f);
    const std::size_t stride = reference->channels.size();
    for (std::size_t i = 0; i < target.size() / 4; ++i)
        for (std::size_t c = 0; c < std::min<std::size_t>(3, stride); ++c)
            target[4 * i + c] = reference->pixels[i * stride + c];
    return glossyError(frame, radiance, target, roughnessThreshold);
}

std::vector<std::size_t> glossyPixels(const capture::Frame& frame, float roughnessThreshold) {
    std::vector<std::size_t> pixels;
    const capture::Layer* depth = capture::findLayer(frame, "depth");
    const capture::Layer* roughness = capture::findLayer(frame, frame.roughness.layer);
    if (!depth || !roughness) return pixels;
    const int channel = capture::channelIndex(roughness->channels, frame.roughness.channel);
    const std::size_t roughStride = roughness->channels.size();
    const bool reversed = frame.camera.depth != capture::DepthConvention::Standard;
    for (std::size_t i = 0; i < std::size_t{frame.width} * frame.height; ++i) {
        const float d = depth->pixels[i];
        if (!std::isfinite(d) || (reversed ? d <= 1e-6f : d >= 1.0f - 1e-6f)) continue;
        float r = roughness->pixels[i * roughStride + static_cast<std::size_t>(channel)];
        const float alpha = frame.roughness.perceptual ? r * r : r;
        if (alpha < roughnessThreshold) pixels.push_back(i);
    }
    return pixels;
}

double glossyError(const capture::Frame& frame, const std::vector<float>& radiance,
                   const std::vector<float>& target, float roughnessThreshold) {
    auto luma = [](const float* c) {
        return 0.2126 * static_cast<double>(c[0]) + 0.7152 * static_cast<double>(c[1]) +
               0.0722 * static_cast<double>(c[2]);
    };
    const std::vector<std::size_t> pixels = glossyPixels(frame, roughnessThreshold);
    double sum = 0.0;
    for (std::size_t i : pixels) {
        const double expected = luma(&target[4 * i]);
        sum += std::abs(luma(&radiance[4 * i]) - expected) / std::max(expected, 0.05);
    }
    return pixels.empty() ? -1.0 : sum / static_cast<double>(pixels.size());
}

double glossyRmse(const capture::Frame& frame, const std::vector<float>& radiance, float roughnessThreshold) {
    const capture::Layer* reference = capture::findLayer(frame, "reference.reflection");
    if (!reference) return -1.0;
    const std::size_t stride = reference->channels.size();
    const std::vector<std::size_t> pixels = glossyPixels(frame, roughnessThreshold);
    double sum = 0.0;
    for (std::size_t i : pixels)
        for (std::size_t c = 0; c < 3; ++c) {
            const double d = static_cast<double>(radiance[4 * i + c]) -
                             static_cast<double>(reference->pixels[i * stride + c]);
            sum += d * d;
        }
    return pixels.empty() ? -1.0 : std::sqrt(sum / (3.0 * static_cast<double>(pixels.size())));
}

std::vector<std::vector<float>> runDenoiserFrames(const DenoiserScene& scene,
                                                  const std::vector<std::size_t>& frameOrder, bool denoise) {
    SssrDesc desc = scene.desc;
    desc.denoise = denoise;
    gpu::SssrRunner runner(testContext(), desc);
    std::vector<std::vector<float>> radiance;
    for (std::uint32_t index = 0; index < frameOrder.size(); ++index) {
        const capture::Frame& frame = scene.frames.at(frameOrder[index]);
        gpu::SssrFrameInputs inputs;
        SssrDesc frameDesc = desc;
        replay::sssrFromFrame(frame, scene.environment, frameDesc, inputs);
        frameDesc.denoise = denoise;
        frameDesc.frameIndex = index;
        runner.upload(inputs);
        const ReflectionsDenoiserDesc denoiser =
            replay::denoiserFromFrame(frame, frameDesc, index, index == 0);
        runner.run(frameDesc, nullptr, denoise ? &denoiser : nullptr);
        gpu::SssrFrameOutputs out = runner.readback();
        for (float value : out.radiance) REQUIRE(std::isfinite(value));
        radiance.push_back(std::move(out.radiance));
    }
    return radiance;
}

void requireFiniteOverTiles(const gpu::SssrRunner& runner, const gpu::SssrFrameOutputs& out,
                            const std::string& name) {
    INFO(name);
    const std::vector<float> texels = gpu::readbackImage(testContext(), runner.ownedImage(name));
    const std::size_t channels = texels.size() / (std::size_t{out.width} * out.height);
    for (std::uint32_t tile : out.tileList) {
        const std::uint32_t tileX = shared::GLINT_WIRE_TileEntryX(tile),
                            tileY = shared::GLINT_WIRE_TileEntryY(tile);
        for (std::uint32_t y = tileY; y < std::min(out.height, tileY + 8); ++y)
            for (std::uint32_t x = tileX; x < std::min(out.width, tileX + 8); ++x)
                for (std::size_t c = 0; c < channels; ++c)
                    REQUIRE(std::isfinite(texels[(std::size_t{y} * out.width + x) * channels + c]));
    }
}

void uploadPoisonedFrame(gpu::SssrRunner& runner, const gpu::SssrFrameInputs& clean, std::uint32_t index) {
    if (index != 1 && index != 2) {
        runner.upload(clean);
        return;
    }
    const float value =
        index == 1 ? std::numeric_limits<float>::quiet_NaN() : std::numeric_limits<float>::infinity();
    // The histories are read from the other parity.
    const char* parity = (index & 1u) != 0 ? "0" : "1";
    for (const char* name : {"rd_radiance", "rd_variance", "rd_length", "rd_guides"}) {
        VkClearColorValue fill{};
        for (float& channel : fill.float32) channel = value;
        gpu::clearImage(testContext(), runner.ownedImage(std::string(name) + parity), fill);
    }
    gpu::SssrFrameInputs bad = clean;
    for (std::size_t i = 0; i < bad.depth.size(); i += 7) {
        bad.color[4 * i] = value;
        bad.normals[4 * i + (i % 3)] = value;
        if (i % 21 == 0) bad.depth[i] = value;
        if (i % 35 == 0) bad.motion[2 * i] = value;
        if (i % 49 == 0) bad.material[4 * i] = value;
    }
    runner.upload(bad);
}

} // namespace glint::test
