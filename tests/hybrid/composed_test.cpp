// The composed hybrid effect (planHybridReflections): SSSR-first tracing, ray tracing, the
// reflections denoiser and the composite in one plan over several frames, with NaN and Inf in
// the inputs, the feedback history and the denoiser's histories on one frame. Every output
// stays finite on every frame; the denoiser runs on the hybrid tiles.
#include "hybrid/hybrid_test_frame.h"
#include "support/gpu_test_context.h"

#include <gpu/gpu_effect_runner.h>
#include <gpu/gpu_transfer.h>
#include <scene/scene_shaders.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace glint;

namespace {

shaders::float3 point(float x, float y, float z) {
    return {x, y, z};
}

// The hybrid with the denoiser and the composite, and the denoiser's desc, for the view.
HybridDesc denoisedHybrid(const test::SssrTestView& view) {
    HybridDesc desc;
    desc.sssr = view.desc;
    desc.sssr.denoise = true;
    desc.sssr.composite = true;
    return desc;
}

ReflectionsDenoiserDesc denoiserFor(const test::SssrTestView& view) {
    ReflectionsDenoiserDesc denoiser;
    denoiser.halfPrecisionStorage = view.desc.halfPrecisionStorage;
    denoiser.size = view.desc.size;
    denoiser.projection = view.desc.projection;
    denoiser.viewFromWorld = view.desc.viewFromWorld;
    denoiser.previousClipFromWorld = view.desc.projection;
    denoiser.depth = view.desc.depth;
    denoiser.nearPlane = view.desc.nearPlane;
    denoiser.farPlane = view.desc.farPlane;
    denoiser.vulkanNdc = view.desc.vulkanNdc;
    return denoiser;
}

// A wall behind the camera and one beside it (what screen space cannot see), lit by a sun.
test::HybridTestScene litWalls() {
    std::vector<shaders::ScenePrimitive> walls;
    const auto quad = [&](shaders::float3 a, shaders::float3 b, shaders::float3 c, shaders::float3 d) {
        shaders::ScenePrimitive t{};
        t.kind = GLINT_SCENE_PRIM_TRIANGLE;
        t.p0 = a, t.p1 = b, t.p2 = c;
        walls.push_back(t);
        t.p0 = a, t.p1 = c, t.p2 = d;
        walls.push_back(t);
    };
    quad(point(-30, -30, 5), point(30, -30, 5), point(30, 30, 5), point(-30, 30, 5));
    quad(point(8, -30, -40), point(8, -30, 10), point(8, 30, 10), point(8, 30, -40));
    shaders::SceneMaterial paint{};
    paint.baseColor = {0.7f, 0.6f, 0.5f};
    paint.roughness = 0.6f;
    paint.emissive = {0.05f, 0.05f, 0.05f};
    shaders::SceneLight sun{};
    sun.where = {0.3f, 0.8f, 0.52f};
    sun.kind = GLINT_SCENE_LIGHT_DIRECTIONAL;
    sun.radiance = {3.0f, 3.0f, 3.0f};
    sun.size = 0.01f;
    return test::HybridTestScene(walls, {paint}, {sun});
}

} // namespace

namespace {

// `bothPaths`: the view is large enough that some rays are ray traced and some re-shaded.
void checkPoisoned(std::uint32_t width, std::uint32_t height, bool bothPaths) {
    INFO(width << "x" << height);
    test::SssrTestView view = test::makeSssrTestView(width, height, false);
    test::fillRandomSurfaces(view, 41);
    view.inputs.baseColorMetallic.clear();
    for (std::size_t i = 0; i < std::size_t{width} * height; ++i) {
        view.inputs.material[4 * i] = (i % 3) == 0 ? 0.0f : 0.12f;
        for (int c = 0; c < 3; ++c) view.inputs.baseColorMetallic.push_back(0.8f);
        view.inputs.baseColorMetallic.push_back(1.0f);
    }
    const test::HybridTestScene scene = litWalls();
    const gpu::Context& context = test::testContext();

    HybridDesc desc = denoisedHybrid(view);
    ReflectionsDenoiserDesc denoiser = denoiserFor(view);
    EffectPlan plan;
    std::string error;
    REQUIRE(planHybridReflections(desc, &denoiser, plan, &error) == Result::Ok);
    gpu::EffectRunner runner(context, plan, scene::findShader);
    runner.initialize();
    gpu::InputImages inputs(context, view.desc.size, false);
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    double reshadedHits = 0.0;
    for (std::uint32_t frame = 0; frame < 4; ++frame) {
        INFO("frame " << frame);
        desc.sssr.frameIndex = denoiser.frameIndex = frame;
        denoiser.resetHistory = frame == 0;
        test::SssrTestView poisoned = view;
        if (frame == 2) {
            for (std::size_t i = 0; i < poisoned.inputs.depth.size(); i += 5) {
                poisoned.inputs.normals[4 * i + i % 3] = nan;
                poisoned.inputs.color[4 * i] = inf;
                if (i % 15 == 0) poisoned.inputs.depth[i] = nan;
                if (i % 25 == 0) poisoned.inputs.motion[2 * i] = inf;
                if (i % 35 == 0) poisoned.inputs.material[4 * i] = nan;
            }
            for (const char* name : {"rd_radiance1", "rd_variance1", "rd_length1", "rd_guides1"}) {
                VkClearColorValue fill{};
                for (float& channel : fill.float32) channel = nan;
                gpu::clearImage(context, runner.image(name), fill);
            }
            VkClearColorValue garbage{};
            for (std::uint32_t& word : garbage.uint32) word = 0xFFFFFFFFu;
            gpu::clearImage(context, runner.image(hybridFeedbackImages(frame).second), garbage);
        }
        REQUIRE(planHybridReflections(desc, &denoiser, plan, &error) == Result::Ok);
        vk::ResourceTable table = test::uploadInputs(inputs, poisoned);
        scene.addTo(table);
        runner.run(plan, table);
        std::size_t checked = 0;
        for (const gpu::DecodedOutput& output : runner.readOutputs(plan, false)) {
            INFO("output " << output.name);
            for (const float value : output.pixels) REQUIRE(std::isfinite(value));
            checked += output.name == "denoised" || output.name == "composite" || output.name == "noisy";
        }
        CHECK(checked == 3);
        const auto counters = runner.readCounters(plan);
        for (const auto& [name, value] : counters) {
            if (bothPaths && name == "ray_traced_rays") CHECK(value > 0.0);
            if (name == "reshaded_hits") reshadedHits += value;
        }
    }
    // Frame 0 has no statistics (tiles start ray traced); screen space answers from then on.
    if (bothPaths) CHECK(reshadedHits > 0.0);
}

} // namespace

TEST_CASE("the composed hybrid effect keeps every output finite through poisoned inputs and histories",
          "[hybrid][composed]") {
    checkPoisoned(48, 32, true);
    checkPoisoned(1, 1, false); // one partial tile, no quad neighbours
    checkPoisoned(7, 5, false);
    checkPoisoned(33, 17, false); // odd sizes: partial tiles on both edges
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("the composed hybrid composites the denoised reflection", "[hybrid][composed]") {
    // The denoiser writes its result into sssr_radiance, which the composite reads: its passes
    // must all run before the composite (they once ran after it, compositing the noisy result).
    const test::SssrTestView view = test::makeSssrTestView(32, 16, false);
    const HybridDesc desc = denoisedHybrid(view);
    const ReflectionsDenoiserDesc denoiser = denoiserFor(view);
    EffectPlan plan;
    std::string error;
    REQUIRE(planHybridReflections(desc, &denoiser, plan, &error) == Result::Ok);
    const auto position = [&](const std::string& name) {
        for (std::size_t i = 0; i < plan.passes.size(); ++i)
            if (plan.passes[i].name == name) return i;
        FAIL("no pass " << name);
        return plan.passes.size();
    };
    CHECK(position("resolve") < position("composite"));
    CHECK(position("composite") == plan.passes.size() - 1);
}
