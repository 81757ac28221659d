// The effect descriptors (glint_effect.h): every registered effect plans from its own settings
// table, and its plans name only passes and resources they have.
#include "core/pass_model.h"

#include "glint/glint_effect.h"
#include "glint/glint_reflections_denoiser.h"
#include "glint/reflections_denoiser/glint_reflections_denoiser_constants.h"
#include "glint/sssr/glint_sssr_constants.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <set>

namespace {

// A small odd-sized frame with a perspective camera (standard depth, Vulkan NDC).
glint::FrameInfo testFrame(std::uint32_t index = 1) {
    glint::FrameInfo frame;
    frame.size = {37, 23};
    const double n = 0.1, f = 100.0, aspect = 37.0 / 23.0;
    frame.projection = {1.0 / aspect, 0, 0, 0, 0, 1, 0, 0, 0, 0, f / (n - f), n * f / (n - f), 0, 0, -1, 0};
    frame.previousClipFromWorld = frame.projection;
    frame.frameIndex = index;
    return frame;
}

bool declares(const glint::EffectDescriptor& effect, const std::string& name, glint::SettingType type) {
    return std::any_of(
        effect.settings.begin(), effect.settings.end(),
        [&](const glint::SettingDesc& setting) { return setting.name == name && setting.type == type; });
}

bool hasResource(const glint::EffectPlan& plan, const std::string& name) {
    for (const glint::Pass& pass : plan.passes)
        for (const glint::ResourceUse& use : pass.uses)
            if (use.resource == name) return true;
    return false;
}

bool hasPass(const glint::EffectPlan& plan, const std::string& name) {
    return std::any_of(plan.passes.begin(), plan.passes.end(),
                       [&](const glint::Pass& pass) { return pass.name == name; });
}

float floatAt(const glint::Pass& pass, std::size_t offset) {
    float value = 0.0f;
    REQUIRE(offset + sizeof(float) <= pass.constants.size());
    std::memcpy(&value, pass.constants.data() + offset, sizeof(float));
    return value;
}

const glint::Pass& passNamed(const glint::EffectPlan& plan, const std::string& name) {
    for (const glint::Pass& pass : plan.passes)
        if (pass.name == name) return pass;
    FAIL("no pass " << name);
    return plan.passes.front();
}

} // namespace

TEST_CASE("every registered effect is found by name, once", "[effects]") {
    std::set<std::string> names;
    for (const glint::EffectDescriptor* effect : glint::effectRegistry()) {
        CHECK(names.insert(effect->name).second);
        CHECK(glint::findEffect(effect->name) == effect);
        CHECK(effect->plan != nullptr);
        CHECK_FALSE(effect->help.empty());
    }
    CHECK(glint::findEffect("nosuch") == nullptr);
}

TEST_CASE("every setting an effect refers to is declared in its own table", "[effects]") {
    for (const glint::EffectDescriptor* effect : glint::effectRegistry()) {
        INFO(effect->name);
        std::set<std::string> names;
        for (const glint::SettingDesc& setting : effect->settings) {
            CHECK(names.insert(setting.name).second);
            CHECK_FALSE(setting.help.empty());
            CHECK_FALSE(setting.target.empty());
            if (setting.type == glint::SettingType::Float || setting.type == glint::SettingType::Uint)
                CHECK((setting.minimum <= setting.defaultValue && setting.defaultValue <= setting.maximum));
        }
        for (const std::string& name : effect->resourceSettings) CHECK(names.contains(name));
        for (const glint::InputDesc& input : effect->inputs)
            if (!input.setting.empty()) CHECK(declares(*effect, input.setting, glint::SettingType::Bool));
        if (!effect->debugSetting.empty())
            CHECK(declares(*effect, effect->debugSetting, glint::SettingType::Bool));
    }
}

TEST_CASE("a setting two effects declare is the same row in both", "[effects]") {
    for (const glint::SettingDesc* shared : glint::allSettings())
        for (const glint::EffectDescriptor* effect : glint::effectRegistry())
            for (const glint::SettingDesc& setting : effect->settings)
                if (setting.name == shared->name) {
                    CHECK(setting.type == shared->type);
                    CHECK(setting.defaultValue == shared->defaultValue);
                }
}

TEST_CASE("every effect plans at its defaults, and its plan names only what it has", "[effects]") {
    for (const glint::EffectDescriptor* effect : glint::effectRegistry()) {
        for (const bool reset : {true, false}) {
            INFO(effect->name << " reset " << reset);
            glint::FrameInfo frame = testFrame();
            frame.resetHistory = reset;
            glint::EffectPlan plan;
            std::string error;
            REQUIRE(effect->plan(frame, glint::defaultSettings({effect}), plan, &error) == glint::Result::Ok);
            CHECK(glint::core::validatePlan(plan).empty());
            CHECK(plan.size.width == 37);
            CHECK(plan.size.height == 23);
            CHECK_FALSE(plan.outputs.empty());
            for (const glint::OutputDesc& output : plan.outputs) {
                INFO(output.name);
                CHECK(hasPass(plan, output.pass));
                CHECK(hasResource(plan, output.resource));
            }
            for (const glint::CounterDesc& counter : plan.counters) CHECK(hasResource(plan, counter.buffer));
            for (const glint::InputDesc& input : effect->inputs) {
                INFO(input.resource);
                if (input.setting.empty()) CHECK(hasResource(plan, input.resource));
            }
        }
    }
}

TEST_CASE("the roughness threshold set once reaches SSSR's and the denoiser's constants", "[effects]") {
    const glint::EffectDescriptor& reflections = *glint::findEffect("reflections");
    glint::SettingValues settings = glint::defaultSettings({&reflections});
    REQUIRE(settings.assign("denoise=true").empty());
    REQUIRE(settings.assign("roughnessThreshold=0.35").empty());
    REQUIRE(settings.assign("mirrorThreshold=0.01").empty());
    glint::EffectPlan plan;
    std::string error;
    REQUIRE(reflections.plan(testFrame(), settings, plan, &error) == glint::Result::Ok);
    using glint::shaders::GLINT_ReflectionsDenoiserConstants;
    using glint::shaders::GLINT_SssrConstants;
    CHECK(floatAt(passNamed(plan, "classify"), offsetof(GLINT_SssrConstants, roughnessThreshold)) == 0.35f);
    CHECK(floatAt(passNamed(plan, "reproject"),
                  offsetof(GLINT_ReflectionsDenoiserConstants, roughnessThreshold)) == 0.35f);
    CHECK(floatAt(passNamed(plan, "classify"), offsetof(GLINT_SssrConstants, mirrorThreshold)) == 0.01f);
    CHECK(floatAt(passNamed(plan, "reproject"),
                  offsetof(GLINT_ReflectionsDenoiserConstants, mirrorThreshold)) == 0.01f);
}

TEST_CASE("the reflections' variance history is last frame's denoised variance", "[effects]") {
    const glint::EffectDescriptor& reflections = *glint::findEffect("reflections");
    glint::SettingValues settings = glint::defaultSettings({&reflections});
    for (const std::uint32_t index : {4u, 5u}) {
        REQUIRE(settings.assign("denoise=true").empty());
        glint::EffectPlan plan;
        std::string error;
        REQUIRE(reflections.plan(testFrame(index), settings, plan, &error) == glint::Result::Ok);
        const std::string written = glint::reflectionsDenoiserVariance(index);
        const std::string read = glint::reflectionsDenoiserVariance(index + 1);
        CHECK(written != read);
        bool classifyReads = false;
        for (const glint::ResourceUse& use : passNamed(plan, "classify").uses)
            classifyReads =
                classifyReads || (use.binding == "g_glint_variance_history" && use.resource == read);
        CHECK(classifyReads);
        // Without the denoiser: a zero history, and none of the denoiser's passes.
        REQUIRE(settings.assign("denoise=false").empty());
        glint::EffectPlan plain;
        REQUIRE(reflections.plan(testFrame(index), settings, plain, &error) == glint::Result::Ok);
        CHECK_FALSE(hasPass(plain, "reproject"));
        CHECK(hasResource(plain, "sssr_zero_variance"));
    }
}

TEST_CASE("the shadows effect refuses scaled motion it cannot apply", "[effects]") {
    const glint::EffectDescriptor& shadows = *glint::findEffect("shadows");
    glint::FrameInfo frame = testFrame();
    frame.motionScaleX = 2.0f;
    glint::EffectPlan plan;
    std::string error;
    CHECK(shadows.plan(frame, glint::defaultSettings({&shadows}), plan, &error) ==
          glint::Result::InvalidArgument);
    CHECK(error == "shadows: motion must be unscaled convention A (FrameInfo::motionScale 1, 1)");
}
