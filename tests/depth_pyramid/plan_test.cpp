// depthPyramidLayout and planDepthPyramid against the header's contract: sizes, level counts,
// the resources a plan asks for, and the one level count shared by image and constants.
#include "core/pass_model.h"
#include "core/shader_library.h"
#include "glint/depth_pyramid/glint_depth_pyramid_constants.h"
#include "glint/glint_depth_pyramid.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <set>

using namespace glint;

namespace {

struct LayoutCase {
    std::uint32_t width, height, w0, h0, full;
};

EffectPlan planFor(std::uint32_t width, std::uint32_t height, std::uint32_t levels,
                   DepthPyramidChannels channels = DepthPyramidChannels::Closest,
                   DepthConvention depth = DepthConvention::Standard) {
    DepthPyramidDesc desc;
    desc.size = {width, height};
    desc.levelCount = levels;
    desc.channels = channels;
    desc.depth = depth;
    EffectPlan plan;
    std::string error;
    INFO(width << "x" << height << " levels " << levels << ": " << error);
    REQUIRE(planDepthPyramid(desc, plan, &error) == Result::Ok);
    return plan;
}

const BufferDesc* findBuffer(const EffectPlan& plan, const std::string& name) {
    for (const BufferDesc& buffer : plan.buffers)
        if (buffer.name == name) return &buffer;
    return nullptr;
}

shaders::GLINT_DepthPyramidConstants constantsOf(const Pass& pass) {
    shaders::GLINT_DepthPyramidConstants constants{};
    REQUIRE(pass.constants.size() == sizeof constants);
    std::memcpy(&constants, pass.constants.data(), sizeof constants);
    return constants;
}

} // namespace

TEST_CASE("the layout pads level 0 to multiples of 64 and counts the full chain from it", "[layout]") {
    const LayoutCase cases[] = {
        {1, 1, 64, 64, 7},
        {1, 37, 64, 64, 7},
        {53, 1, 64, 64, 7},
        {7, 3, 64, 64, 7},
        {7, 4, 64, 64, 7},
        {64, 64, 64, 64, 7},
        {65, 1, 128, 64, 8},
        {128, 32, 128, 64, 8},
        {1917, 1077, 1920, 1088, 11},
        {1920, 1080, 1920, 1088, 11},
        {3840, 2160, 3840, 2176, 12},
        {16383, 5, 16384, 64, 15},
        {16384, 16384, 16384, 16384, 15},
    };
    for (const LayoutCase& c : cases) {
        INFO(c.width << "x" << c.height);
        const DepthPyramidLayout layout = depthPyramidLayout({c.width, c.height}, 0);
        CHECK(layout.level0.width == c.w0);
        CHECK(layout.level0.height == c.h0);
        CHECK(layout.fullLevelCount == c.full);
        CHECK(layout.levelCount == c.full);
        CHECK(depthPyramidLayout({c.width, c.height}, 3).levelCount == 3);
        CHECK(depthPyramidLayout({c.width, c.height}, c.full).levelCount == c.full);
    }
}

TEST_CASE("the plan's image is the padded level 0 with exactly the levels built", "[plan]") {
    const EffectPlan plan = planFor(1920, 1080, 0);
    CHECK(core::validatePlan(plan).empty());
    REQUIRE(plan.images.size() == 1);
    const ImageDesc& image = plan.images[0];
    CHECK(image.name == "depth_pyramid");
    CHECK(image.width == 1920);
    CHECK(image.height == 1088);
    CHECK(image.mipLevels == 11);
    CHECK(image.format == Format::R32Float);
    CHECK(planFor(1920, 1080, 0, DepthPyramidChannels::ClosestAndFarthest).images[0].format ==
          Format::RG32Float);
    CHECK(planFor(1920, 1080, 5).images[0].mipLevels == 5);
    CHECK(planFor(1, 1, 0).images[0].mipLevels == 7);
}

TEST_CASE("one pass of 256-thread groups covers level 0 in 64x64 tiles", "[plan]") {
    const EffectPlan plan = planFor(1917, 1077, 0);
    REQUIRE(plan.passes.size() == 1);
    const Pass& pass = plan.passes[0];
    CHECK(pass.groupSize[0] * pass.groupSize[1] * pass.groupSize[2] == 256);
    REQUIRE(std::holds_alternative<DirectDispatch>(pass.dispatch));
    const DirectDispatch grid = std::get<DirectDispatch>(pass.dispatch);
    CHECK(grid.groupsX == 1920 / 64);
    CHECK(grid.groupsY == 1088 / 64);
    CHECK(grid.groupsZ == 1);

    bool readsDepth = false, writesPyramid = false;
    for (const ResourceUse& use : pass.uses) {
        if (use.resource == "depth") readsDepth = use.access == Access::Read;
        if (use.resource == "depth_pyramid")
            writesPyramid = use.access == Access::Write || use.access == Access::ReadWrite;
    }
    CHECK(readsDepth);
    CHECK(writesPyramid);
}

TEST_CASE("image and constants share one level count and describe the same layout", "[plan]") {
    // docs/conventions.md, defects DP1 and DP5: the shader built more levels than were allocated.
    for (const std::uint32_t levels : {0u, 1u, 3u, 7u, 8u, 11u}) {
        INFO("levelCount " << levels);
        const EffectPlan plan =
            planFor(1917, 1077, levels, DepthPyramidChannels::Closest, DepthConvention::Reversed);
        const auto constants = constantsOf(plan.passes[0]);
        const DirectDispatch grid = std::get<DirectDispatch>(plan.passes[0].dispatch);
        CHECK(constants.levelCount == plan.images[0].mipLevels);
        CHECK(constants.levelCount == (levels == 0 ? 11u : levels));
        CHECK(constants.inputSize.x == 1917);
        CHECK(constants.inputSize.y == 1077);
        CHECK(constants.level0Size.x == 1920);
        CHECK(constants.level0Size.y == 1088);
        CHECK(constants.groupCount == grid.groupsX * grid.groupsY * grid.groupsZ);
        CHECK(constants.farDepth == 0.0f);
        CHECK(constants.levelCount <= GLINT_DEPTH_PYRAMID_MAX_LEVELS);
    }
    CHECK(constantsOf(planFor(8, 8, 0).passes[0]).farDepth == 1.0f);
}

TEST_CASE("the level-0 copy is on by default and can be left out", "[plan]") {
    CHECK(constantsOf(planFor(300, 200, 0).passes[0]).writeLevel0 == 1u);
    DepthPyramidDesc desc;
    desc.size = {300, 200};
    desc.copyLevel0 = false;
    EffectPlan plan;
    REQUIRE(planDepthPyramid(desc, plan, nullptr) == Result::Ok);
    CHECK(constantsOf(plan.passes[0]).writeLevel0 == 0u);
    // Level 0 is still allocated at W0 x H0, so level k keeps its size W0 >> k.
    CHECK(plan.images[0].width == 320);
    CHECK(plan.images[0].height == 256);
    CHECK(plan.images[0].mipLevels == 9);
}

TEST_CASE("the completion counter is always bound and zeroed only when levels above 6 are built", "[plan]") {
    // The entry binds the counter in every permutation, so the plan always lists it; only the
    // last-group pattern (levelCount > 7) uses it, and only then does the plan clear it.
    for (const std::uint32_t levels : {1u, 3u, 7u, 8u, 11u, 0u}) {
        INFO("levelCount " << levels);
        const EffectPlan plan = planFor(1920, 1080, levels);
        const BufferDesc* counter = findBuffer(plan, "depth_pyramid_counter");
        REQUIRE(counter != nullptr);
        CHECK(counter->size >= 4);
        bool counterIsAtomic = false;
        for (const ResourceUse& use : plan.passes[0].uses)
            if (use.resource == "depth_pyramid_counter") counterIsAtomic = use.access == Access::ReadWrite;
        CHECK(counterIsAtomic);
        const auto& zeroed = plan.passes[0].zeroBuffers;
        const bool usesCounter = levels == 0 || levels > 7;
        CHECK((std::find(zeroed.begin(), zeroed.end(), "depth_pyramid_counter") != zeroed.end()) ==
              usesCounter);
    }
    // A 64x64 level 0 has exactly 7 levels: no coarse levels, nothing to clear.
    CHECK(planFor(7, 3, 0).passes[0].zeroBuffers.empty());
}

TEST_CASE("each convention and channel choice has its own embedded pipeline", "[plan]") {
    std::set<std::string> pipelines;
    for (const auto depth : {DepthConvention::Standard, DepthConvention::Reversed})
        for (const auto channels :
             {DepthPyramidChannels::Closest, DepthPyramidChannels::ClosestAndFarthest}) {
            const std::string name = planFor(100, 100, 0, channels, depth).passes[0].pipeline;
            INFO(name);
            CHECK_FALSE(core::findShader(name).empty());
            pipelines.insert(name);
        }
    CHECK(pipelines.size() == 4);
}

TEST_CASE("planDepthPyramid rejects sizes out of range and more levels than the full chain", "[plan]") {
    DepthPyramidDesc desc;
    EffectPlan plan;
    std::string error;
    for (const Extent2D size :
         {Extent2D{0, 4}, Extent2D{4, 0}, Extent2D{16385, 4}, Extent2D{4, 16385}, Extent2D{16385, 16385}}) {
        INFO(size.width << "x" << size.height);
        desc.size = size;
        error.clear();
        CHECK(planDepthPyramid(desc, plan, &error) == Result::InvalidArgument);
        CHECK_THAT(error, Catch::Contains("size"));
    }
    desc.size = {16384, 16384};
    CHECK(planDepthPyramid(desc, plan, &error) == Result::Ok);
    CHECK(plan.images[0].mipLevels == 15);

    desc.size = {1920, 1080};
    desc.levelCount = 12;
    error.clear();
    CHECK(planDepthPyramid(desc, plan, &error) == Result::InvalidArgument);
    CHECK_THAT(error, Catch::Contains("levelCount"));
    desc.levelCount = 11;
    CHECK(planDepthPyramid(desc, plan, &error) == Result::Ok);
    desc.size = {7, 3};
    desc.levelCount = 8;
    CHECK(planDepthPyramid(desc, plan, &error) == Result::InvalidArgument);
    desc.levelCount = 7;
    CHECK(planDepthPyramid(desc, plan, &error) == Result::Ok);
    desc.levelCount = 1;
    CHECK(planDepthPyramid(desc, plan, &error) == Result::Ok);
    CHECK(plan.images[0].mipLevels == 1);
}
