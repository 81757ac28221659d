// The reflections denoiser's plan without a GPU: passes, indirect dispatch over SSSR's tile
// list, history parity, validation messages.
#include "glint/glint_reflections_denoiser.h"
#include "glint/glint_sssr.h"
#include "glint/reflections_denoiser/glint_reflections_denoiser_constants.h"

#include <catch2/catch.hpp>

#include <cstddef>
#include <cstring>
#include <limits>
#include <variant>

using namespace glint;

namespace {

ReflectionsDenoiserDesc validDesc() {
    ReflectionsDenoiserDesc desc;
    desc.size = {1919, 1081};
    desc.projection = {1.0, 0, 0, 0, 0, 1.7, 0, 0, 0, 0, -1.0001, -0.10001, 0, 0, -1, 0};
    return desc;
}

bool uses(const Pass& pass, const std::string& binding, const std::string& resource) {
    for (const ResourceUse& use : pass.uses)
        if (use.binding == binding && use.resource == resource) return true;
    return false;
}

Access accessOf(const Pass& pass, const std::string& binding) {
    for (const ResourceUse& use : pass.uses)
        if (use.binding == binding) return use.access;
    FAIL("no binding " << binding << " in " << pass.name);
    return Access::Read;
}

std::uint32_t flagsOf(const Pass& pass) {
    using shaders::GLINT_ReflectionsDenoiserConstants;
    REQUIRE(pass.constants.size() >= sizeof(GLINT_ReflectionsDenoiserConstants));
    std::uint32_t flags = 0;
    std::memcpy(&flags, pass.constants.data() + offsetof(GLINT_ReflectionsDenoiserConstants, flags),
                sizeof flags);
    return flags;
}

} // namespace

TEST_CASE("three passes over SSSR's listed tiles, histories on the frame's parity",
          "[reflections_denoiser]") {
    for (std::uint32_t frame : {0u, 1u, 6u, 7u}) {
        INFO("frame " << frame);
        ReflectionsDenoiserDesc desc = validDesc();
        desc.frameIndex = frame;
        EffectPlan plan;
        REQUIRE(planReflectionsDenoiser(desc, plan, nullptr) == Result::Ok);
        REQUIRE(plan.passes.size() == 3);
        CHECK(plan.passes[0].name == "reproject");
        CHECK(plan.passes[1].name == "prefilter");
        CHECK(plan.passes[2].name == "resolve");
        for (const Pass& pass : plan.passes) {
            const auto& indirect = std::get<IndirectDispatch>(pass.dispatch);
            CHECK(indirect.resource == "sssr_indirect_args");
            CHECK(indirect.offset == 12);
            CHECK(uses(pass, "g_glint_tile_list", "sssr_tile_list"));
        }
        const std::string now = frame % 2 ? "1" : "0", before = frame % 2 ? "0" : "1";
        CHECK(uses(plan.passes[0], "g_glint_history_radiance", "rd_radiance" + before));
        CHECK(uses(plan.passes[0], "g_glint_history_length", "rd_length" + before));
        // Last frame's variance reaches reproject in the radiance history's alpha, not through
        // its own image.
        for (const ResourceUse& use : plan.passes[0].uses) CHECK(use.resource != "rd_variance" + before);
        CHECK(uses(plan.passes[0], "g_glint_history_tile_mask", "rd_tile_mask" + before));
        CHECK(uses(plan.passes[0], "g_glint_tile_mask", "rd_tile_mask" + now));
        CHECK(plan.passes[0].zeroBuffers == std::vector<std::string>{"rd_tile_mask" + now});
        CHECK(uses(plan.passes[2], "g_glint_radiance_history", "rd_radiance" + now));
        CHECK(uses(plan.passes[2], "g_glint_output", "sssr_radiance"));
        // The resolve writes this frame's history length back after its anti-lag.
        CHECK(uses(plan.passes[2], "g_glint_length", "rd_length" + now));
        CHECK(accessOf(plan.passes[2], "g_glint_length") == Access::ReadWrite);
        CHECK(reflectionsDenoiserVariance(frame) == "rd_variance" + now);
    }
    EffectPlan plan;
    REQUIRE(planReflectionsDenoiser(validDesc(), plan, nullptr) == Result::Ok);
    for (const ImageDesc& image : plan.images)
        if (image.name == "rd_average") CHECK((image.width == 240 && image.height == 136));
}

TEST_CASE("the anti-lag is on by default and reaches the passes as a flag", "[reflections_denoiser]") {
    ReflectionsDenoiserDesc desc = validDesc();
    CHECK(desc.antiLag);
    EffectPlan plan;
    REQUIRE(planReflectionsDenoiser(desc, plan, nullptr) == Result::Ok);
    for (const Pass& pass : plan.passes) CHECK((flagsOf(pass) & GLINT_RD_FLAG_ANTI_LAG) != 0u);
    desc.antiLag = false;
    REQUIRE(planReflectionsDenoiser(desc, plan, nullptr) == Result::Ok);
    for (const Pass& pass : plan.passes) CHECK((flagsOf(pass) & GLINT_RD_FLAG_ANTI_LAG) == 0u);
}

TEST_CASE("invalid denoiser descs are refused with a message naming the field", "[reflections_denoiser]") {
    struct Case {
        const char* field;
        void (*apply)(ReflectionsDenoiserDesc&);
    };
    const Case cases[] = {
        {"size",
         [](ReflectionsDenoiserDesc& d) {
             d.size = {0, 4};
         }},
        {"historyClipScale", [](ReflectionsDenoiserDesc& d) { d.historyClipScale = 0.0f; }},
        {"maxHistoryLength", [](ReflectionsDenoiserDesc& d) { d.maxHistoryLength = 2; }},
        {"roughnessThreshold",
         [](ReflectionsDenoiserDesc& d) { d.roughnessThreshold = std::numeric_limits<float>::quiet_NaN(); }},
        {"camera matrices",
         [](ReflectionsDenoiserDesc& d) {
             d.previousClipFromWorld[0] = std::numeric_limits<double>::infinity();
         }},
        {"projection", [](ReflectionsDenoiserDesc& d) { d.projection.fill(0.0); }},
        {"reconstructionRadius", [](ReflectionsDenoiserDesc& d) { d.reconstructionRadius = 9.0f; }},
        {"reconstructionRadius",
         [](ReflectionsDenoiserDesc& d) {
             d.reconstructionRadius = std::numeric_limits<float>::quiet_NaN();
         }},
        {"cleanupSigma", [](ReflectionsDenoiserDesc& d) { d.cleanupSigma = 0.0f; }},
        {"spatialPath", [](ReflectionsDenoiserDesc& d) { d.spatialPath = static_cast<SpatialPath>(7); }},
    };
    for (const Case& c : cases) {
        ReflectionsDenoiserDesc desc = validDesc();
        c.apply(desc);
        EffectPlan plan;
        std::string error;
        CHECK(planReflectionsDenoiser(desc, plan, &error) == Result::InvalidArgument);
        INFO(error);
        CHECK(error.find(c.field) != std::string::npos);
    }
}

TEST_CASE("the ratio-estimator path: reconstruct instead of prefilter, cleanup after resolve, SSSR's rays in",
          "[reflections_denoiser]") {
    for (std::uint32_t frame : {0u, 1u}) {
        INFO("frame " << frame);
        ReflectionsDenoiserDesc desc = validDesc();
        desc.frameIndex = frame;
        desc.spatialPath = SpatialPath::RatioEstimator;
        EffectPlan plan;
        REQUIRE(planReflectionsDenoiser(desc, plan, nullptr) == Result::Ok);
        REQUIRE(plan.passes.size() == 4);
        CHECK(plan.passes[0].name == "reproject");
        CHECK(plan.passes[1].name == "reconstruct");
        CHECK(plan.passes[2].name == "resolve");
        CHECK(plan.passes[3].name == "cleanup");
        const std::string now = frame % 2 ? "1" : "0";
        CHECK(uses(plan.passes[1], "g_glint_rays", "sssr_rays"));
        CHECK(uses(plan.passes[1], "g_glint_clamped", "rd_clamped"));
        CHECK(uses(plan.passes[1], "g_glint_variance", "rd_variance" + now));
        CHECK(uses(plan.passes[1], "g_glint_reconstructed", "rd_prefiltered"));
        CHECK(uses(plan.passes[2], "g_glint_prefiltered", "rd_prefiltered"));
        CHECK(uses(plan.passes[3], "g_glint_resolved", "rd_radiance" + now));
        CHECK(uses(plan.passes[3], "g_glint_output", "sssr_radiance"));
        for (const Pass& pass : plan.passes) {
            const auto& indirect = std::get<IndirectDispatch>(pass.dispatch);
            CHECK(indirect.offset == 12);
        }
        // The ratio passes carry the larger constants (common + rotation + path parameters).
        CHECK(plan.passes[1].constants.size() == 272);
        CHECK(plan.passes[0].constants.size() == 208);
        // No resource beyond the default path's: the reconstruction reuses the prefilter's image.
        EffectPlan defaults;
        desc.spatialPath = SpatialPath::Prefilter;
        REQUIRE(planReflectionsDenoiser(desc, defaults, nullptr) == Result::Ok);
        CHECK(defaults.images.size() == plan.images.size());
        CHECK(defaults.buffers.size() == plan.buffers.size());
    }
    ReflectionsDenoiserDesc half = validDesc();
    half.spatialPath = SpatialPath::RatioEstimator;
    half.halfPrecisionStorage = true;
    EffectPlan plan;
    REQUIRE(planReflectionsDenoiser(half, plan, nullptr) == Result::Ok);
    CHECK(plan.passes[1].pipeline == "rd_reconstruct.half");
    CHECK(plan.passes[3].pipeline == "rd_cleanup.half");
}

TEST_CASE("SSSR stores its rays only when asked, in a permutation of the intersection",
          "[reflections_denoiser]") {
    SssrDesc desc;
    desc.halfPrecisionStorage = false; // 32-bit first, then the 16-bit permutation
    desc.size = {64, 32};
    EffectPlan plan;
    REQUIRE(planSssr(desc, plan, nullptr) == Result::Ok);
    auto intersect = [](const EffectPlan& p) {
        for (const Pass& pass : p.passes)
            if (pass.name == "intersect") return pass;
        return Pass{};
    };
    CHECK(intersect(plan).pipeline == "sssr_intersect");
    for (const ImageDesc& image : plan.images) CHECK(image.name != "sssr_rays");
    desc.storeRays = true;
    desc.halfPrecisionStorage = true;
    REQUIRE(planSssr(desc, plan, nullptr) == Result::Ok);
    CHECK(intersect(plan).pipeline == "sssr_intersect.ray_half");
    CHECK(uses(intersect(plan), "g_glint_rays", "sssr_rays"));
    bool found = false;
    for (const ImageDesc& image : plan.images)
        if (image.name == "sssr_rays") found = image.format == Format::RGBA16Float;
    CHECK(found);
    desc.thicknessAware = true;
    desc.debugOutput = true;
    REQUIRE(planSssr(desc, plan, nullptr) == Result::Ok);
    CHECK(intersect(plan).pipeline == "sssr_intersect.thick_debug_ray_half");
}
