// The SSSR plan without a GPU: pass order and dispatch shapes, resources, validation messages.
#include "glint/glint_sssr.h"

#include <catch2/catch.hpp>

#include <tuple>

#include <cmath>
#include <limits>
#include <variant>

using namespace glint;

namespace {

SssrDesc validDesc() {
    SssrDesc desc;
    desc.halfPrecisionStorage = false; // the permutations named below are the 32-bit ones
    desc.size = {1920, 1080};
    desc.projection = {1.0, 0, 0, 0, 0, 1.7, 0, 0, 0, 0, -1.0001, -0.10001, 0, 0, -1, 0};
    return desc;
}

const Pass* findPass(const EffectPlan& plan, const std::string& name) {
    for (const Pass& pass : plan.passes)
        if (pass.name == name) return &pass;
    return nullptr;
}

} // namespace

TEST_CASE(
    "the plan runs the pyramid, classification, compaction, blue noise, arguments and intersection in order",
    "[sssr]") {
    EffectPlan plan;
    REQUIRE(planSssr(validDesc(), plan, nullptr) == Result::Ok);
    std::vector<std::string> names;
    for (const Pass& pass : plan.passes) names.push_back(pass.name);
    REQUIRE(names.size() == 4);
    CHECK(names[1] == "classify");
    CHECK(names[2] == "compact_noise_args");
    CHECK(names[3] == "intersect");
    const auto& classify = std::get<DirectDispatch>(findPass(plan, "classify")->dispatch);
    CHECK(classify.groupsX == 240);
    CHECK(classify.groupsY == 135);
    // 32,400 tiles in blocks of 64: 507 groups (more than the blue noise's 256), one row.
    const Pass* compact = findPass(plan, "compact_noise_args");
    CHECK(compact->pipeline == "sssr_blue_noise.compact");
    const auto& compactGrid = std::get<DirectDispatch>(compact->dispatch);
    CHECK((compactGrid.groupsX == 507 && compactGrid.groupsY == 1));
    const auto& intersect = std::get<IndirectDispatch>(findPass(plan, "intersect")->dispatch);
    CHECK(intersect.resource == "sssr_indirect_args");
    CHECK(intersect.offset == 0);
    bool pyramidHasSevenLevels = false;
    for (const ImageDesc& image : plan.images)
        if (image.name == "depth_pyramid") pyramidHasSevenLevels = image.mipLevels == 7;
    CHECK(pyramidHasSevenLevels);
    for (const BufferDesc& buffer : plan.buffers) {
        if (buffer.name == "sssr_ray_list") CHECK(buffer.size == 1920ull * 1080 * 4);
        if (buffer.name == "sssr_tile_list") CHECK(buffer.size == 240ull * 135 * 4);
        if (buffer.name == "sssr_counters") CHECK(buffer.size == 16);
        // 64 slots and a count per tile, 507 block and 8 superblock counts, a completion counter.
        if (buffer.name == "sssr_ray_scratch") CHECK(buffer.size == (32400ull * 65 + 507 + 8 + 1) * 4);
        if (buffer.name == "sssr_indirect_args") CHECK((buffer.size == 24 && buffer.indirectArgs));
    }
}

TEST_CASE("the compaction's grid covers every block of 64 tiles and the blue noise's 256 groups", "[sssr]") {
    // 4K: 480 x 270 = 129,600 tiles, 2,025 blocks in rows of 1,024; 64x64: one block, and the
    // blue noise still needs its 16 x 16 groups.
    for (const auto& [width, height, x, y] :
         {std::tuple{3840u, 2160u, 1024u, 2u}, std::tuple{64u, 64u, 256u, 1u}}) {
        INFO(width << "x" << height);
        SssrDesc desc = validDesc();
        desc.size = {width, height};
        EffectPlan plan;
        REQUIRE(planSssr(desc, plan, nullptr) == Result::Ok);
        const auto& grid = std::get<DirectDispatch>(findPass(plan, "compact_noise_args")->dispatch);
        CHECK(grid.groupsX == x);
        CHECK(grid.groupsY == y);
    }
}

TEST_CASE("options pick the permutation and add their resources", "[sssr]") {
    SssrDesc desc = validDesc();
    desc.thicknessAware = true;
    desc.debugOutput = true;
    desc.composite = true;
    EffectPlan plan;
    REQUIRE(planSssr(desc, plan, nullptr) == Result::Ok);
    CHECK(findPass(plan, "intersect")->pipeline == "sssr_intersect.thick_debug");
    REQUIRE(findPass(plan, "composite") != nullptr);
    bool rgPyramid = false, rayInfo = false;
    for (const ImageDesc& image : plan.images) {
        if (image.name == "depth_pyramid") rgPyramid = image.format == Format::RG32Float;
        if (image.name == "sssr_ray_info") rayInfo = true;
    }
    CHECK(rgPyramid);
    CHECK(rayInfo);
    desc.size = {3, 2}; // fewer than 7 levels exist: the whole chain
    REQUIRE(planSssr(desc, plan, nullptr) == Result::Ok);
}

TEST_CASE("invalid descs are refused with a message naming the field", "[sssr]") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    struct Case {
        const char* field;
        void (*apply)(SssrDesc&);
    };
    const Case cases[] = {
        {"size",
         [](SssrDesc& d) {
             d.size = {0, 10};
         }},
        {"size",
         [](SssrDesc& d) {
             d.size = {100, 16384};
         }},
        {"samplesPerQuad", [](SssrDesc& d) { d.samplesPerQuad = 3; }},
        {"roughnessThreshold",
         [](SssrDesc& d) { d.roughnessThreshold = std::numeric_limits<float>::quiet_NaN(); }},
        {"mostDetailedMip", [](SssrDesc& d) { d.mostDetailedMip = 7; }},
        {"maxTraversalIterations", [](SssrDesc& d) { d.maxTraversalIterations = 0; }},
        {"projection", [](SssrDesc& d) { d.projection.fill(0.0); }},
        {"camera matrices",
         [](SssrDesc& d) { d.viewFromWorld[3] = std::numeric_limits<double>::infinity(); }},
        {"farPlane", [](SssrDesc& d) { d.farPlane = 0.0f; }}, // infinite only with reversed depth
        {"materialChannel", [](SssrDesc& d) { d.materialChannel = 4; }},
        {"importanceSampleBias", [](SssrDesc& d) { d.importanceSampleBias = 1.5f; }},
    };
    (void)nan;
    for (const Case& c : cases) {
        SssrDesc desc = validDesc();
        c.apply(desc);
        EffectPlan plan;
        std::string error;
        CHECK(planSssr(desc, plan, &error) == Result::InvalidArgument);
        INFO(error);
        CHECK(error.find(c.field) != std::string::npos);
        CHECK(error.find('\n') == std::string::npos);
    }
    SssrDesc reversedInfinite = validDesc();
    reversedInfinite.depth = DepthConvention::Reversed;
    reversedInfinite.farPlane = 0.0f;
    EffectPlan plan;
    CHECK(planSssr(reversedInfinite, plan, nullptr) == Result::Ok);
}
