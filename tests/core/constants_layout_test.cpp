// The C++ view of each constants struct must match the layout the HLSL compiler chose for
// the same header; reflection of the compiled module is the independent witness.
#include "core/shader_library.h"
#include "glint/gbuffer/glint_gbuffer_constants.h"
#include "glint/vulkan/vk_reflect.h"

#include <catch2/catch.hpp>

#include <cstddef>
#include <map>

namespace {

std::map<std::string, std::uint32_t> reflectedOffsets(const char* module, const char* binding,
                                                      std::uint32_t& size) {
    const auto shader = glint::vk::reflectComputeShader(glint::core::findShader(module), module);
    for (const auto& b : shader.bindings) {
        if (b.name != binding) continue;
        size = b.blockSize;
        std::map<std::string, std::uint32_t> offsets;
        for (const auto& member : b.members) offsets[member.name] = member.offset;
        return offsets;
    }
    FAIL("binding " << binding << " not found in " << module);
    return {};
}

} // namespace

TEST_CASE("roughness extraction constants have the same layout in C++ and HLSL", "[constants]") {
    using glint::shaders::GLINT_GBufferRoughnessConstants;
    for (const char* module : {"gbuffer_extract_roughness", "gbuffer_extract_roughness.fp16"}) {
        INFO(module);
        std::uint32_t size = 0;
        const auto offsets = reflectedOffsets(module, "g_glint_constants", size);
        CHECK(size == sizeof(GLINT_GBufferRoughnessConstants));
        CHECK(offsets.at("size") == offsetof(GLINT_GBufferRoughnessConstants, size));
        CHECK(offsets.at("materialChannel") == offsetof(GLINT_GBufferRoughnessConstants, materialChannel));
        CHECK(offsets.at("inputIsPerceptual") ==
              offsetof(GLINT_GBufferRoughnessConstants, inputIsPerceptual));
    }
}
