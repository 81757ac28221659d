#include "shadow_denoiser/shadow_runner.h"

#include "support/gpu_test_context.h"

#include <gpu/gpu_transfer.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <iterator>
#include <map>
#include <string>

namespace glint::test {

ShadowRunner::ShadowRunner(const ShadowDenoiserDesc& desc) : gpu::ShadowRunner(testContext(), desc) {}

ShadowOutputs runShadowDenoiser(const ShadowDenoiserDesc& desc, const ShadowInputs& inputs) {
    ShadowRunner runner(desc);
    return runner.run(desc, inputs);
}

ShadowInputs makeShadowInputs(std::uint32_t width, std::uint32_t height, std::uint32_t seed) {
    ShadowInputs inputs;
    const std::size_t count = std::size_t{width} * height;
    inputs.visibility.resize(count);
    inputs.depth.resize(count);
    inputs.normals.resize(4 * count);
    inputs.meanVariance.resize(2 * count);
    inputs.motion.assign(2 * count, 0.0f);
    std::uint32_t state = seed * 747796405u + 2891336453u;
    auto next = [&state]() {
        state = state * 1664525u + 1013904223u;
        return static_cast<float>(state >> 8) / 16777216.0f;
    };
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            const std::size_t i = std::size_t{y} * width + x;
            const float u = (static_cast<float>(x) + 0.5f) / static_cast<float>(width);
            const float v = (static_cast<float>(y) + 0.5f) / static_cast<float>(height);
            const float penumbra = std::clamp((u + 0.3f * v - 0.5f) * 6.0f + 0.5f, 0.0f, 1.0f);
            inputs.visibility[i] = next() < penumbra ? 1.0f : 0.0f;
            const bool sky = v < 0.1f;
            const float base = u < 0.6f ? 0.95f + 0.03f * v : 0.9f + 0.02f * v; // a depth step at u = 0.6
            inputs.depth[i] = sky ? 1.0f : base;
            const bool wall = u > 0.8f;
            inputs.normals[4 * i + 0] = wall ? -1.0f : 0.0f;
            inputs.normals[4 * i + 1] = wall ? 0.0f : 1.0f;
            inputs.normals[4 * i + 2] = 0.0f;
            inputs.normals[4 * i + 3] = 0.0f;
            inputs.meanVariance[2 * i] = std::clamp(penumbra + 0.3f * (next() - 0.5f), 0.0f, 1.0f);
            inputs.meanVariance[2 * i + 1] = 0.05f * next();
        }
    inputs.previousDepth = inputs.depth;
    return inputs;
}

// The previous depth is 40% farther in the left quarter. The motion is deliberately not a
// multiple of half a pixel: with (1.5, -0.5) every previous position lands exactly on a pixel edge, where the
// history pixel index is discontinuous and a one-ulp difference in GPU arithmetic (which devices may have)
// picks the neighbour's history.
ShadowInputs movingShadowInputs(std::uint32_t width, std::uint32_t height, std::uint32_t seed) {
    ShadowInputs inputs = makeShadowInputs(width, height, seed);
    for (std::size_t i = 0; i < inputs.motion.size(); i += 2) {
        inputs.motion[i] = 1.3f / static_cast<float>(width);
        inputs.motion[i + 1] = -0.7f / static_cast<float>(height);
    }
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width / 4; ++x) {
            float& d = inputs.previousDepth[std::size_t{y} * width + x];
            if (d < 1.0f) d = std::min(d + 0.02f, 0.999f);
        }
    return inputs;
}

void addUniformBands(ShadowInputs& inputs, std::uint32_t width, std::uint32_t height) {
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            float& v = inputs.visibility[std::size_t{y} * width + x];
            if (x < 12) v = 1.0f;
            if (x >= 40) v = 0.0f;
        }
}

ShadowOutputs runThreeFrames(ShadowDenoiserDesc desc, const ShadowInputs& inputs) {
    ShadowRunner runner(desc);
    ShadowOutputs last;
    for (std::uint32_t frame = 0; frame < 3; ++frame) {
        desc.frameIndex = frame;
        desc.resetHistory = frame == 0;
        last = runner.run(desc, inputs);
    }
    return last;
}

} // namespace glint::test
