#include "hybrid/hybrid_test_frame.h"

#include "support/gpu_test_context.h"

#include <scene/scene_shaders.h>

#include <gpu/gpu_effect_runner.h>
#include <gpu/gpu_input_images.h>
#include <gpu/gpu_transfer.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>

namespace glint::test {

namespace {

template <typename T> vk::Buffer deviceBuffer(const std::vector<T>& values) {
    const gpu::Context& context = testContext();
    // Never empty: a binding needs a buffer even when the scene has none of these.
    const std::size_t bytes = std::max<std::size_t>(values.size() * sizeof(T), 16);
    vk::Buffer buffer = vk::createBuffer(context.device, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                         vk::MemoryUse::DeviceLocal);
    if (!values.empty()) gpu::uploadBuffer(context, buffer, std::span<const T>(values));
    return buffer;
}

} // namespace

HybridTestScene::HybridTestScene(std::vector<shaders::ScenePrimitive> primitives,
                                 const std::vector<shaders::SceneMaterial>& materials,
                                 const std::vector<shaders::SceneLight>& lights)
    : bvh_(scene::buildBvh(std::move(primitives))) {
    shaders::GLINT_SceneConstants constants{};
    constants.lightCount = static_cast<std::uint32_t>(lights.size());
    constants.shadowSamples = 4;
    constants_ = deviceBuffer(std::vector<shaders::GLINT_SceneConstants>{constants});
    nodes_ = deviceBuffer(bvh_.nodes);
    primitives_ = deviceBuffer(bvh_.primitives);
    materials_ = deviceBuffer(materials);
    lights_ = deviceBuffer(lights);
}

HybridTestScene::~HybridTestScene() {
    const gpu::Context& context = testContext();
    for (vk::Buffer* buffer : {&constants_, &nodes_, &primitives_, &materials_, &lights_})
        vk::destroyBuffer(context.device, *buffer);
}

void HybridTestScene::addTo(vk::ResourceTable& table) const {
    table.buffers["scene_constants"] = &constants_;
    table.buffers["scene_nodes"] = &nodes_;
    table.buffers["scene_primitives"] = &primitives_;
    table.buffers["scene_materials"] = &materials_;
    table.buffers["scene_lights"] = &lights_;
}

vk::ResourceTable uploadInputs(gpu::InputImages& inputs, const SssrTestView& view) {
    const std::pair<const char*, InputKind> kinds[] = {
        {"depth", InputKind::Depth},       {"normals", InputKind::Normals},
        {"material", InputKind::Material}, {"color", InputKind::Color},
        {"motion", InputKind::Motion},     {"base_color_metallic", InputKind::BaseColorMetallic}};
    const std::vector<float>* texels[] = {&view.inputs.depth,    &view.inputs.normals,
                                          &view.inputs.material, &view.inputs.color,
                                          &view.inputs.motion,   &view.inputs.baseColorMetallic};
    const std::uint32_t channels[] = {1, 4, 4, 4, 2, 4};
    vk::ResourceTable table;
    for (std::size_t i = 0; i < std::size(kinds); ++i) {
        if (texels[i]->empty()) continue;
        inputs.upload(kinds[i].second, *texels[i], channels[i]);
        table.images[kinds[i].first] = inputs.find(kinds[i].second);
    }
    inputs.uploadEnvironment(view.inputs.environmentWidth, view.inputs.environmentHeight,
                             view.inputs.environment);
    table.images["environment"] = inputs.find(InputKind::Environment);
    return table;
}

HybridFrame runHybridFrame(const HybridDesc& desc, const SssrTestView& view,
                           const std::vector<std::uint32_t>& history,
                           const std::vector<std::string>& skipPasses, const HybridTestScene* sceneInputs) {
    AddScene add;
    if (sceneInputs) add = [sceneInputs](vk::ResourceTable& table) { sceneInputs->addTo(table); };
    return runHybridFrame(desc, view, history, skipPasses, add);
}

HybridFrame runHybridFrame(const HybridDesc& desc, const SssrTestView& view,
                           const std::vector<std::uint32_t>& history,
                           const std::vector<std::string>& skipPasses, const AddScene& addScene) {
    EffectPlan plan;
    std::string error;
    REQUIRE(planHybrid(desc, plan, &error) == Result::Ok);
    std::erase_if(plan.passes, [&](const Pass& pass) {
        return std::find(skipPasses.begin(), skipPasses.end(), pass.name) != skipPasses.end();
    });
    const bool rayTracedArguments = std::none_of(skipPasses.begin(), skipPasses.end(),
                                                 [](const std::string& name) { return name == "hw_args"; });

    const gpu::Context& context = testContext();
    gpu::EffectRunner runner(context, plan, scene::findShader);
    runner.initialize();
    gpu::uploadImageBytes(context, runner.image(hybridFeedbackImages(desc.sssr.frameIndex).second),
                          std::as_bytes(std::span(history)));
    gpu::InputImages inputs(context, view.desc.size, false);
    vk::ResourceTable table = uploadInputs(inputs, view);
    if (addScene) addScene(table);
    runner.run(plan, table);

    const auto words = [&](const std::string& image) {
        const std::vector<std::byte> bytes = gpu::readbackImageBytes(context, runner.image(image));
        std::vector<std::uint32_t> values(bytes.size() / 4);
        std::memcpy(values.data(), bytes.data(), bytes.size());
        return values;
    };
    HybridFrame out;
    out.tileClass = words("hybrid_tile_class");
    out.feedback = words(hybridFeedbackImages(desc.sssr.frameIndex).first);
    out.counters = runner.readWords("hybrid_counters");
    out.arguments = runner.readWords("hybrid_indirect_args");
    // The arguments pass kept the screen-space list's length in counter 1 and the tiles' in 3.
    out.swList = runner.readWords("hybrid_sw_ray_list", out.counters.at(1));
    out.hwList = runner.readWords("hybrid_hw_ray_list", out.counters.at(rayTracedArguments ? 5 : 4));
    out.tileList = runner.readWords("sssr_tile_list", out.counters.at(3));
    out.radiance = gpu::readbackImage(context, runner.image("sssr_radiance"));
    out.confidence = gpu::readbackImage(context, runner.image("sssr_confidence"));
    if (addScene) out.hits = runner.readWords("hybrid_hits", 4 * out.hwList.size());
    const std::uint32_t reshaded = out.counters.at(rayTracedArguments ? 7 : 6);
    if (reshaded > 0) {
        const std::vector<std::uint32_t> list = runner.readWords("hybrid_hw_ray_list");
        const std::vector<std::uint32_t> records = runner.readWords("hybrid_hits");
        const std::size_t capacity = std::size_t{desc.sssr.size.width} * desc.sssr.size.height;
        for (std::size_t k = 0; k < reshaded; ++k) {
            const std::size_t slot = capacity - 1 - k;
            out.reshadedList.push_back(list.at(slot));
            for (std::size_t word = 0; word < 4; ++word)
                out.reshadedHits.push_back(records.at(4 * slot + word));
        }
    }
    return out;
}

} // namespace glint::test
