#include "gpu/gpu_sssr_runner.h"

#include "gpu/gpu_timestamps.h"
#include "gpu/gpu_transfer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace glint::gpu {
namespace {

enum InputSlot { kDepth, kNormals, kMaterial, kColor, kMotion, kBaseColor, kEnvironment, kSlotCount };

std::vector<std::uint32_t> readWords(const Context& context, const vk::Buffer& buffer, std::size_t count) {
    const std::vector<std::byte> bytes = readbackBuffer(context, buffer);
    std::vector<std::uint32_t> words(std::min(count, bytes.size() / 4));
    if (!words.empty()) std::memcpy(words.data(), bytes.data(), words.size() * 4);
    return words;
}

} // namespace

std::vector<std::vector<float>> environmentMips(std::uint32_t width, std::uint32_t height,
                                                const std::vector<float>& rgba) {
    std::vector<std::vector<float>> levels{rgba};
    std::uint32_t w = width, h = height;
    while (w > 1 || h > 1) {
        const std::uint32_t nw = std::max(1u, w / 2), nh = std::max(1u, h / 2);
        const std::vector<float>& src = levels.back();
        std::vector<float> dst(std::size_t{nw} * nh * 4, 0.0f);
        for (std::uint32_t y = 0; y < nh; ++y)
            for (std::uint32_t x = 0; x < nw; ++x)
                for (std::uint32_t c = 0; c < 4; ++c) {
                    float sum = 0.0f;
                    for (std::uint32_t dy = 0; dy < 2; ++dy)
                        for (std::uint32_t dx = 0; dx < 2; ++dx) {
                            const std::uint32_t sx = std::min(2 * x + dx, w - 1),
                                                sy = std::min(2 * y + dy, h - 1);
                            sum += src[(std::size_t{sy} * w + sx) * 4 + c];
                        }
                    dst[(std::size_t{y} * nw + x) * 4 + c] = 0.25f * sum;
                }
        levels.push_back(std::move(dst));
        w = nw;
        h = nh;
    }
    return levels;
}

SssrRunner::SssrRunner(const Context& context, const SssrDesc& desc, bool compactInputs)
    : context_(context), desc_(desc), compact_(compactInputs) {
    std::string error;
    if (vk::createSssr(context.device, desc, effect_, &error) != Result::Ok) throw std::runtime_error(error);
    executor_ = vk::createExecutor(context.device);
}

SssrRunner::~SssrRunner() {
    vk::destroyExecutor(executor_);
    vk::destroySssr(effect_);
    for (vk::Image& image : images_) vk::destroyImage(context_.device, image);
}

void SssrRunner::upload(const SssrFrameInputs& inputs) {
    const std::uint32_t w = desc_.size.width, h = desc_.size.height;
    if (images_.empty()) {
        const VkFormat full[] = {VK_FORMAT_R32_SFLOAT,          VK_FORMAT_R32G32B32A32_SFLOAT,
                                 VK_FORMAT_R32G32B32A32_SFLOAT, VK_FORMAT_R32G32B32A32_SFLOAT,
                                 VK_FORMAT_R32G32_SFLOAT,       VK_FORMAT_R32G32B32A32_SFLOAT};
        const VkFormat compact[] = {VK_FORMAT_R32_SFLOAT,    VK_FORMAT_R16G16B16A16_SFLOAT,
                                    VK_FORMAT_R16_SFLOAT,    VK_FORMAT_R16G16B16A16_SFLOAT,
                                    VK_FORMAT_R16G16_SFLOAT, VK_FORMAT_R8G8B8A8_UNORM};
        for (VkFormat format : compact_ ? compact : full)
            images_.push_back(vk::createImage2D(context_.device, w, h, format));
        images_.push_back(vk::Image{});
    }
    const std::vector<float>* data[] = {&inputs.depth, &inputs.normals, &inputs.material,
                                        &inputs.color, &inputs.motion,  &inputs.baseColorMetallic};
    const std::uint32_t channels[] = {1, 4, 4, 4, 2, 4};
    for (int slot = 0; slot < kEnvironment; ++slot) {
        if (data[slot]->empty()) continue;
        if (data[slot]->size() != std::size_t{w} * h * channels[slot])
            throw std::runtime_error("sssr runner: input " + std::to_string(slot) + " has the wrong size");
        if (compact_ && slot == kMaterial) { // R16F: roughness only, from channel 0
            std::vector<float> roughness(std::size_t{w} * h);
            for (std::size_t i = 0; i < roughness.size(); ++i) roughness[i] = (*data[slot])[4 * i];
            uploadImage(context_, images_[kMaterial], roughness, 1);
            continue;
        }
        uploadImage(context_, images_[static_cast<std::size_t>(slot)], *data[slot], channels[slot]);
    }
    if (!inputs.environment.empty()) {
        const auto levels =
            environmentMips(inputs.environmentWidth, inputs.environmentHeight, inputs.environment);
        vk::Image& env = images_[kEnvironment];
        vk::destroyImage(context_.device, env);
        env = vk::createImage2D(context_.device, inputs.environmentWidth, inputs.environmentHeight,
                                VK_FORMAT_R32G32B32A32_SFLOAT, static_cast<std::uint32_t>(levels.size()));
        clearImage(context_, env, VkClearColorValue{});
        for (std::size_t level = 0; level < levels.size(); ++level)
            uploadImage(context_, env, levels[level], 4, static_cast<std::uint32_t>(level));
    }
}

std::vector<std::string> SssrRunner::passNames(const SssrDesc& frame, bool denoised,
                                               SpatialPath spatialPath) const {
    EffectPlan plan;
    std::vector<std::string> names;
    if (planSssr(frame, plan, nullptr) == Result::Ok)
        for (const Pass& pass : plan.passes) names.push_back(pass.name);
    if (denoised) { // dispatched between the intersection and the composite (vk_sssr.cpp)
        ReflectionsDenoiserDesc denoiser;
        denoiser.size = frame.size;
        denoiser.spatialPath = spatialPath;
        EffectPlan denoiserPlan;
        std::vector<std::string> denoiserNames;
        if (planReflectionsDenoiser(denoiser, denoiserPlan, nullptr) == Result::Ok)
            for (const Pass& pass : denoiserPlan.passes) denoiserNames.push_back(pass.name);
        const auto composite = std::find(names.begin(), names.end(), "composite");
        names.insert(composite, denoiserNames.begin(), denoiserNames.end());
    }
    return names;
}

const vk::Image& SssrRunner::ownedImage(const std::string& name) const {
    return effect_.images.at(name);
}

void SssrRunner::run(const SssrDesc& frame, std::vector<double>* timings,
                     const ReflectionsDenoiserDesc* denoiser, const vk::PassHooks* extraHooks) {
    if (images_.empty() || images_[kEnvironment].image == VK_NULL_HANDLE)
        throw std::runtime_error("sssr runner: upload the inputs (with an environment) before running");
    vk::SssrInputs inputs;
    inputs.depth = &images_[kDepth];
    inputs.normals = &images_[kNormals];
    inputs.material = &images_[kMaterial];
    inputs.color = &images_[kColor];
    inputs.motion = &images_[kMotion];
    inputs.baseColorMetallic = &images_[kBaseColor];
    inputs.environment = &images_[kEnvironment];
    const std::size_t passCount =
        passNames(frame, denoiser != nullptr, denoiser ? denoiser->spatialPath : SpatialPath::Prefilter)
            .size();
    const bool timed = timings != nullptr && context_.device.timestamps;
    TimestampPool pool;
    if (timed) pool = createTimestampPool(context_.device, static_cast<std::uint32_t>(2 * passCount));
    vk::PassHooks hooks;
    hooks.beforeDispatch = [&](VkCommandBuffer cmd, std::size_t index) {
        if (extraHooks && extraHooks->beforeDispatch) extraHooks->beforeDispatch(cmd, index);
        if (timed) writeTimestamp(cmd, pool, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT);
    };
    hooks.afterDispatch = [&](VkCommandBuffer cmd, std::size_t index) {
        if (timed) writeTimestamp(cmd, pool, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);
        if (extraHooks && extraHooks->afterDispatch) extraHooks->afterDispatch(cmd, index);
    };
    vk::resetExecutor(executor_);
    std::string error;
    Result result = Result::Ok;
    submitAndWait(context_, [&](VkCommandBuffer cmd) {
        if (timed) resetTimestamps(cmd, pool);
        result = vk::dispatchSssr(effect_, executor_, cmd, frame, inputs, hooks, &error, denoiser);
    });
    if (timed) {
        const std::vector<uint64_t> ticks = readTimestamps(context_.device, pool);
        timings->clear();
        for (std::size_t i = 0; i + 1 < ticks.size(); i += 2)
            timings->push_back(timestampMilliseconds(pool, ticks[i], ticks[i + 1]));
        destroyTimestampPool(context_.device, pool);
    }
    if (result != Result::Ok) throw std::runtime_error(error);
}

std::array<std::uint32_t, 4> SssrRunner::counters() const {
    const std::vector<std::uint32_t> words = readWords(context_, effect_.buffers.at("sssr_counters"), 4);
    return {words[0], words[1], words[2], words[3]};
}

SssrFrameOutputs SssrRunner::readback() const {
    SssrFrameOutputs out;
    out.width = desc_.size.width;
    out.height = desc_.size.height;
    const auto& images = effect_.images;
    const auto& buffers = effect_.buffers;
    out.radiance = readbackImage(context_, images.at("sssr_radiance"));
    out.confidence = readbackImage(context_, images.at("sssr_confidence"));
    out.roughness = readbackImage(context_, images.at("sssr_roughness"));
    out.blueNoise = readbackImage(context_, images.at("sssr_blue_noise"));
    if (images.contains("sssr_ray_info")) out.rayInfo = readbackImage(context_, images.at("sssr_ray_info"));
    if (images.contains("sssr_rays")) out.rays = readbackImage(context_, images.at("sssr_rays"));
    if (images.contains("composite")) out.composite = readbackImage(context_, images.at("composite"));
    const std::vector<std::uint32_t> counters = readWords(context_, buffers.at("sssr_counters"), 4);
    const std::vector<std::uint32_t> arguments = readWords(context_, buffers.at("sssr_indirect_args"), 6);
    std::copy(counters.begin(), counters.end(), out.counters);
    std::copy(arguments.begin(), arguments.end(), out.arguments);
    out.rayList = readWords(context_, buffers.at("sssr_ray_list"), out.counters[1]);
    out.tileList = readWords(context_, buffers.at("sssr_tile_list"), out.counters[3]);
    return out;
}

} // namespace glint::gpu
