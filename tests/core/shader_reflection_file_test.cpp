// The reflection files installed with the SPIR-V (cmake/GlintShaderData.cmake) against the
// hand-written plans: each file is read from a compiled module, each plan states what its
// passes bind and dispatch, so the two agree only if both are right. Plans are made at every
// effect's defaults and with each Bool and Choice setting changed, so that every permutation a
// plan can pick is covered.
#include "core/shader_library.h"

#include "glint/glint_effect.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace {

const std::filesystem::path kSpirvDir = GLINT_TEST_SPIRV_DIR;
const std::filesystem::path kGlslDir = GLINT_TEST_GLSL_DIR;

nlohmann::json readReflection(const std::string& module) {
    std::ifstream in(kSpirvDir / (module + ".json"));
    REQUIRE(in.good());
    return nlohmann::json::parse(in);
}

glint::FrameInfo testFrame() {
    glint::FrameInfo frame;
    frame.size = {45, 29};
    const double n = 0.1, f = 100.0, aspect = 45.0 / 29.0;
    frame.projection = {1.0 / aspect, 0, 0, 0, 0, 1, 0, 0, 0, 0, f / (n - f), n * f / (n - f), 0, 0, -1, 0};
    frame.previousClipFromWorld = frame.projection;
    frame.frameIndex = 3;
    return frame;
}

// The settings variations of one effect: its defaults, then each Bool flipped and each Choice
// at each of its values, one change at a time.
std::vector<std::pair<std::string, glint::SettingValues>> variations(const glint::EffectDescriptor& effect) {
    std::vector<std::pair<std::string, glint::SettingValues>> result{
        {"defaults", glint::defaultSettings({&effect})}};
    const auto vary = [&](const glint::SettingDesc& setting, double value, const std::string& shown) {
        glint::SettingValues values = glint::defaultSettings({&effect});
        values.set(setting.name, value);
        result.emplace_back(setting.name + "=" + shown, values);
    };
    for (const glint::SettingDesc& setting : effect.settings) {
        if (setting.type == glint::SettingType::Bool)
            vary(setting, setting.defaultValue != 0.0 ? 0.0 : 1.0,
                 setting.defaultValue != 0.0 ? "false" : "true");
        else if (setting.type == glint::SettingType::Choice)
            for (std::size_t choice = 0; choice < setting.choices.size(); ++choice)
                vary(setting, static_cast<double>(choice), setting.choices[choice]);
    }
    return result;
}

// The GLSL spelling of a storage format, as SPIRV-Cross reflects it.
std::string formatName(glint::Format format) {
    switch (format) {
    case glint::Format::R32Float:
        return "r32f";
    case glint::Format::RG32Float:
        return "rg32f";
    case glint::Format::RGBA32Float:
        return "rgba32f";
    case glint::Format::R16Float:
        return "r16f";
    case glint::Format::RG16Float:
        return "rg16f";
    case glint::Format::RGBA16Float:
        return "rgba16f";
    case glint::Format::R8Unorm:
        return "r8";
    case glint::Format::RGBA8Unorm:
        return "rgba8";
    case glint::Format::R32Uint:
        return "r32ui";
    }
    return "?";
}

void checkPass(const glint::EffectPlan& plan, const glint::Pass& pass) {
    INFO("pass " << pass.name << " module " << pass.pipeline);
    const nlohmann::json reflection = readReflection(pass.pipeline);
    CHECK(reflection.at("module") == pass.pipeline);
    CHECK(reflection.at("thread_shape") ==
          nlohmann::json::array({pass.groupSize[0], pass.groupSize[1], pass.groupSize[2]}));

    std::map<std::string, nlohmann::json> bindings;
    for (const nlohmann::json& binding : reflection.at("bindings"))
        bindings[binding.at("name").get<std::string>()] = binding;
    std::set<std::string> bound;
    for (const glint::ResourceUse& use : pass.uses) {
        INFO("binding " << use.binding);
        if (use.access == glint::Access::IndirectArgs) continue;
        REQUIRE(bindings.count(use.binding) == 1);
        const nlohmann::json& binding = bindings[use.binding];
        bound.insert(use.binding);
        const bool writes = use.access == glint::Access::Write || use.access == glint::Access::ReadWrite;
        if (writes) CHECK(binding.at("access") != "read");
        const auto image =
            std::find_if(plan.images.begin(), plan.images.end(),
                         [&](const glint::ImageDesc& desc) { return desc.name == use.resource; });
        const auto buffer =
            std::find_if(plan.buffers.begin(), plan.buffers.end(),
                         [&](const glint::BufferDesc& desc) { return desc.name == use.resource; });
        if (buffer != plan.buffers.end()) CHECK(binding.at("kind") == "storage_buffer");
        if (image != plan.images.end()) {
            if (writes) CHECK(binding.at("kind") == "storage_image");
            if (binding.at("kind") == "storage_image")
                CHECK(binding.at("format") == formatName(image->format));
            else
                CHECK(binding.at("kind") == "sampled_image");
        }
    }
    if (!pass.constantsBinding.empty()) {
        INFO("constants " << pass.constantsBinding);
        REQUIRE(bindings.count(pass.constantsBinding) == 1);
        bound.insert(pass.constantsBinding);
        CHECK(bindings[pass.constantsBinding].at("kind") == "uniform_buffer");
        const nlohmann::json& constants = reflection.at("constants");
        REQUIRE(constants.size() == 1);
        CHECK(constants[0].at("size").get<std::size_t>() == pass.constants.size());
        CHECK_FALSE(constants[0].at("members").empty());
    }
    // Every binding the module has is one the plan fills (samplers are the backend's own).
    for (const auto& [name, binding] : bindings) {
        INFO("module binding " << name);
        if (binding.at("kind") != "sampler") CHECK(bound.count(name) == 1);
    }
}

} // namespace

TEST_CASE("every library module has a reflection file and a GLSL 450 translation", "[shaders]") {
    for (std::string_view name : glint::core::shaderNames()) {
        const std::string module(name);
        INFO(module);
        const nlohmann::json reflection = readReflection(module);
        CHECK(reflection.at("format") == "glint-shader");
        CHECK(reflection.at("module") == module);
        CHECK(std::filesystem::exists(std::filesystem::path(GLINT_TEST_HLSL_ROOT) /
                                      reflection.at("source").get<std::string>()));
        // The translation declares the same thread shape as the module.
        std::ifstream glsl(kGlslDir / (module + ".comp"));
        REQUIRE(glsl.good());
        const std::string text((std::istreambuf_iterator<char>(glsl)), std::istreambuf_iterator<char>());
        const nlohmann::json& shape = reflection.at("thread_shape");
        const std::string layout = "layout(local_size_x = " + std::to_string(shape[0].get<int>()) +
                                   ", local_size_y = " + std::to_string(shape[1].get<int>()) +
                                   ", local_size_z = " + std::to_string(shape[2].get<int>()) + ") in;";
        CHECK(text.find("#version 450") != std::string::npos);
        CHECK(text.find(layout) != std::string::npos);
    }
}

TEST_CASE("reflection files agree with every pass of every plan", "[shaders]") {
    std::set<std::string> modulesSeen;
    for (const glint::EffectDescriptor* effect : glint::effectRegistry()) {
        std::size_t planned = 0;
        for (const auto& [shown, settings] : variations(*effect)) {
            INFO(effect->name << " with " << shown);
            glint::EffectPlan plan;
            std::string error;
            if (effect->plan(testFrame(), settings, plan, &error) != glint::Result::Ok) continue;
            ++planned;
            for (const glint::Pass& pass : plan.passes) {
                // The application's modules (the hybrid's ray tracing and shading) are not glint's.
                if (glint::core::findShader(pass.pipeline).empty()) continue;
                checkPass(plan, pass);
                modulesSeen.insert(pass.pipeline);
            }
        }
        INFO(effect->name);
        CHECK(planned > 1); // the defaults and at least one variation plan
    }
    CHECK(modulesSeen.size() > 10);
}
