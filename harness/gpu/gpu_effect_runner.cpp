#include "gpu/gpu_effect_runner.h"

#include "gpu/gpu_timestamps.h"
#include "gpu/gpu_transfer.h"

#include "glint/common/glint_wire_formats.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <stdexcept>

namespace glint::gpu {
namespace {

using namespace glint::shared;

// The index of the last pass that writes `resource` (SIZE_MAX when none does).
std::size_t lastWriter(const EffectPlan& plan, const std::string& resource) {
    std::size_t last = SIZE_MAX;
    for (std::size_t i = 0; i < plan.passes.size(); ++i)
        for (const ResourceUse& use : plan.passes[i].uses)
            if (use.resource == resource && use.access != Access::Read && use.access != Access::IndirectArgs)
                last = i;
    return last;
}

std::size_t passIndex(const EffectPlan& plan, const std::string& name) {
    for (std::size_t i = 0; i < plan.passes.size(); ++i)
        if (plan.passes[i].name == name) return i;
    return SIZE_MAX;
}

// Whether `output` must be copied after its pass: a later pass writes its resource again.
bool needsSnapshot(const EffectPlan& plan, const OutputDesc& output) {
    if (output.decoder != OutputDecoder::Channels) return false;
    const std::size_t pass = passIndex(plan, output.pass);
    const std::size_t last = lastWriter(plan, output.resource);
    return pass != SIZE_MAX && last != SIZE_MAX && last > pass;
}

// Copies level 0 of `source` into `target` between two dispatches.
void recordCopy(VkCommandBuffer cmd, const vk::Image& source, const vk::Image& target) {
    VkMemoryBarrier before{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    before.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT;
    before.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &before, 0, nullptr, 0, nullptr);
    VkImageCopy region{};
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.extent = {source.width, source.height, 1};
    vkCmdCopyImage(cmd, source.image, VK_IMAGE_LAYOUT_GENERAL, target.image, VK_IMAGE_LAYOUT_GENERAL, 1,
                   &region);
    VkMemoryBarrier after{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    after.srcAccessMask = VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    after.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1,
                         &after, 0, nullptr, 0, nullptr);
}

std::vector<float> channelsOf(const std::vector<float>& texels, std::size_t count, std::uint32_t stride,
                              std::uint32_t first, std::uint32_t keep) {
    std::vector<float> out(count * keep);
    for (std::size_t i = 0; i < count; ++i)
        for (std::uint32_t c = 0; c < keep; ++c) out[i * keep + c] = texels[i * stride + first + c];
    return out;
}

} // namespace

std::vector<std::string> passNames(const EffectPlan& plan) {
    std::vector<std::string> names;
    for (const Pass& pass : plan.passes) names.push_back(pass.name);
    return names;
}

EffectRunner::EffectRunner(const Context& context, const EffectPlan& plan,
                           vk::ShaderLookup applicationShaders)
    : context_(context), size_(plan.size) {
    std::string error;
    if (vk::createEffect(context.device, plan, effect_, &error) != Result::Ok)
        throw std::runtime_error(error);
    executor_ = vk::createExecutor(context.device);
    if (applicationShaders) {
        vk::ShaderLookup library = executor_.findShader;
        executor_.findShader = [library, applicationShaders](std::string_view name) {
            const std::span<const std::uint32_t> code = applicationShaders(name);
            return code.empty() ? library(name) : code;
        };
    }
}

EffectRunner::~EffectRunner() {
    vk::destroyExecutor(executor_);
    for (auto& [name, image] : snapshots_) vk::destroyImage(context_.device, image);
    vk::destroyEffect(effect_);
}

const vk::Image& EffectRunner::image(const std::string& name) const {
    const auto found = effect_.images.find(name);
    if (found == effect_.images.end())
        throw std::runtime_error(effect_.effect + ": the effect owns no image '" + name + "'");
    return found->second;
}

const vk::Buffer& EffectRunner::buffer(const std::string& name) const {
    const auto found = effect_.buffers.find(name);
    if (found == effect_.buffers.end())
        throw std::runtime_error(effect_.effect + ": the effect owns no buffer '" + name + "'");
    return found->second;
}

std::vector<std::uint32_t> EffectRunner::readWords(const std::string& name, std::size_t count) const {
    const std::vector<std::byte> bytes = readbackBuffer(context_, buffer(name));
    std::vector<std::uint32_t> words(std::min(count, bytes.size() / 4));
    if (!words.empty()) std::memcpy(words.data(), bytes.data(), words.size() * 4);
    return words;
}

void EffectRunner::initialize() {
    if (effect_.initialized) return;
    submitAndWait(context_, [&](VkCommandBuffer cmd) { vk::initializeEffect(effect_, cmd); });
}

void EffectRunner::beginFrames() {
    vk::resetExecutor(executor_);
}

std::string EffectRunner::recordFrame(VkCommandBuffer cmd, const EffectPlan& plan,
                                      const vk::ResourceTable& inputs, TimestampPool* timestamps,
                                      const vk::PassHooks* extraHooks, const SnapshotCopies& copies) {
    vk::PassHooks hooks;
    // Top of pipe before and bottom of pipe after: the dispatch's own duration, with the
    // barriers before it and the copies after it outside the interval.
    hooks.beforeDispatch = [&](VkCommandBuffer commands, std::size_t index) {
        if (extraHooks && extraHooks->beforeDispatch) extraHooks->beforeDispatch(commands, index);
        if (timestamps) writeTimestamp(commands, *timestamps, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT);
    };
    hooks.afterDispatch = [&](VkCommandBuffer commands, std::size_t index) {
        if (timestamps) writeTimestamp(commands, *timestamps, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);
        for (const auto& [pass, source, target] : copies)
            if (pass == index) recordCopy(commands, *source, *target);
        if (extraHooks && extraHooks->afterDispatch) extraHooks->afterDispatch(commands, index);
    };
    std::string error;
    if (vk::dispatchEffect(effect_, executor_, cmd, plan, inputs, hooks, &error) != Result::Ok)
        return error.empty() ? plan.effect + ": the frame could not be recorded" : error;
    return {};
}

void EffectRunner::record(VkCommandBuffer cmd, const EffectPlan& plan, const vk::ResourceTable& inputs,
                          TimestampPool* timestamps, const vk::PassHooks* extraHooks) {
    if (const std::string error = recordFrame(cmd, plan, inputs, timestamps, extraHooks, {}); !error.empty())
        throw std::runtime_error(error);
}

EffectRunner::SnapshotCopies EffectRunner::prepareSnapshots(const EffectPlan& plan) {
    SnapshotCopies copies;
    for (const OutputDesc& output : plan.outputs) {
        if (!needsSnapshot(plan, output) || !effect_.images.contains(output.resource)) continue;
        const vk::Image& source = effect_.images.at(output.resource);
        vk::Image& target = snapshots_[output.name];
        if (target.image == VK_NULL_HANDLE || target.format != source.format ||
            target.width != source.width) {
            vk::destroyImage(context_.device, target);
            target = vk::createImage2D(context_.device, source.width, source.height, source.format);
            clearImage(context_, target, VkClearColorValue{});
        }
        copies.emplace_back(passIndex(plan, output.pass), &source, &target);
    }
    return copies;
}

FrameRun EffectRunner::run(const EffectPlan& plan, const vk::ResourceTable& inputs, bool snapshots,
                           const vk::PassHooks* extraHooks) {
    const SnapshotCopies copies = snapshots ? prepareSnapshots(plan) : SnapshotCopies{};
    FrameRun result;
    result.passes = passNames(plan);
    const bool timed = context_.device.timestamps;
    TimestampPool pool;
    if (timed)
        pool = createTimestampPool(context_.device, static_cast<std::uint32_t>(2 * plan.passes.size()));
    beginFrames();
    std::string error;
    try {
        // What was recorded before a failure is still submitted: the effect's initialization
        // (recorded once, then marked done) must run.
        submitAndWait(context_, [&](VkCommandBuffer cmd) {
            if (timed) resetTimestamps(cmd, pool);
            error = recordFrame(cmd, plan, inputs, timed ? &pool : nullptr, extraHooks, copies);
        });
        if (timed && error.empty()) {
            const std::vector<std::uint64_t> ticks = readTimestamps(context_.device, pool);
            for (std::size_t i = 0; i + 1 < ticks.size(); i += 2)
                result.milliseconds.push_back(timestampMilliseconds(pool, ticks[i], ticks[i + 1]));
        }
    } catch (...) {
        if (timed) destroyTimestampPool(context_.device, pool);
        throw;
    }
    if (timed) destroyTimestampPool(context_.device, pool);
    if (!error.empty()) throw std::runtime_error(error);
    return result;
}

const vk::Image& EffectRunner::outputImage(const OutputDesc& output) const {
    const auto snapshot = snapshots_.find(output.name);
    if (snapshot != snapshots_.end()) return snapshot->second;
    return image(output.resource);
}

std::vector<DecodedOutput>
EffectRunner::readOutputs(const EffectPlan& plan, bool intermediates,
                          const std::function<bool(const std::string&)>& wanted) const {
    const auto shown = [&](const std::string& name) { return !wanted || wanted(name); };
    std::vector<DecodedOutput> outputs;
    const std::uint32_t w = size_.width, h = size_.height;
    const std::size_t pixels = std::size_t{w} * h;
    std::vector<std::pair<std::string, double>> counters; // read once, when a list needs them
    // Every image level the outputs show, read back in one submission.
    TransferBatch batch(context_);
    std::map<std::pair<const vk::Image*, std::uint32_t>, std::size_t> tickets;
    const auto queue = [&](const vk::Image& source, std::uint32_t level) {
        if (!tickets.contains({&source, level}))
            tickets[{&source, level}] = batch.readbackImage(source, level);
    };
    for (const OutputDesc& output : plan.outputs) {
        if (output.intermediate && !intermediates) continue;
        if (output.decoder == OutputDecoder::Channels && shown(output.name))
            queue(outputImage(output), output.level);
        if (output.decoder == OutputDecoder::MipChain)
            for (std::uint32_t level = output.level; level < image(output.resource).mipLevels; ++level)
                if (shown(output.name + std::to_string(level))) queue(image(output.resource), level);
    }
    batch.submit();
    const auto texelsOf = [&](const vk::Image& source, std::uint32_t level) {
        return batch.floats(tickets.at({&source, level}));
    };
    for (const OutputDesc& output : plan.outputs) {
        if (output.intermediate && !intermediates) continue;
        if (output.decoder != OutputDecoder::MipChain && !shown(output.name)) continue;
        DecodedOutput decoded{output.name, output.pass, w, h, 1, {}, output.intermediate};
        switch (output.decoder) {
        case OutputDecoder::Channels: {
            const vk::Image& source = outputImage(output);
            const std::vector<float> texels = texelsOf(source, output.level);
            decoded.width = mipWidth(source, output.level);
            decoded.height = mipHeight(source, output.level);
            const std::size_t count = std::size_t{decoded.width} * decoded.height;
            const auto stride = static_cast<std::uint32_t>(texels.size() / count);
            decoded.channels = std::min(output.channels, stride - std::min(stride, output.firstChannel));
            decoded.pixels = channelsOf(texels, count, stride, output.firstChannel, decoded.channels);
            break;
        }
        case OutputDecoder::MipChain: {
            const vk::Image& pyramid = image(output.resource);
            for (std::uint32_t level = output.level; level < pyramid.mipLevels; ++level) {
                if (!shown(output.name + std::to_string(level))) continue;
                const std::vector<float> texels = texelsOf(pyramid, level);
                const std::uint32_t lw = mipWidth(pyramid, level), lh = mipHeight(pyramid, level);
                const std::size_t count = std::size_t{lw} * lh;
                const auto stride = static_cast<std::uint32_t>(texels.size() / count);
                outputs.push_back({output.name + std::to_string(level), output.pass, lw, lh, 1,
                                   channelsOf(texels, count, stride, output.firstChannel, 1),
                                   output.intermediate});
            }
            continue;
        }
        case OutputDecoder::RayList:
        case OutputDecoder::TileList: {
            if (counters.empty()) counters = readCounters(plan);
            std::size_t count = 0;
            for (const auto& [name, value] : counters)
                if (name == output.count) count = static_cast<std::size_t>(value);
            decoded.pixels.assign(pixels, 0.0f);
            for (std::uint32_t entry : readWords(output.resource, count)) {
                if (output.decoder == OutputDecoder::RayList) {
                    const std::uint32_t x = GLINT_WIRE_RayEntryX(entry), y = GLINT_WIRE_RayEntryY(entry);
                    if (x < w && y < h) decoded.pixels[std::size_t{y} * w + x] = 1.0f;
                    continue;
                }
                const std::uint32_t x0 = GLINT_WIRE_TileEntryX(entry), y0 = GLINT_WIRE_TileEntryY(entry);
                for (std::uint32_t y = y0; y < std::min(h, y0 + 8); ++y)
                    for (std::uint32_t x = x0; x < std::min(w, x0 + 8); ++x)
                        decoded.pixels[std::size_t{y} * w + x] = 1.0f;
            }
            break;
        }
        case OutputDecoder::ShadowMask: {
            const std::vector<std::uint32_t> words = readWords(output.resource);
            const std::uint32_t wordsX = (w + 7) / 8;
            decoded.pixels.assign(pixels, 0.0f);
            for (std::uint32_t y = 0; y < h; ++y)
                for (std::uint32_t x = 0; x < w; ++x) {
                    const std::uint32_t word = words.at(std::size_t{y / 4} * wordsX + x / 8);
                    decoded.pixels[std::size_t{y} * w + x] =
                        static_cast<float>((word >> GLINT_WIRE_ShadowMaskBit(x, y)) & 1u);
                }
            break;
        }
        case OutputDecoder::ShadowTileClass: {
            const std::vector<std::uint32_t> words = readWords(output.resource);
            const std::uint32_t tilesX = (w + 7) / 8;
            constexpr std::uint32_t bits = GLINT_WIRE_SHADOW_TILE_CLEAR | GLINT_WIRE_SHADOW_TILE_LIGHT;
            decoded.pixels.assign(pixels, 0.0f);
            for (std::uint32_t y = 0; y < h; ++y)
                for (std::uint32_t x = 0; x < w; ++x)
                    decoded.pixels[std::size_t{y} * w + x] =
                        static_cast<float>(words.at(std::size_t{y / 8} * tilesX + x / 8) & bits);
            break;
        }
        }
        outputs.push_back(std::move(decoded));
    }
    return outputs;
}

std::vector<std::pair<std::string, double>> EffectRunner::readCounters(const EffectPlan& plan) const {
    std::vector<std::pair<std::string, double>> counters;
    const double pixels = static_cast<double>(size_.width) * size_.height;
    std::map<std::string, std::vector<std::uint32_t>> words;
    for (const CounterDesc& counter : plan.counters) {
        if (!effect_.buffers.contains(counter.buffer)) continue;
        auto [slot, fresh] = words.try_emplace(counter.buffer);
        if (fresh) slot->second = readWords(counter.buffer);
        const double value = counter.word < slot->second.size() ? slot->second[counter.word] : 0.0;
        counters.emplace_back(counter.name, value);
        if (!counter.fractionName.empty()) counters.emplace_back(counter.fractionName, value / pixels);
    }
    return counters;
}

} // namespace glint::gpu
