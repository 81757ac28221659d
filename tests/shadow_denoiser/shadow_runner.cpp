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

namespace {
const char* const kInputNames[] = {"shadow_visibility", "shadow_depth",  "shadow_previous_depth",
                                   "shadow_normals",    "shadow_motion", "shadow_filter_input"};
const VkFormat kInputFormats[] = {VK_FORMAT_R32_SFLOAT,    VK_FORMAT_R32_SFLOAT,
                                  VK_FORMAT_R32_SFLOAT,    VK_FORMAT_R32G32B32A32_SFLOAT,
                                  VK_FORMAT_R32G32_SFLOAT, VK_FORMAT_R32G32_SFLOAT};
const std::uint32_t kInputChannels[] = {1, 1, 1, 4, 2, 2};

std::vector<std::uint32_t> readWords(const gpu::Context& context, const vk::Buffer& buffer) {
    const std::vector<std::byte> bytes = gpu::readbackBuffer(context, buffer);
    std::vector<std::uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), words.size() * 4);
    return words;
}
} // namespace

ShadowRunner::ShadowRunner(const ShadowDenoiserDesc& desc) {
    gpu::Context& context = testContext();
    EffectPlan plan;
    std::string error;
    INFO(error);
    REQUIRE(planShadowDenoiser(desc, plan, &error) == Result::Ok);
    for (std::size_t i = 0; i < std::size(kInputNames); ++i)
        inputs_.push_back(
            vk::createImage2D(context.device, desc.size.width, desc.size.height, kInputFormats[i]));
    owned_ = gpu::createPlanResources(context, plan, 0.0f);
    executor_ = vk::createExecutor(context.device);
}

ShadowRunner::~ShadowRunner() {
    gpu::Context& context = testContext();
    vk::destroyExecutor(executor_);
    gpu::destroyPlanResources(context, owned_);
    for (vk::Image& image : inputs_) vk::destroyImage(context.device, image);
}

void ShadowRunner::setHistory(std::uint32_t frameIndex, const std::vector<float>& moments,
                              const std::vector<float>& shadow) {
    gpu::Context& context = testContext();
    const char* read = (frameIndex & 1u) != 0 ? "shadow_moments0" : "shadow_moments1";
    gpu::uploadImage(context, owned_.images.at(read), moments, 4);
    gpu::uploadImage(context, owned_.images.at("shadow_scratch1"), shadow, 2);
}

ShadowOutputs ShadowRunner::run(const ShadowDenoiserDesc& desc, const ShadowInputs& inputs) {
    gpu::Context& context = testContext();
    EffectPlan plan;
    std::string error;
    INFO(error);
    REQUIRE(planShadowDenoiser(desc, plan, &error) == Result::Ok);
    const std::vector<float>* data[] = {&inputs.visibility, &inputs.depth,  &inputs.previousDepth,
                                        &inputs.normals,    &inputs.motion, &inputs.meanVariance};
    std::map<std::string, const vk::Image*> external;
    for (std::size_t i = 0; i < std::size(kInputNames); ++i) {
        if (!data[i]->empty()) gpu::uploadImage(context, inputs_[i], *data[i], kInputChannels[i]);
        external[kInputNames[i]] = &inputs_[i];
    }
    gpu::executePlan(context, executor_, plan, gpu::resourceTable(owned_, external));

    ShadowOutputs outputs;
    outputs.mask = readWords(context, owned_.buffers.at("shadow_mask"));
    if (desc.classify) {
        outputs.metadata = readWords(context, owned_.buffers.at("shadow_tile_metadata"));
        const char* written = (desc.frameIndex & 1u) != 0 ? "shadow_moments1" : "shadow_moments0";
        outputs.moments = gpu::readbackImage(context, owned_.images.at(written));
        if (!desc.filter)
            outputs.classified = gpu::readbackImage(context, owned_.images.at("shadow_scratch0"));
    }
    if (desc.filter) outputs.filtered = gpu::readbackImage(context, owned_.images.at("shadow_output"));
    if (owned_.buffers.contains("shadow_filter_work"))
        outputs.filteredTiles = readWords(context, owned_.buffers.at("shadow_filter_work")).at(0);
    return outputs;
}

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

} // namespace glint::test
