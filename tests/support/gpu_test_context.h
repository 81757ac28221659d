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

#define GLINT_REQUIRE_NO_VALIDATION_ERRORS()                                                                 \
    do {                                                                                                     \
        const ::glint::test::ValidationCheck glintValidationCheck = ::glint::test::takeValidationErrors();   \
        INFO("validation messages:\n" << glintValidationCheck.messages);                                     \
        REQUIRE(glintValidationCheck.newErrors == 0u);                                                       \
    } while (false)
