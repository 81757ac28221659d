// The shadow denoiser plan and the CPU packer's bit layout.
#include "core/shader_library.h"
#include "reference/shadow_denoiser_reference.h"

#include "glint/glint_shadow_denoiser.h"
#include "glint/shadow_denoiser/glint_shadow_denoiser_constants.h"

#include <catch2/catch.hpp>

#include <array>
#include <cstddef>
#include <cstring>
#include <iterator>
#include <limits>
#include <string>
#include <utility>
#include <vector>

using namespace glint;

TEST_CASE("shadow plan: passes, resources and sizes", "[plan]") {
    ShadowDenoiserDesc desc;
    desc.size = {13, 7};
    EffectPlan plan;
    std::string error;
    REQUIRE(planShadowDenoiser(desc, plan, &error) == Result::Ok);
    // One classification dispatch (every binding of the pass): sizes, buffers, the frame parity.
    desc.splitClassify = false;
    REQUIRE(planShadowDenoiser(desc, plan, &error) == Result::Ok);
    REQUIRE(plan.passes.size() == 4);
    CHECK(plan.passes[0].name == "prepare");
    CHECK(plan.passes[1].name == "classify");
    CHECK(plan.passes[2].name == "filter01");
    CHECK(std::get<DirectDispatch>(plan.passes[0].dispatch).groupsX == 1);
    CHECK(std::get<DirectDispatch>(plan.passes[1].dispatch).groupsX == 2);
    CHECK(std::get<DirectDispatch>(plan.passes[1].dispatch).groupsY == 1);
    REQUIRE(plan.buffers.size() == 6);
    CHECK(plan.buffers[0].name == "shadow_mask");
    CHECK(plan.buffers[0].size == 2 * 2 * 4);
    CHECK(plan.buffers[1].name == "shadow_tile_metadata0");
    CHECK(plan.buffers[1].size == 2 * 1 * 4);
    CHECK(plan.buffers[2].name == "shadow_tile_metadata1");
    CHECK(plan.buffers[3].name == "shadow_filter_work");
    // Moments and metadata ping-pong on the frame parity; the filter reads this frame's.
    CHECK(plan.passes[1].uses[9].resource == "shadow_moments0");
    CHECK(plan.passes[1].uses[6].resource == "shadow_tile_metadata1");
    CHECK(plan.passes[1].uses[7].resource == "shadow_tile_metadata0");
    CHECK(plan.passes[2].uses[4].resource == "shadow_tile_metadata0");
    desc.frameIndex = 1;
    REQUIRE(planShadowDenoiser(desc, plan, &error) == Result::Ok);
    CHECK(plan.passes[1].uses[9].resource == "shadow_moments1");
    CHECK(plan.passes[1].uses[5].resource == "shadow_moments0");
    CHECK(plan.passes[1].uses[6].resource == "shadow_tile_metadata0");
    CHECK(plan.passes[1].uses[7].resource == "shadow_tile_metadata1");
    CHECK(plan.passes[2].uses[4].resource == "shadow_tile_metadata1");
    desc.frameIndex = 0;
    CHECK(shadowMaskTiles({1917, 1077}).width == 240);
    CHECK(shadowMaskTiles({1917, 1077}).height == 270);

    const auto classifyFlags = [&] {
        using Constants = shaders::GLINT_ShadowDenoiserClassifyConstants;
        REQUIRE(plan.passes[1].constants.size() == sizeof(Constants));
        std::uint32_t flags = 0;
        std::memcpy(&flags, plan.passes[1].constants.data() + offsetof(Constants, flags), 4);
        return flags;
    };
    constexpr std::uint32_t kDefaults =
        GLINT_SHADOW_DENOISER_CLASSIFY_FLAG_ANTI_LAG | GLINT_SHADOW_DENOISER_CLASSIFY_FLAG_REBUILD_CLEAR;
    CHECK(classifyFlags() == kDefaults);

    // The default: classification in two parts ("classify" over every tile, 2x2 tiles a
    // group; "temporal" indirect over the tiles it lists), then "filter01" (steps 1 and 2) and
    // "filter2", indirect over the same list (prepare resets it).
    desc.splitClassify = true;
    REQUIRE(planShadowDenoiser(desc, plan, &error) == Result::Ok);
    REQUIRE(plan.passes.size() == 5);
    CHECK(plan.passes[0].pipeline == "shadow_denoiser_prepare.list");
    CHECK(plan.passes[1].name == "classify");
    CHECK(plan.passes[1].pipeline == "shadow_denoiser_classify.tiles_r8");
    CHECK(plan.passes[1].groupSize[2] == GLINT_SHADOW_DENOISER_CLASSIFY_TILE_BLOCKS);
    CHECK(std::get<DirectDispatch>(plan.passes[1].dispatch).groupsX == 1);
    CHECK(std::get<DirectDispatch>(plan.passes[1].dispatch).groupsY == 1);
    CHECK(plan.passes[2].name == "temporal");
    CHECK(plan.passes[2].pipeline == "shadow_denoiser_classify.listed");
    CHECK(std::get<IndirectDispatch>(plan.passes[2].dispatch).resource == "shadow_filter_args");
    CHECK(plan.passes[3].name == "filter01");
    CHECK(plan.passes[3].pipeline == "shadow_denoiser_filter.pair_list");
    CHECK(plan.passes[3].zeroBuffers == std::vector<std::string>{"shadow_filter_work"});
    CHECK(std::get<IndirectDispatch>(plan.passes[3].dispatch).resource == "shadow_filter_args");
    CHECK(plan.passes[4].name == "filter2");
    CHECK(plan.passes[4].pipeline == "shadow_denoiser_filter.list_r8");
    // Each part binds only what it reads or writes; the temporal part writes the moments.
    const auto binds = [](const Pass& pass, const std::string& binding) {
        for (const ResourceUse& use : pass.uses)
            if (use.binding == binding) return true;
        return false;
    };
    CHECK(binds(plan.passes[1], "g_glint_filter_args"));
    CHECK_FALSE(binds(plan.passes[1], "g_glint_motion"));
    CHECK(binds(plan.passes[2], "g_glint_motion"));
    CHECK_FALSE(binds(plan.passes[2], "g_glint_filter_args"));
    // One classification dispatch and three filter dispatches when asked.
    desc.splitClassify = false;
    desc.pairedFilter = false;
    REQUIRE(planShadowDenoiser(desc, plan, &error) == Result::Ok);
    REQUIRE(plan.passes.size() == 5);
    CHECK(plan.passes[1].pipeline == "shadow_denoiser_classify.list_r8");
    CHECK(std::get<DirectDispatch>(plan.passes[1].dispatch).groupsX == 2);
    CHECK(plan.passes[2].name == "filter0");
    CHECK(plan.passes[4].name == "filter2");
    CHECK(plan.passes[2].pipeline == "shadow_denoiser_filter.list");
    CHECK(plan.passes[2].zeroBuffers == std::vector<std::string>{"shadow_filter_work"});
    CHECK(std::get<IndirectDispatch>(plan.passes[2].dispatch).resource == "shadow_filter_args");
    REQUIRE(plan.buffers.size() == 6);
    CHECK(plan.buffers[4].name == "shadow_filter_tiles");
    CHECK(plan.buffers[4].size == 2 * 1 * 4);
    CHECK(plan.buffers[5].name == "shadow_filter_args");
    CHECK(plan.buffers[5].indirectArgs);
    CHECK(plan.images.size() == 5);
    CHECK(classifyFlags() == kDefaults);
    // Without tile skipping: a direct grid over every tile, no list.
    desc.skipClearedTiles = false;
    REQUIRE(planShadowDenoiser(desc, plan, &error) == Result::Ok);
    CHECK(plan.passes[0].pipeline == "shadow_denoiser_prepare");
    CHECK(plan.passes[2].pipeline == "shadow_denoiser_filter");
    CHECK(std::get<DirectDispatch>(plan.passes[2].dispatch).groupsX == 2);
    desc.pairedFilter = true;
    REQUIRE(planShadowDenoiser(desc, plan, &error) == Result::Ok);
    REQUIRE(plan.passes.size() == 4);
    CHECK(plan.passes[2].pipeline == "shadow_denoiser_filter.pair");
    CHECK(std::get<DirectDispatch>(plan.passes[2].dispatch).groupsX == 2);
    desc.skipClearedTiles = true;
    desc.resetHistory = true;
    REQUIRE(planShadowDenoiser(desc, plan, &error) == Result::Ok);
    CHECK(classifyFlags() == (GLINT_SHADOW_DENOISER_CLASSIFY_FLAG_RESET | kDefaults));
    desc.resetHistory = false;
    desc.antiLag = false;
    desc.rebuildClearHistory = false;
    REQUIRE(planShadowDenoiser(desc, plan, &error) == Result::Ok);
    CHECK(classifyFlags() == 0u);
    desc.antiLag = true;
    desc.rebuildClearHistory = true;

    desc.filter = false;
    desc.classify = false;
    REQUIRE(planShadowDenoiser(desc, plan, &error) == Result::Ok);
    CHECK(plan.passes.size() == 1);
    CHECK(plan.images.empty());
}

namespace {

const Pass* findPass(const EffectPlan& plan, const std::string& name) {
    for (const Pass& pass : plan.passes)
        if (pass.name == name) return &pass;
    return nullptr;
}

const ImageDesc* findImage(const EffectPlan& plan, const std::string& name) {
    for (const ImageDesc& image : plan.images)
        if (image.name == name) return &image;
    return nullptr;
}

// A pass of a plan variant and its pipeline per output format (RG32F, R16F, R8): the same
// for passes that do not write "shadow_output".
struct ExpectedPass {
    const char* name;
    std::array<const char*, 3> pipelines;
    bool writesOutput() const { return std::string(pipelines[0]) != pipelines[2]; }
};

ExpectedPass scratchPass(const char* name, const char* pipeline) {
    return {name, {pipeline, pipeline, pipeline}};
}

struct PlanVariant {
    const char* what;
    struct {
        bool classify, skipClearedTiles, splitClassify, pairedFilter;
    } flags;
    std::vector<ExpectedPass> passes; // after "prepare"
};

} // namespace

TEST_CASE("shadow plan: the output format picks the final output's format and permutations", "[plan]") {
    ShadowDenoiserDesc desc;
    desc.size = {53, 37};
    EffectPlan plan;
    std::string error;
    // The default: one 8-bit channel.
    REQUIRE(planShadowDenoiser(desc, plan, &error) == Result::Ok);
    REQUIRE(findImage(plan, "shadow_output") != nullptr);
    CHECK(findImage(plan, "shadow_output")->format == Format::R8Unorm);
    CHECK(findPass(plan, "classify")->pipeline == "shadow_denoiser_classify.tiles_r8");
    CHECK(findPass(plan, "temporal")->pipeline == "shadow_denoiser_classify.listed");
    CHECK(findPass(plan, "filter01")->pipeline == "shadow_denoiser_filter.pair_list");
    CHECK(findPass(plan, "filter2")->pipeline == "shadow_denoiser_filter.list_r8");

    const ExpectedPass listFilter2{"filter2",
                                   {"shadow_denoiser_filter.list", "shadow_denoiser_filter.list_r16f",
                                    "shadow_denoiser_filter.list_r8"}};
    const ExpectedPass plainFilter2{
        "filter2", {"shadow_denoiser_filter", "shadow_denoiser_filter.r16f", "shadow_denoiser_filter.r8"}};
    const ExpectedPass plainClassify = scratchPass("classify", "shadow_denoiser_classify");
    const std::vector<PlanVariant> variants = {
        {"default",
         {true, true, true, true},
         {{"classify",
           {"shadow_denoiser_classify.tiles", "shadow_denoiser_classify.tiles_r16f",
            "shadow_denoiser_classify.tiles_r8"}},
          scratchPass("temporal", "shadow_denoiser_classify.listed"),
          scratchPass("filter01", "shadow_denoiser_filter.pair_list"),
          listFilter2}},
        {"one classification dispatch, three filter dispatches",
         {true, true, false, false},
         {{"classify",
           {"shadow_denoiser_classify.list", "shadow_denoiser_classify.list_r16f",
            "shadow_denoiser_classify.list_r8"}},
          scratchPass("filter0", "shadow_denoiser_filter.list"),
          scratchPass("filter1", "shadow_denoiser_filter.list"),
          listFilter2}},
        {"paired without tile skipping",
         {true, false, true, true},
         {plainClassify, scratchPass("filter01", "shadow_denoiser_filter.pair"), plainFilter2}},
        {"three filter dispatches without classification",
         {false, true, true, false},
         {scratchPass("filter0", "shadow_denoiser_filter"), scratchPass("filter1", "shadow_denoiser_filter"),
          plainFilter2}},
    };
    const Format formats[] = {Format::RG32Float, Format::R16Float, Format::R8Unorm};
    for (std::size_t f = 0; f < std::size(formats); ++f)
        for (const PlanVariant& variant : variants) {
            INFO(variant.what << ", format " << f);
            desc.outputFormat = formats[f];
            desc.classify = variant.flags.classify;
            desc.skipClearedTiles = variant.flags.skipClearedTiles;
            desc.splitClassify = variant.flags.splitClassify;
            desc.pairedFilter = variant.flags.pairedFilter;
            REQUIRE(planShadowDenoiser(desc, plan, &error) == Result::Ok);
            REQUIRE(findImage(plan, "shadow_output") != nullptr);
            CHECK(findImage(plan, "shadow_output")->format == formats[f]);
            // Only the final output changes: the scratch images stay (shadow, variance).
            for (const char* scratch : {"shadow_scratch0", "shadow_scratch1"})
                if (const ImageDesc* image = findImage(plan, scratch))
                    CHECK(image->format == Format::RG32Float);
            CHECK(plan.passes.size() == 1 + variant.passes.size());
            for (const ExpectedPass& expected : variant.passes) {
                const Pass* pass = findPass(plan, expected.name);
                REQUIRE(pass != nullptr);
                CHECK(pass->pipeline == expected.pipelines[f]);
                CHECK_FALSE(core::findShader(pass->pipeline).empty()); // the permutation is built
                bool writesOutput = false;
                for (const ResourceUse& use : pass->uses) writesOutput |= use.resource == "shadow_output";
                CHECK(writesOutput == expected.writesOutput());
            }
        }
    // Without the filter there is no output image to format.
    desc.filter = false;
    desc.classify = true;
    REQUIRE(planShadowDenoiser(desc, plan, &error) == Result::Ok);
    CHECK(findImage(plan, "shadow_output") == nullptr);
    CHECK(findPass(plan, "classify")->pipeline == "shadow_denoiser_classify");
}

TEST_CASE("shadow plan: an unsupported output format is refused", "[plan]") {
    ShadowDenoiserDesc desc;
    desc.size = {16, 16};
    EffectPlan plan;
    for (Format format :
         {Format::RGBA32Float, Format::R32Float, Format::RG16Float, Format::RGBA8Unorm, Format::R32Uint}) {
        desc.outputFormat = format;
        std::string error;
        CHECK(planShadowDenoiser(desc, plan, &error) == Result::InvalidArgument);
        CHECK(error.find("shadow denoiser") == 0);
        CHECK(error.find("outputFormat") != std::string::npos);
        CHECK(error.find('\n') == std::string::npos);
    }
}

TEST_CASE("shadow plan: invalid descriptions are refused", "[plan]") {
    EffectPlan plan;
    std::string error;
    ShadowDenoiserDesc desc;
    desc.size = {0, 4};
    CHECK(planShadowDenoiser(desc, plan, &error) == Result::InvalidArgument);
    desc.size = {16385, 4};
    CHECK(planShadowDenoiser(desc, plan, &error) == Result::InvalidArgument);
    desc.size = {4, 4};
    desc.depthSigma = 0.0f;
    CHECK(planShadowDenoiser(desc, plan, &error) == Result::InvalidArgument);
    desc.depthSigma = 0.02f;
    desc.farPlane = desc.nearPlane;
    CHECK(planShadowDenoiser(desc, plan, &error) == Result::InvalidArgument);
    desc.depth = ShadowDenoiserDepth::Reversed;
    desc.farPlane = 0.0f; // infinite
    CHECK(planShadowDenoiser(desc, plan, &error) == Result::Ok);
    desc.normalPower = std::numeric_limits<float>::quiet_NaN();
    CHECK(planShadowDenoiser(desc, plan, &error) == Result::InvalidArgument);
    CHECK(error.find("shadow denoiser") == 0);
    desc.normalPower = 32.0f;
    desc.storedVarianceScale = -1.0f;
    CHECK(planShadowDenoiser(desc, plan, &error) == Result::InvalidArgument);
    CHECK(error.find("storedVarianceScale") != std::string::npos);
    desc.storedVarianceScale = std::numeric_limits<float>::infinity();
    CHECK(planShadowDenoiser(desc, plan, &error) == Result::InvalidArgument);
}

// The penumbra estimate (docs/shadow_denoiser.md, "Penumbra-aware filtering", "Hard shadows
// pass through"): with penumbraAware and both sizes known, classification and the filter get
// penumbraScale = 2 tan / pixel angle (0 for a light of size 0), otherwise -1 (no estimate); they
// read "shadow_blocker_distance" only for a light of positive size, the depth stands in otherwise.
TEST_CASE("shadow plan: the penumbra estimate needs the light's and a pixel's angular size", "[plan]") {
    ShadowDenoiserDesc desc;
    desc.size = {64, 48};
    const auto estimate = [&](float expectedScale, const char* expectedImage) {
        EffectPlan plan;
        std::string error;
        REQUIRE(planShadowDenoiser(desc, plan, &error) == Result::Ok);
        std::size_t filters = 0, temporal = 0;
        for (const Pass& pass : plan.passes) {
            std::string bound;
            for (const ResourceUse& use : pass.uses)
                if (use.binding == "g_glint_blocker_distance") bound = use.resource;
            INFO(pass.name);
            if (pass.name.rfind("filter", 0) == 0) {
                ++filters;
                shaders::GLINT_ShadowDenoiserFilterConstants constants{};
                REQUIRE(pass.constants.size() == sizeof(constants));
                std::memcpy(&constants, pass.constants.data(), sizeof(constants));
                CHECK(constants.penumbraScale == Approx(expectedScale).epsilon(1e-6));
                CHECK(bound == expectedImage);
            } else if (pass.name == "temporal") {
                ++temporal;
                shaders::GLINT_ShadowDenoiserClassifyConstants constants{};
                REQUIRE(pass.constants.size() == sizeof(constants));
                std::memcpy(&constants, pass.constants.data(), sizeof(constants));
                CHECK(constants.penumbraScale == Approx(expectedScale).epsilon(1e-6));
                CHECK(bound == expectedImage);
            } else {
                CHECK(bound.empty()); // prepare and the tile test read no blocker
            }
        }
        CHECK(filters == 2u);
        CHECK(temporal == 1u);
    };
    estimate(-1.0f, "shadow_depth"); // both sizes unknown
    desc.lightTanHalfAngle = 0.05f;
    estimate(-1.0f, "shadow_depth"); // the pixel's unknown
    desc.pixelAngularSize = 0.01f;
    estimate(10.0f, "shadow_blocker_distance"); // 2 * 0.05 / 0.01
    desc.lightTanHalfAngle = 0.0f;
    estimate(0.0f, "shadow_depth"); // a light of size 0: every shadow hard, no blocker read
    desc.lightTanHalfAngle = -0.5f;
    estimate(-1.0f, "shadow_depth"); // negative: unknown
    desc.lightTanHalfAngle = 0.05f;
    desc.penumbraAware = false;
    estimate(-1.0f, "shadow_depth");
    desc.penumbraAware = true;
    desc.pixelAngularSize = -1.0f;
    EffectPlan plan;
    std::string error;
    CHECK(planShadowDenoiser(desc, plan, &error) == Result::InvalidArgument);
    CHECK(error.find("pixelAngularSize") != std::string::npos);
    desc.pixelAngularSize = 0.01f;
    desc.lightTanHalfAngle = std::numeric_limits<float>::quiet_NaN();
    CHECK(planShadowDenoiser(desc, plan, &error) == Result::InvalidArgument);
    CHECK(error.find("lightTanHalfAngle") != std::string::npos);
}

// The automatic stored variance scale: 1/16 up to 360 rows, (rows / 360)^2 / 16 above; an
// explicit value wins; the classify constants carry it in their own field.
TEST_CASE("shadow plan: the stored variance scale follows the image height", "[plan]") {
    ShadowDenoiserDesc desc;
    desc.size = {160, 90};
    CHECK(shadowStoredVarianceScale(desc) == 0.0625f);
    desc.size = {640, 360};
    CHECK(shadowStoredVarianceScale(desc) == 0.0625f);
    desc.size = {1920, 1080};
    CHECK(shadowStoredVarianceScale(desc) == Approx(0.5625f));
    desc.size = {3840, 2160};
    CHECK(shadowStoredVarianceScale(desc) == Approx(2.25f));
    desc.storedVarianceScale = 0.25f;
    CHECK(shadowStoredVarianceScale(desc) == 0.25f);
    EffectPlan plan;
    std::string error;
    REQUIRE(planShadowDenoiser(desc, plan, &error) == Result::Ok);
    shaders::GLINT_ShadowDenoiserClassifyConstants constants{};
    REQUIRE(plan.passes[1].name == "classify");
    REQUIRE(plan.passes[1].constants.size() == sizeof(constants));
    std::memcpy(&constants, plan.passes[1].constants.data(), sizeof(constants));
    CHECK(constants.storedVarianceScale == 0.25f);
    CHECK(constants.eyePosition.w == 0.0f);
}

TEST_CASE("shadow mask layout: one byte per row, leftmost pixel in bit 0, edges clamp", "[reference]") {
    // 9 x 5: tiles 2 x 2. Only pixel (8, 4) is lit: it is the whole in-image part of tile
    // (1, 1), so every bit of that tile repeats it; tile (1, 0) has column 8 of rows 0-3.
    std::vector<float> visibility(9 * 5, 0.0f);
    visibility[4 * 9 + 8] = 1.0f;
    std::vector<std::uint32_t> mask = reference::packShadowMask(visibility, 9, 5);
    REQUIRE(mask.size() == 4);
    CHECK(mask[0] == 0u);
    CHECK(mask[1] == 0u);
    CHECK(mask[2] == 0u);
    CHECK(mask[3] == 0xFFFFFFFFu);
    visibility.assign(9 * 5, 0.0f);
    visibility[1 * 9 + 2] = 1.0f; // (2, 1): bit 8 + 2
    mask = reference::packShadowMask(visibility, 9, 5);
    CHECK(mask[0] == (1u << 10));
}
