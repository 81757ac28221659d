#include "gpu/gpu_shadow_runner.h"

#include <gpu/gpu_transfer.h>

#include <cstring>
#include <iterator>
#include <map>
#include <stdexcept>
#include <string>

namespace glint::gpu {

namespace {
const char* const kInputNames[] = {"shadow_visibility", "shadow_depth",  "shadow_previous_depth",
                                   "shadow_normals",    "shadow_motion", "shadow_filter_input"};
const VkFormat kInputFormats[] = {VK_FORMAT_R32_SFLOAT,    VK_FORMAT_R32_SFLOAT,
                                  VK_FORMAT_R32_SFLOAT,    VK_FORMAT_R32G32B32A32_SFLOAT,
                                  VK_FORMAT_R32G32_SFLOAT, VK_FORMAT_R32G32_SFLOAT};
// What an engine would bind: an 8-bit visibility target (0 or 1; NaN uploads as 0, shadowed, as
// the shader treats it), 16-bit normals and motion. Depth stays 32-bit.
const VkFormat kCompactFormats[] = {VK_FORMAT_R8_UNORM,      VK_FORMAT_R32_SFLOAT,
                                    VK_FORMAT_R32_SFLOAT,    VK_FORMAT_R16G16B16A16_SFLOAT,
                                    VK_FORMAT_R16G16_SFLOAT, VK_FORMAT_R32G32_SFLOAT};
const std::uint32_t kInputChannels[] = {1, 1, 1, 4, 2, 2};

std::vector<std::uint32_t> readWords(const Context& context, const vk::Buffer& buffer) {
    const std::vector<std::byte> bytes = readbackBuffer(context, buffer);
    std::vector<std::uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), words.size() * 4);
    return words;
}

// The output's texels as (shadow, variance) pairs; one-channel formats get variance 0.
std::vector<float> asShadowVariance(std::vector<float> texels, Format format) {
    if (format == Format::RG32Float) return texels;
    std::vector<float> pairs(2 * texels.size(), 0.0f);
    for (std::size_t i = 0; i < texels.size(); ++i) pairs[2 * i] = texels[i];
    return pairs;
}

EffectPlan planOrThrow(const ShadowDenoiserDesc& desc) {
    EffectPlan plan;
    std::string error;
    if (planShadowDenoiser(desc, plan, &error) != Result::Ok)
        throw std::invalid_argument("shadow denoiser: " + error);
    return plan;
}
} // namespace

ShadowRunner::ShadowRunner(const Context& context, const ShadowDenoiserDesc& desc, bool compactInputs)
    : context_(context) {
    const EffectPlan plan = planOrThrow(desc);
    for (std::size_t i = 0; i < std::size(kInputNames); ++i)
        inputs_.push_back(vk::createImage2D(context.device, desc.size.width, desc.size.height,
                                            compactInputs ? kCompactFormats[i] : kInputFormats[i]));
    // Histories start at zero, not NaN: the first frame ignores them through resetHistory,
    // but tile-skipped texels of the output keep what they hold.
    owned_ = createPlanResources(context, plan, 0.0f);
    executor_ = vk::createExecutor(context.device);
}

ShadowRunner::~ShadowRunner() {
    vk::destroyExecutor(executor_);
    destroyPlanResources(context_, owned_);
    for (vk::Image& image : inputs_) vk::destroyImage(context_.device, image);
}

void ShadowRunner::setHistory(std::uint32_t frameIndex, const std::vector<float>& moments,
                              const std::vector<float>& shadow) {
    const char* read = (frameIndex & 1u) != 0 ? "shadow_moments0" : "shadow_moments1";
    uploadImage(context_, owned_.images.at(read), moments, 4);
    // Last frame's metadata all zero (no tile clear): every history texel is read as uploaded,
    // none rebuilt (rebuildClearHistory).
    const vk::Buffer& metadata = owned_.buffers.at(shadowTileMetadataName(frameIndex + 1));
    uploadBuffer(context_, metadata, std::span<const std::byte>(std::vector<std::byte>(metadata.size)));
    if (owned_.images.contains("shadow_scratch1"))
        uploadImage(context_, owned_.images.at("shadow_scratch1"), shadow, 2);
}

ShadowOutputs ShadowRunner::run(const ShadowDenoiserDesc& desc, const ShadowInputs& inputs,
                                PlanTimings* timings, bool readback) {
    const EffectPlan plan = planOrThrow(desc);
    const std::vector<float>* data[] = {&inputs.visibility, &inputs.depth,  &inputs.previousDepth,
                                        &inputs.normals,    &inputs.motion, &inputs.meanVariance};
    std::map<std::string, const vk::Image*> external;
    for (std::size_t i = 0; i < std::size(kInputNames); ++i) {
        if (!data[i]->empty()) uploadImage(context_, inputs_[i], *data[i], kInputChannels[i]);
        external[kInputNames[i]] = &inputs_[i];
    }
    PlanTimings measured = executePlan(context_, executor_, plan, resourceTable(owned_, external));
    if (timings) *timings = std::move(measured);

    ShadowOutputs outputs;
    if (owned_.buffers.contains("shadow_filter_work"))
        outputs.filteredTiles = readWords(context_, owned_.buffers.at("shadow_filter_work")).at(0);
    if (!readback) return outputs;
    outputs.mask = readWords(context_, owned_.buffers.at("shadow_mask"));
    if (desc.classify) {
        outputs.metadata = readWords(context_, owned_.buffers.at(shadowTileMetadataName(desc.frameIndex)));
        const char* written = (desc.frameIndex & 1u) != 0 ? "shadow_moments1" : "shadow_moments0";
        outputs.moments = readbackImage(context_, owned_.images.at(written));
        if (!desc.filter) outputs.classified = readbackImage(context_, owned_.images.at("shadow_scratch0"));
    }
    if (desc.filter)
        outputs.filtered =
            asShadowVariance(readbackImage(context_, owned_.images.at("shadow_output")), desc.outputFormat);
    return outputs;
}

} // namespace glint::gpu
