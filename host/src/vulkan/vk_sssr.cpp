// The reflections effect on Vulkan: resources at create, initialization on the first dispatch.
#include "vulkan/vk_sssr.h"

#include "glint/glint_sssr_tables.h"

#include <algorithm>
#include <cstring>
#include <exception>
#include <vector>

namespace glint::vk {
namespace {

constexpr const char* kBlueNoiseSource = "sssr_blue_noise_source";
constexpr const char* kBrdfLut = "sssr_brdf_lut";
constexpr const char* kZeroVariance = "sssr_zero_variance";

Result fail(std::string* error, const std::string& message) {
    if (error) *error = "sssr: " + message;
    return Result::InvalidArgument;
}

bool sameResources(const SssrDesc& a, const SssrDesc& b) {
    return a.size.width == b.size.width && a.size.height == b.size.height &&
           a.thicknessAware == b.thicknessAware && a.debugOutput == b.debugOutput &&
           a.composite == b.composite && a.depth == b.depth &&
           a.halfPrecisionStorage == b.halfPrecisionStorage && a.denoise == b.denoise &&
           a.storeRays == b.storeRays;
}

// Every owned image to GENERAL (contents zeroed), counters zeroed, tables copied in.
void recordInitialization(SssrEffect& effect, VkCommandBuffer cmd) {
    std::vector<VkImageMemoryBarrier> toTransfer;
    for (auto& [name, image] : effect.images) {
        VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
        barrier.srcAccessMask = 0;
        barrier.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        barrier.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        barrier.newLayout = VK_IMAGE_LAYOUT_GENERAL;
        barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        barrier.image = image.image;
        barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, image.mipLevels, 0, 1};
        toTransfer.push_back(barrier);
    }
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0,
                         nullptr, 0, nullptr, static_cast<uint32_t>(toTransfer.size()), toTransfer.data());
    const VkClearColorValue zero{};
    for (auto& [name, image] : effect.images) {
        const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, image.mipLevels, 0, 1};
        vkCmdClearColorImage(cmd, image.image, VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &range);
    }
    for (auto& [name, buffer] : effect.buffers) vkCmdFillBuffer(cmd, buffer.buffer, 0, VK_WHOLE_SIZE, 0);
    VkMemoryBarrier clearDone{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    clearDone.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    clearDone.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1,
                         &clearDone, 0, nullptr, 0, nullptr);
    VkDeviceSize offset = 0;
    for (const char* name : {kBlueNoiseSource, kBrdfLut}) {
        const Image& image = effect.images.at(name);
        VkBufferImageCopy copy{};
        copy.bufferOffset = offset;
        copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        copy.imageExtent = {image.width, image.height, 1};
        vkCmdCopyBufferToImage(cmd, effect.staging.buffer, image.image, VK_IMAGE_LAYOUT_GENERAL, 1, &copy);
        offset += VkDeviceSize{image.width} * image.height * formatTexelSize(image.format);
    }
    // The executor's first barrier per resource waits for "all commands" writes.
    VkMemoryBarrier done{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    done.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    done.dstAccessMask =
        VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_INDIRECT_COMMAND_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT, 0, 1,
                         &done, 0, nullptr, 0, nullptr);
}

} // namespace

Result createSssr(const Device& device, const SssrDesc& desc, SssrEffect& effect, std::string* error) {
    EffectPlan plan;
    SssrDesc planned = desc;
    if (planned.composite && planned.compositeReflection.empty())
        planned.compositeReflection = "sssr_radiance";
    if (const Result result = planSssr(planned, plan, error); result != Result::Ok) return result;
    effect = SssrEffect{};
    effect.device = &device;
    effect.desc = planned;
    try {
        if (planned.denoise) { // the denoiser's resources, allocated now like every other
            ReflectionsDenoiserDesc denoiser;
            denoiser.size = planned.size;
            denoiser.halfPrecisionStorage = planned.halfPrecisionStorage;
            EffectPlan denoiserPlan;
            if (const Result result = planReflectionsDenoiser(denoiser, denoiserPlan, error);
                result != Result::Ok)
                return result;
            plan.images.insert(plan.images.end(), denoiserPlan.images.begin(), denoiserPlan.images.end());
            plan.buffers.insert(plan.buffers.end(), denoiserPlan.buffers.begin(), denoiserPlan.buffers.end());
        }
        for (const ImageDesc& image : plan.images)
            effect.images[image.name] =
                createImage2D(device, image.width, image.height, toVkFormat(image.format), image.mipLevels);
        for (const BufferDesc& buffer : plan.buffers) {
            VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
            if (buffer.indirectArgs) usage |= VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT;
            effect.buffers[buffer.name] = createBuffer(device, buffer.size, usage, MemoryUse::DeviceLocal);
        }
        const std::vector<float>& noise = sssrBlueNoise();
        const std::vector<float> lut = sssrBrdfLut(kSssrBrdfLutSize);
        effect.images[kBlueNoiseSource] =
            createImage2D(device, kSssrBlueNoiseSize, kSssrBlueNoiseSize, VK_FORMAT_R32G32_SFLOAT);
        effect.images[kBrdfLut] =
            createImage2D(device, kSssrBrdfLutSize, kSssrBrdfLutSize, VK_FORMAT_R32G32_SFLOAT);
        effect.images[kZeroVariance] = createImage2D(device, 1, 1, VK_FORMAT_R32_SFLOAT);
        const VkDeviceSize bytes = (noise.size() + lut.size()) * sizeof(float);
        effect.staging = createBuffer(device, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::Upload);
        std::memcpy(effect.staging.mapped, noise.data(), noise.size() * sizeof(float));
        std::memcpy(static_cast<char*>(effect.staging.mapped) + noise.size() * sizeof(float), lut.data(),
                    lut.size() * sizeof(float));
        flushBuffer(device, effect.staging);
    } catch (const std::exception& exception) {
        destroySssr(effect);
        return fail(error, exception.what());
    }
    return Result::Ok;
}

Result dispatchSssr(SssrEffect& effect, Executor& executor, VkCommandBuffer cmd, const SssrDesc& frame,
                    const SssrInputs& inputs, const PassHooks& hooks, std::string* error,
                    const ReflectionsDenoiserDesc* denoiser) {
    if (!effect.device) return fail(error, "the effect was not created");
    SssrDesc desc = frame;
    desc.compositeReflection = effect.desc.compositeReflection;
    if (!sameResources(desc, effect.desc))
        return fail(error, "size, depth convention, thicknessAware, debugOutput, halfPrecisionStorage, "
                           "storeRays, composite and denoise are fixed at create");
    const std::pair<const char*, const Image*> required[] = {
        {"depth", inputs.depth}, {"normals", inputs.normals}, {"material", inputs.material},
        {"color", inputs.color}, {"motion", inputs.motion},   {"environment", inputs.environment}};
    ResourceTable table;
    for (const auto& [name, image] : required) {
        if (!image) return fail(error, std::string("input '") + name + "' is missing");
        if (image->width != desc.size.width || image->height != desc.size.height)
            if (std::string(name) != "environment")
                return fail(error, std::string("input '") + name + "' is " + std::to_string(image->width) +
                                       "x" + std::to_string(image->height) + ", the effect is " +
                                       std::to_string(desc.size.width) + "x" +
                                       std::to_string(desc.size.height));
        table.images[name] = image;
    }
    if (desc.composite) {
        if (!inputs.baseColorMetallic)
            return fail(error, "input 'base_color_metallic' is missing (composite)");
        table.images["base_color_metallic"] = inputs.baseColorMetallic;
        if (inputs.compositeReflection) table.images[desc.compositeReflection] = inputs.compositeReflection;
    }
    for (const auto& [name, image] : effect.images) table.images[name] = &image;
    for (const auto& [name, buffer] : effect.buffers) table.buffers[name] = &buffer;
    table.images["sssr_variance_history"] =
        inputs.varianceHistory ? inputs.varianceHistory
        : desc.denoise         ? &effect.images.at(reflectionsDenoiserVariance(desc.frameIndex + 1))
                               : &effect.images.at(kZeroVariance);

    EffectPlan plan;
    if (const Result result = planSssr(desc, plan, error); result != Result::Ok) return result;
    if (denoiser) {
        if (!desc.denoise) return fail(error, "the effect was created without denoise");
        if (denoiser->size.width != desc.size.width || denoiser->size.height != desc.size.height)
            return fail(error, "the denoiser's size differs from the effect's");
        if (denoiser->halfPrecisionStorage != desc.halfPrecisionStorage)
            return fail(error, "the denoiser's halfPrecisionStorage must equal the effect's");
        if (denoiser->spatialPath == SpatialPath::RatioEstimator && !desc.storeRays)
            return fail(error, "the denoiser's ratio-estimator path needs the effect created with storeRays");
        EffectPlan denoiserPlan;
        if (const Result result = planReflectionsDenoiser(*denoiser, denoiserPlan, error);
            result != Result::Ok)
            return result;
        // The denoiser goes right after the intersection, before the composite, so that the
        // composite applies the denoised reflection it overwrites "sssr_radiance" with.
        const auto composite = std::find_if(plan.passes.begin(), plan.passes.end(),
                                            [](const Pass& pass) { return pass.name == "composite"; });
        plan.passes.insert(composite, denoiserPlan.passes.begin(), denoiserPlan.passes.end());
        plan.images.insert(plan.images.end(), denoiserPlan.images.begin(), denoiserPlan.images.end());
        plan.buffers.insert(plan.buffers.end(), denoiserPlan.buffers.begin(), denoiserPlan.buffers.end());
    }
    if (!effect.initialized) {
        recordInitialization(effect, cmd);
        effect.initialized = true;
    }
    try {
        recordPlan(executor, cmd, plan, table, hooks);
    } catch (const std::exception& exception) {
        if (error) *error = exception.what();
        return Result::Unsupported;
    }
    return Result::Ok;
}

void destroySssr(SssrEffect& effect) {
    if (!effect.device) return;
    for (auto& [name, image] : effect.images) destroyImage(*effect.device, image);
    for (auto& [name, buffer] : effect.buffers) destroyBuffer(*effect.device, buffer);
    destroyBuffer(*effect.device, effect.staging);
    effect = SssrEffect{};
}

} // namespace glint::vk
