#include "core/shader_library.h"
#include "glint/vulkan/vk_reflect.h"

#include <catch2/catch.hpp>

#include <string>

TEST_CASE("every embedded module is a valid compute shader whose bindings reflect", "[shaders]") {
    const auto names = glint::core::shaderNames();
    REQUIRE_FALSE(names.empty());
    for (std::string_view name : names) {
        INFO(name);
        const auto code = glint::core::findShader(name);
        REQUIRE(code.size() > 5);
        CHECK(code[0] == 0x07230203u); // SPIR-V magic, in host byte order
        const glint::vk::ReflectedShader shader = glint::vk::reflectComputeShader(code, std::string(name));
        CHECK(shader.localSize[0] * shader.localSize[1] * shader.localSize[2] > 0);
        CHECK_FALSE(shader.bindings.empty());
    }
}

TEST_CASE("looking up an unknown module gives an empty span", "[shaders]") {
    CHECK(glint::core::findShader("no_such_shader").empty());
    CHECK(glint::core::findShader("").empty());
}

TEST_CASE("reflection of an empty module names the module", "[shaders]") {
    CHECK_THROWS_WITH(glint::vk::reflectComputeShader({}, "missing_module"),
                      Catch::Contains("missing_module"));
}

TEST_CASE("the roughness extraction permutations exist with their declared formats", "[shaders]") {
    for (const char* name : {"gbuffer_extract_roughness", "gbuffer_extract_roughness.fp16"}) {
        INFO(name);
        const auto shader = glint::vk::reflectComputeShader(glint::core::findShader(name), name);
        CHECK(shader.localSize[0] == 8);
        CHECK(shader.localSize[1] == 8);
        CHECK(shader.localSize[2] == 1);
    }
}
