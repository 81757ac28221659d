#include "support/test_sssr_runner.h"

#include <gpu/gpu_transfer.h>

#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <utility>

namespace glint::gpu {
namespace {

SssrDesc withDefaults(SssrDesc desc) {
    if (desc.composite && desc.compositeReflection.empty()) desc.compositeReflection = "sssr_radiance";
    return desc;
}

EffectPlan planOrThrow(const SssrDesc& desc, const ReflectionsDenoiserDesc* denoiser) {
    EffectPlan plan;
    std::string error;
    if (planReflections(desc, denoiser, plan, &error) != Result::Ok) throw std::runtime_error(error);
    return plan;
}

} // namespace

SssrRunner::SssrRunner(const Context& context, const SssrDesc& desc, bool compactInputs)
    : context_(context), desc_(withDefaults(desc)), runner_(context, planOrThrow(desc_, nullptr)),
      inputs_(context, desc_.size, compactInputs) {
    // Owned images zeroed now rather than in the first run, so that they may be read or
    // overwritten at any time.
    runner_.initialize();
}

SssrRunner::~SssrRunner() = default;

SssrDesc SssrRunner::frameDesc(const SssrDesc& frame) const {
    SssrDesc desc = frame;
    desc.compositeReflection = desc_.compositeReflection;
    return desc;
}

void SssrRunner::upload(const SssrFrameInputs& inputs) {
    const std::pair<InputKind, const std::vector<float>*> images[] = {
        {InputKind::Depth, &inputs.depth},       {InputKind::Normals, &inputs.normals},
        {InputKind::Material, &inputs.material}, {InputKind::Color, &inputs.color},
        {InputKind::Motion, &inputs.motion},     {InputKind::BaseColorMetallic, &inputs.baseColorMetallic}};
    const std::uint32_t channels[] = {1, 4, 4, 4, 2, 4};
    for (std::size_t slot = 0; slot < std::size(images); ++slot) {
        const auto& [kind, texels] = images[slot];
        if (texels->empty()) continue;
        if (texels->size() != std::size_t{desc_.size.width} * desc_.size.height * channels[slot])
            throw std::runtime_error("sssr runner: input " + std::to_string(slot) + " has the wrong size");
        inputs_.upload(kind, *texels, channels[slot]);
    }
    if (!inputs.environment.empty())
        inputs_.uploadEnvironment(inputs.environmentWidth, inputs.environmentHeight, inputs.environment);
}

std::vector<std::string> SssrRunner::passNames(const SssrDesc& frame, bool denoised,
                                               SpatialPath spatialPath) const {
    SssrDesc desc = frameDesc(frame);
    ReflectionsDenoiserDesc denoiser;
    if (denoised) {
        desc.denoise = true;
        if (spatialPath == SpatialPath::RatioEstimator) desc.storeRays = true;
        denoiser.size = desc.size;
        denoiser.halfPrecisionStorage = desc.halfPrecisionStorage;
        denoiser.spatialPath = spatialPath;
    }
    EffectPlan plan;
    if (planReflections(desc, denoised ? &denoiser : nullptr, plan, nullptr) != Result::Ok) return {};
    return gpu::passNames(plan);
}

const vk::Image& SssrRunner::ownedImage(const std::string& name) const {
    return runner_.image(name);
}

void SssrRunner::run(const SssrDesc& frame, std::vector<double>* timings,
                     const ReflectionsDenoiserDesc* denoiser, const vk::PassHooks* extraHooks) {
    if (!inputs_.find(InputKind::Environment))
        throw std::runtime_error("sssr runner: upload the inputs (with an environment) before running");
    const EffectPlan plan = planOrThrow(frameDesc(frame), denoiser);
    const std::pair<const char*, InputKind> names[] = {{"depth", InputKind::Depth},
                                                       {"normals", InputKind::Normals},
                                                       {"material", InputKind::Material},
                                                       {"color", InputKind::Color},
                                                       {"motion", InputKind::Motion},
                                                       {"environment", InputKind::Environment},
                                                       {"base_color_metallic", InputKind::BaseColorMetallic}};
    vk::ResourceTable table;
    for (const auto& [name, kind] : names)
        if (const vk::Image* image = inputs_.find(kind)) table.images[name] = image;
    const FrameRun measured = runner_.run(plan, table, false, extraHooks);
    if (timings && context_.device.timestamps) *timings = measured.milliseconds;
}

std::array<std::uint32_t, 4> SssrRunner::counters() const {
    const std::vector<std::uint32_t> words = runner_.readWords("sssr_counters", 4);
    return {words.at(0), words.at(1), words.at(2), words.at(3)};
}

std::vector<std::uint32_t> SssrRunner::bufferWords(const std::string& buffer, std::size_t count) const {
    return runner_.readWords(buffer, count);
}

SssrFrameOutputs SssrRunner::readback() const {
    SssrFrameOutputs out;
    out.width = desc_.size.width;
    out.height = desc_.size.height;
    const auto read = [&](const char* name) { return readbackImage(context_, runner_.image(name)); };
    out.radiance = read("sssr_radiance");
    out.confidence = read("sssr_confidence");
    out.roughness = read("sssr_roughness");
    out.blueNoise = read("sssr_blue_noise");
    if (runner_.hasImage("sssr_ray_info")) out.rayInfo = read("sssr_ray_info");
    if (runner_.hasImage("sssr_rays")) out.rays = read("sssr_rays");
    if (runner_.hasImage("composite")) out.composite = read("composite");
    const std::vector<std::uint32_t> counters = runner_.readWords("sssr_counters", 4);
    const std::vector<std::uint32_t> arguments = runner_.readWords("sssr_indirect_args", 6);
    std::copy(counters.begin(), counters.end(), out.counters);
    std::copy(arguments.begin(), arguments.end(), out.arguments);
    out.rayList = runner_.readWords("sssr_ray_list", out.counters[1]);
    out.tileList = runner_.readWords("sssr_tile_list", out.counters[3]);
    return out;
}

} // namespace glint::gpu
