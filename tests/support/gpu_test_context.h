// The GPU context every GPU test shares, and the check that no validation error slipped by.
//
// testContext() creates one context per test process on first use, with the Khronos
// validation layer and synchronization validation on, on the device GLINT_DEVICE selects.
// End every GPU test with GLINT_REQUIRE_NO_VALIDATION_ERRORS(). As a backstop, when the
// process exits the context is destroyed (so the layer reports leaked Vulkan objects) and, if
// any validation error was ever reported, the process exits with status 1 after listing them,
// even if every test passed.
#pragma once

#include <gpu/gpu_context.h>

#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdio>
#include <string>

namespace glint::test {

gpu::Context& testContext();

struct ValidationCheck {
    uint32_t newErrors = 0;
    std::string messages; // every message (errors and warnings) since the previous check
};

// The validation errors reported since the previous call; does not create the context.
ValidationCheck takeValidationErrors();

} // namespace glint::test

// A GPU test that cannot run on this device says so and ends: it prints "GLINT_SKIP: <reason>",
// which every suite's SKIP_REGULAR_EXPRESSION (tests/CMakeLists.txt) turns into a skip in
// ctest's summary instead of a silent pass. With GLINT_FORBID_SKIPS=1 in the environment (CI,
// on lavapipe, where every such test can run) a skip fails the test instead.
namespace glint::test {
[[nodiscard]] bool skipsForbidden();
} // namespace glint::test

#define GLINT_SKIP(reason)                                                                                   \
    do {                                                                                                     \
        if (::glint::test::skipsForbidden()) FAIL("cannot run, and GLINT_FORBID_SKIPS is set: " << reason);  \
        std::printf("GLINT_SKIP: %s\n", std::string(reason).c_str());                                        \
        std::fflush(stdout);                                                                                 \
        return;                                                                                              \
    } while (false)

#define GLINT_REQUIRE_NO_VALIDATION_ERRORS()                                                                 \
    do {                                                                                                     \
        const ::glint::test::ValidationCheck glintValidationCheck = ::glint::test::takeValidationErrors();   \
        INFO("validation messages:\n" << glintValidationCheck.messages);                                     \
        REQUIRE(glintValidationCheck.newErrors == 0u);                                                       \
    } while (false)
