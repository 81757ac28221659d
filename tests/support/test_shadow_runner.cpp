#include "support/test_shadow_runner.h"

#include <gpu/gpu_transfer.h>

#include <cstddef>
#include <iterator>
#include <span>
#include <stdexcept>
#include <string>

namespace glint::gpu {

namespace {
const char* const kInputNames[] = {"shadow_visibility",      "shadow_depth",  "shadow_previous_depth",
                                   "shadow_normals",         "shadow_motion", "shadow_filter_input",
                                   "shadow_blocker_distance"};
const VkFormat kInputFormats[] = {
    VK_FORMAT_R32_SFLOAT,    VK_FORMAT_R32_SFLOAT,    VK_FORMAT_R32_SFLOAT, VK_FORMAT_R32G32B32A32_SFLOAT,
    VK_FORMAT_R32G32_SFLOAT, VK_FORMAT_R32G32_SFLOAT, VK_FORMAT_R32_SFLOAT};
// What an engine would bind: an 8-bit visibility target (0 or 1; NaN uploads as 0, shadowed, as
// the shader treats it), 16-bit normals and motion. Depth stays 32-bit.
const VkFormat kCompactFormats[] = {
    VK_FORMAT_R8_UNORM,      VK_FORMAT_R32_SFLOAT,    VK_FORMAT_R32_SFLOAT, VK_FORMAT_R16G16B16A16_SFLOAT,
    VK_FORMAT_R16G16_SFLOAT, VK_FORMAT_R32G32_SFLOAT, VK_FORMAT_R16_SFLOAT};
const std::uint32_t kInputChannels[] = {1, 1, 1, 4, 2, 2, 1};

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
        throw std::invalid_argument(error); // the planner's message names the effect already
    return plan;
}
} // namespace

ShadowRunner::ShadowRunner(const Context& context, const ShadowDenoiserDesc& desc, bool compactInputs)
    : context_(context), runner_(context, planOrThrow(desc)) {
    try {
        for (std::size_t i = 0; i < std::size(kInputNames); ++i)
            inputs_.push_back(vk::createImage2D(context.device, desc.size.width, desc.size.height,
                                                compactInputs ? kCompactFormats[i] : kInputFormats[i]));
    } catch (...) {
        for (vk::Image& image : inputs_) vk::destroyImage(context_.device, image);
        throw;
    }
    // Histories start at zero, not NaN: the first frame ignores them through resetHistory, but
    // tile-skipped texels of the output keep what they hold. Zeroed now rather than in the first
    // run, so that setHistory may overwrite them before it.
    runner_.initialize();
}

ShadowRunner::~ShadowRunner() {
    for (vk::Image& image : inputs_) vk::destroyImage(context_.device, image);
}

void ShadowRunner::setHistory(std::uint32_t frameIndex, const std::vector<float>& moments,
                              const std::vector<float>& shadow) {
    runner_.initialize();
    const char* read = (frameIndex & 1u) != 0 ? "shadow_moments0" : "shadow_moments1";
    uploadImage(context_, runner_.image(read), moments, 4);
    // Last frame's metadata all zero (no tile clear): every history texel is read as uploaded,
    // none rebuilt (rebuildClearHistory).
    const vk::Buffer& metadata = runner_.buffer(shadowTileMetadataName(frameIndex + 1));
    uploadBuffer(context_, metadata, std::span<const std::byte>(std::vector<std::byte>(metadata.size)));
    if (runner_.hasImage("shadow_scratch1"))
        uploadImage(context_, runner_.image("shadow_scratch1"), shadow, 2);
}

ShadowOutputs ShadowRunner::run(const ShadowDenoiserDesc& desc, const ShadowInputs& inputs, FrameRun* timings,
                                bool readback) {
    const EffectPlan plan = planOrThrow(desc);
    const std::vector<float>* data[] = {&inputs.visibility,     &inputs.depth,  &inputs.previousDepth,
                                        &inputs.normals,        &inputs.motion, &inputs.meanVariance,
                                        &inputs.blockerDistance};
    vk::ResourceTable table;
    for (std::size_t i = 0; i < std::size(kInputNames); ++i) {
        if (!data[i]->empty()) uploadImage(context_, inputs_[i], *data[i], kInputChannels[i]);
        table.images[kInputNames[i]] = &inputs_[i];
    }
    FrameRun measured = runner_.run(plan, table);
    if (timings) *timings = std::move(measured);

    ShadowOutputs outputs;
    if (runner_.hasBuffer("shadow_filter_work"))
        outputs.filteredTiles = runner_.readWords("shadow_filter_work").at(0);
    if (!readback) return outputs;
    outputs.mask = runner_.readWords("shadow_mask");
    if (desc.classify) {
        outputs.metadata = runner_.readWords(shadowTileMetadataName(desc.frameIndex));
        const char* written = (desc.frameIndex & 1u) != 0 ? "shadow_moments1" : "shadow_moments0";
        outputs.moments = readbackImage(context_, runner_.image(written));
        if (!desc.filter) outputs.classified = readbackImage(context_, runner_.image("shadow_scratch0"));
    }
    if (desc.filter)
        outputs.filtered =
            asShadowVariance(readbackImage(context_, runner_.image("shadow_output")), desc.outputFormat);
    return outputs;
}

} // namespace glint::gpu
