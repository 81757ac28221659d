// createEffect refuses, in one line naming the buffer, a plan whose buffer is larger than the
// device lets a storage-buffer descriptor cover (the SSSR ray list and ray scratch grow with
// the resolution), and creates one exactly at the limit.
#include "support/gpu_test_context.h"

#include "glint/vulkan/vk_effect.h"

#include <catch2/catch.hpp>

#include <string>

using namespace glint;

TEST_CASE("an effect whose buffer exceeds maxStorageBufferRange is refused in one line naming it",
          "[gpu][limits]") {
    vk::Device device = test::testContext().device;
    device.properties.limits.maxStorageBufferRange = 4096; // as if the device allowed 4 KiB
    EffectPlan plan;
    plan.effect = "limits";
    plan.buffers.push_back({"at_limit", 4096, false});
    vk::EffectInstance effect;
    std::string error;
    REQUIRE(vk::createEffect(device, plan, effect, &error) == Result::Ok);
    vk::destroyEffect(effect);

    plan.buffers.push_back({"sssr_ray_scratch", 4100, false});
    CHECK(vk::createEffect(device, plan, effect, &error) == Result::Unsupported);
    for (const char* part : {"limits: ", "'sssr_ray_scratch'", "4100", "maxStorageBufferRange", "4096"}) {
        INFO(error << " names " << part);
        CHECK(error.find(part) != std::string::npos);
    }
    CHECK(error.find('\n') == std::string::npos);
    vk::destroyEffect(effect); // nothing is left to destroy; must be harmless
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
