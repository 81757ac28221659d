// The shared validated context and device selection on the real device list.
#include "support/gpu_test_context.h"

#include <gpu/gpu_context.h>

#include <catch2/catch.hpp>

TEST_CASE("the test context runs under validation and reports a subgroup size", "[gpu]") {
    const glint::gpu::Context& context = glint::test::testContext();
    REQUIRE(context.validation != nullptr);
    REQUIRE(context.messenger != VK_NULL_HANDLE);
    REQUIRE(context.device.queue != VK_NULL_HANDLE);
    CHECK(context.info.subgroupSize > 0);
    CHECK(context.device.subgroupSize == context.info.subgroupSize);
    // Subgroup sizes are powers of two from 1 to 128 by the spec.
    CHECK((context.info.subgroupSize & (context.info.subgroupSize - 1)) == 0);
    CHECK(context.device.timestamps == (context.device.timestampValidBits > 0));
    CHECK(context.instanceApiVersion >= VK_API_VERSION_1_1);
    CHECK(context.device.properties.limits.nonCoherentAtomSize > 0);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("the device list names the device the context chose", "[gpu]") {
    const glint::gpu::Context& context = glint::test::testContext();
    const auto devices = glint::gpu::listDevices(context.instance, context.instanceApiVersion);
    REQUIRE(context.info.index < devices.size());
    CHECK(devices[context.info.index].name == context.info.name);
    CHECK(devices[context.info.index].subgroupSize == context.info.subgroupSize);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("a device selector matching nothing fails context creation with a clear message", "[gpu]") {
    glint::gpu::ContextOptions options;
    options.deviceSelector = "no-such-device-glint";
    CHECK_THROWS_WITH(glint::gpu::createContext(options),
                      Catch::Contains("GLINT_DEVICE='no-such-device-glint'"));
}
