#include "core/pass_model.h"

#include <catch2/catch.hpp>

using namespace glint;
using namespace glint::core;

namespace {

Pass pass(std::string name, std::vector<ResourceUse> uses) {
    Pass p;
    p.name = std::move(name);
    p.pipeline = "test";
    p.uses = std::move(uses);
    return p;
}

EffectPlan plan(std::vector<Pass> passes) {
    EffectPlan p;
    p.effect = "test";
    p.passes = std::move(passes);
    return p;
}

// The barriers planned before pass `index`, as (resource, src, dst).
std::vector<PlannedBarrier> before(const std::vector<PlannedBarrier>& all, std::size_t index) {
    std::vector<PlannedBarrier> out;
    for (const PlannedBarrier& b : all)
        if (b.beforePass == index) out.push_back(b);
    return out;
}

} // namespace

TEST_CASE("the first use of every resource waits for the external write that produced it", "[barriers]") {
    const auto barriers =
        planBarriers(plan({pass("a", {{"in", "x", Access::Read}, {"out", "y", Access::Write}})}));
    REQUIRE(barriers.size() == 2);
    for (const PlannedBarrier& b : barriers) {
        CHECK(b.beforePass == 0);
        CHECK(b.src == kAccessExternalWrite);
    }
}

TEST_CASE("a read after a write gets a barrier from shader write to shader read", "[barriers]") {
    const auto barriers =
        planBarriers(plan({pass("a", {{"o", "y", Access::Write}}), pass("b", {{"i", "y", Access::Read}})}));
    const auto second = before(barriers, 1);
    REQUIRE(second.size() == 1);
    CHECK(second[0].resource == "y");
    CHECK(second[0].src == kAccessShaderWrite);
    CHECK(second[0].dst == kAccessShaderRead);
}

TEST_CASE("reads after reads need no barrier", "[barriers]") {
    const auto barriers =
        planBarriers(plan({pass("a", {{"i", "x", Access::Read}}), pass("b", {{"i", "x", Access::Read}}),
                           pass("c", {{"i", "x", Access::Read}})}));
    CHECK(before(barriers, 1).empty());
    CHECK(before(barriers, 2).empty());
}

TEST_CASE("a write after reads waits for every earlier read", "[barriers]") {
    const auto barriers = planBarriers(
        plan({pass("a", {{"i", "x", Access::Read}}), pass("b", {{"args", "x", Access::IndirectArgs}}),
              pass("c", {{"o", "x", Access::Write}})}));
    const auto third = before(barriers, 2);
    REQUIRE(third.size() == 1);
    CHECK(third[0].src == (kAccessShaderRead | kAccessIndirectRead));
    CHECK(third[0].dst == kAccessShaderWrite);
}

TEST_CASE("consecutive writes to one resource are ordered", "[barriers]") {
    const auto barriers = planBarriers(
        plan({pass("a", {{"o", "x", Access::Write}}), pass("b", {{"o", "x", Access::ReadWrite}})}));
    const auto second = before(barriers, 1);
    REQUIRE(second.size() == 1);
    CHECK(second[0].src == kAccessShaderWrite);
    CHECK(second[0].dst == (kAccessShaderRead | kAccessShaderWrite));
}

TEST_CASE("an indirect dispatch waits for the pass that wrote its arguments", "[barriers]") {
    Pass consumer = pass("consume", {});
    consumer.dispatch = IndirectDispatch{"args", 0};
    const auto barriers = planBarriers(plan({pass("produce", {{"o", "args", Access::Write}}), consumer}));
    const auto second = before(barriers, 1);
    REQUIRE(second.size() == 1);
    CHECK(second[0].src == kAccessShaderWrite);
    CHECK(second[0].dst == kAccessIndirectRead);
}

TEST_CASE("a resource bound twice by one pass gets one barrier with the union of accesses", "[barriers]") {
    const auto barriers =
        planBarriers(plan({pass("a", {{"r", "x", Access::Read}, {"w", "x", Access::Write}})}));
    REQUIRE(barriers.size() == 1);
    CHECK(barriers[0].dst == (kAccessShaderRead | kAccessShaderWrite));
}

TEST_CASE("a buffer zeroed before a dispatch is ordered after earlier uses and before the dispatch",
          "[barriers]") {
    Pass first = pass("count", {{"counter", "c", Access::ReadWrite}});
    Pass second = pass("count_again", {{"counter", "c", Access::ReadWrite}});
    second.zeroBuffers = {"c"};
    const auto barriers = planBarriers(plan({first, second}));
    const auto atSecond = before(barriers, 1);
    REQUIRE(atSecond.size() == 2);
    CHECK(atSecond[0].point == BarrierPoint::BeforeFills);
    CHECK(atSecond[0].src == kAccessShaderWrite);
    CHECK(atSecond[0].dst == kAccessTransferWrite);
    CHECK(atSecond[1].point == BarrierPoint::BeforeDispatch);
    CHECK(atSecond[1].src == kAccessTransferWrite);
    CHECK(atSecond[1].dst == (kAccessShaderRead | kAccessShaderWrite));
}
