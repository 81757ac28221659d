#include "core/pass_model.h"
#include "glint/glint_gbuffer.h"

#include <catch2/catch.hpp>

using namespace glint;

namespace {
EffectPlan validRoughnessPlan() {
    RoughnessExtractionDesc desc;
    desc.size = {13, 7};
    EffectPlan plan;
    REQUIRE(planRoughnessExtraction(desc, plan, nullptr) == Result::Ok);
    return plan;
}
} // namespace

TEST_CASE("the roughness extraction plan is well formed", "[plan]") {
    const EffectPlan plan = validRoughnessPlan();
    CHECK(core::validatePlan(plan).empty());
    REQUIRE(plan.passes.size() == 1);
    const auto& grid = std::get<DirectDispatch>(plan.passes[0].dispatch);
    CHECK(grid.groupsX == 2);
    CHECK(grid.groupsY == 1);
}

TEST_CASE("duplicate pass names are rejected", "[plan]") {
    EffectPlan plan = validRoughnessPlan();
    plan.passes.push_back(plan.passes[0]);
    CHECK_THAT(core::validatePlan(plan), Catch::Contains("duplicate pass 'extract_roughness'"));
}

TEST_CASE("a group count over the guaranteed limit is rejected", "[plan]") {
    EffectPlan plan = validRoughnessPlan();
    plan.passes[0].dispatch = DirectDispatch{70000, 1, 1};
    CHECK_THAT(core::validatePlan(plan), Catch::Contains("65535"));
}

TEST_CASE("a buffer cannot be written and read as indirect arguments by one pass", "[plan]") {
    EffectPlan plan = validRoughnessPlan();
    plan.passes[0].uses.push_back({"g_args", "args", Access::Write});
    plan.passes[0].dispatch = IndirectDispatch{"args", 0};
    CHECK_THAT(core::validatePlan(plan), Catch::Contains("indirect"));
}

TEST_CASE("misaligned indirect offsets are rejected", "[plan]") {
    EffectPlan plan = validRoughnessPlan();
    plan.passes[0].dispatch = IndirectDispatch{"args", 6};
    CHECK_THAT(core::validatePlan(plan), Catch::Contains("aligned"));
}

TEST_CASE("roughness extraction rejects sizes and channels out of range", "[plan]") {
    EffectPlan plan;
    std::string error;
    RoughnessExtractionDesc desc;
    desc.size = {0, 4};
    CHECK(planRoughnessExtraction(desc, plan, &error) == Result::InvalidArgument);
    CHECK_THAT(error, Catch::Contains("size"));
    desc.size = {16385, 4};
    CHECK(planRoughnessExtraction(desc, plan, &error) == Result::InvalidArgument);
    desc.size = {4, 4};
    desc.materialChannel = 4;
    CHECK(planRoughnessExtraction(desc, plan, &error) == Result::InvalidArgument);
    CHECK_THAT(error, Catch::Contains("materialChannel"));
}

TEST_CASE("the fp16 permutation is chosen by the desc", "[plan]") {
    RoughnessExtractionDesc desc;
    desc.size = {4, 4};
    desc.halfPrecisionOutput = true;
    EffectPlan plan;
    REQUIRE(planRoughnessExtraction(desc, plan, nullptr) == Result::Ok);
    CHECK(plan.passes[0].pipeline == "gbuffer_extract_roughness.fp16");
}

TEST_CASE("a pass may only zero buffers the plan defines", "[plan]") {
    EffectPlan plan = validRoughnessPlan();
    plan.passes[0].zeroBuffers = {"counter"};
    CHECK_THAT(core::validatePlan(plan), Catch::Contains("'counter'"));
    plan.buffers.push_back({"counter", 4, false});
    CHECK(core::validatePlan(plan).empty());
}

TEST_CASE("resource descriptions need unique names and non-zero sizes", "[plan]") {
    EffectPlan plan = validRoughnessPlan();
    plan.images.push_back({"pyramid", 64, 64, 7, Format::R32Float});
    CHECK(core::validatePlan(plan).empty());
    plan.buffers.push_back({"pyramid", 16, false});
    CHECK_THAT(core::validatePlan(plan), Catch::Contains("duplicate resource 'pyramid'"));
    plan.buffers.back() = {"counter", 6, false};
    CHECK_THAT(core::validatePlan(plan), Catch::Contains("multiple of 4"));
    plan.buffers.pop_back();
    plan.images.back().mipLevels = 0;
    CHECK_THAT(core::validatePlan(plan), Catch::Contains("level count"));
}
