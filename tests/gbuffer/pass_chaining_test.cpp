// Two passes where the second samples what the first wrote: the executor must derive the
// barrier between them (synchronization validation reports a hazard otherwise) and the
// result must be the reference applied twice.
#include "reference/roughness_reference.h"
#include "support/gpu_test_context.h"

#include "glint/glint_gbuffer.h"
#include "glint/vulkan/vk_executor.h"

#include <gpu/gpu_transfer.h>

#include <catch2/catch.hpp>

using namespace glint;

TEST_CASE("a pass reading an earlier pass's output sees its writes through a derived barrier",
          "[gbuffer][gpu]") {
    gpu::Context& context = test::testContext();
    const vk::Device& device = context.device;
    const uint32_t width = 9, height = 11;

    std::vector<float> material(std::size_t{width} * height * 4);
    for (std::size_t i = 0; i < material.size(); ++i) material[i] = static_cast<float>(i % 17) / 16.0f;

    RoughnessExtractionDesc desc;
    desc.size = {width, height};
    desc.materialChannel = 3;
    EffectPlan first, second;
    REQUIRE(planRoughnessExtraction(desc, first, nullptr) == Result::Ok);
    desc.materialChannel = 0; // the R32F output sampled as float4 has alpha in .x
    REQUIRE(planRoughnessExtraction(desc, second, nullptr) == Result::Ok);

    EffectPlan chained;
    chained.effect = "chained";
    chained.passes.push_back(first.passes[0]);
    chained.passes.push_back(second.passes[0]);
    chained.passes[1].name = "extract_again";
    chained.passes[1].uses = {{"g_glint_material", "alpha_once", Access::Read},
                              {"g_glint_alpha", "alpha_twice", Access::Write}};
    chained.passes[0].uses[1].resource = "alpha_once";

    vk::Image materialImage = vk::createImage2D(device, width, height, VK_FORMAT_R32G32B32A32_SFLOAT);
    vk::Image once = vk::createImage2D(device, width, height, VK_FORMAT_R32_SFLOAT);
    vk::Image twice = vk::createImage2D(device, width, height, VK_FORMAT_R32_SFLOAT);
    gpu::uploadImage(context, materialImage, material, 4);
    VkClearColorValue zero{};
    gpu::clearImage(context, once, zero);
    gpu::clearImage(context, twice, zero);

    vk::Executor executor = vk::createExecutor(device);
    vk::ResourceTable resources;
    resources.images = {{"material", &materialImage}, {"alpha_once", &once}, {"alpha_twice", &twice}};
    gpu::submitAndWait(context,
                       [&](VkCommandBuffer cmd) { vk::recordPlan(executor, cmd, chained, resources); });
    const std::vector<float> result = gpu::readbackImage(context, twice);

    const std::vector<float> onceReference = reference::extractRoughness(material, 4, 3, true);
    const std::vector<float> twiceReference = reference::extractRoughness(onceReference, 1, 0, true);
    REQUIRE(result.size() == twiceReference.size());
    for (std::size_t i = 0; i < result.size(); ++i) {
        INFO("pixel " << i);
        CHECK(result[i] == twiceReference[i]);
    }

    vk::destroyExecutor(executor);
    vk::destroyImage(device, twice);
    vk::destroyImage(device, once);
    vk::destroyImage(device, materialImage);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("a plan whose resources are missing from the table fails naming the effect and resource",
          "[gbuffer][gpu]") {
    gpu::Context& context = test::testContext();
    RoughnessExtractionDesc desc;
    desc.size = {4, 4};
    EffectPlan plan;
    REQUIRE(planRoughnessExtraction(desc, plan, nullptr) == Result::Ok);
    vk::Executor executor = vk::createExecutor(context.device);
    vk::ResourceTable empty;
    std::string message;
    gpu::submitAndWait(context, [&](VkCommandBuffer cmd) {
        try {
            vk::recordPlan(executor, cmd, plan, empty);
        } catch (const std::runtime_error& error) {
            message = error.what();
        }
    });
    CHECK_THAT(message,
               Catch::Contains("gbuffer") && Catch::Contains("'roughness' is not in the resource table"));
    vk::destroyExecutor(executor);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
