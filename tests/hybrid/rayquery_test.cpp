// The hybrid's ray-traced rays answered by the engines' RayQuery entry
// (hlsl/entry/hybrid/hybrid_trace_rayquery.cs.hlsl, compiled by DXC, loaded from GLINT_SHADER_DIR)
// over the scene's acceleration structure (harness/scene/scene_acceleration.h), against the
// harness's BVH tracer over the same triangles: the same hit records, and the same denoised error
// against the reference. Needs a device with ray queries (the backports lavapipe:
// CONTRIBUTING.md, "Ray queries").
#include "hybrid/hybrid_test_frame.h"
#include "support/gpu_test_context.h"
#include "support/test_replay.h"

#include <gpu/gpu_effect_runner.h>
#include <gpu/gpu_transfer.h>
#include <replay/replay_frame.h>
#include <scene/scene_acceleration.h>
#include <scene/scene_buffers.h>
#include <scene/scene_file.h>
#include <scene/scene_shaders.h>
#include <scene/scene_simulate.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>

using namespace glint;

namespace {

constexpr std::uint32_t kWidth = 64, kHeight = 36;
constexpr double kLuminance[3] = {0.2126, 0.7152, 0.0722}; // Rec. 709

// Tolerances of two fp32 ray-triangle tests of the same triangle (docs/hybrid.md, "Acceleration
// structures"). Distance: each test rounds about ten times, each by at most 6e-8 of the ray's
// span; a grazing ray (the corridor's mirrors, cosines down to about 0.1) multiplies that by the
// inverse cosine: 10 x 10 x 6e-8 = 6e-6, so 1e-5 relative to max(1, t).
// Barycentrics: each is stored rounded to 1/65535 (GLINT_HYBRID_PackHit), so two equal values
// differ by at most one step after rounding, plus the fp32 error of the weights, well below a
// step for triangles a metre across: two steps.
constexpr double kDistanceTolerance = 1e-5;
constexpr double kBarycentricTolerance = 2.0 / 65535.0;
// A ray that meets two triangles at their shared edge (or grazes a silhouette) may be given to
// either by two correct tracers: a differing primitive is a tie only when each hit lies within
// this of its triangle's edge, in barycentric units.
constexpr double kEdgeTolerance = 1e-3;

struct Record {
    float t;
    std::uint32_t primitive, instance;
    double u, v;
};

Record unpack(const std::vector<std::uint32_t>& words, std::size_t ray) {
    Record r{};
    std::memcpy(&r.t, &words[4 * ray], sizeof r.t);
    r.primitive = words[4 * ray + 1];
    r.u = double(words[4 * ray + 2] & 0xFFFFu) / 65535.0;
    r.v = double(words[4 * ray + 2] >> 16) / 65535.0;
    r.instance = words[4 * ray + 3];
    return r;
}

bool onEdge(const Record& r) {
    return std::min({r.u, r.v, 1.0 - r.u - r.v}) <= kEdgeTolerance;
}

// The scene at the test's size without its spheres: the acceleration structure holds triangles.
scene::Scene trianglesOnly(const char* file) {
    scene::Scene scene = scene::loadScene(file);
    std::erase_if(scene.objects,
                  [](const scene::ObjectDesc& o) { return o.shape == scene::ShapeKind::Sphere; });
    scene.width = kWidth;
    scene.height = kHeight;
    scene.frameCount = 1;
    scene.reference.reflections = true;
    scene.reference.samplesPerPixel = 8;
    return scene;
}

struct TracedFrame {
    std::vector<std::uint32_t> rays, hits; // the ray-traced list and its 4-word records
    std::vector<float> denoised;           // RGB
    std::vector<float> alpha;              // the pixels' GGX alpha
};

// Frame 0 of the hybrid, ray tracing only (every glossy ray reaches the tracer), denoised.
TracedFrame runTraced(const capture::Frame& frame, const capture::Environment& environment,
                      scene::SceneBuffers& buffers, HybridTracer tracer) {
    const gpu::Context& context = test::testContext();
    test::SssrTestView view;
    replay::sssrFromFrame(frame, environment, view.desc, view.inputs);
    view.desc.denoise = true;
    HybridDesc desc;
    desc.sssr = view.desc;
    desc.screenSpace = false;
    desc.tracer = tracer;
    if (tracer == HybridTracer::RayQuery) desc.tracePipeline = "hybrid_trace_rayquery";
    const ReflectionsDenoiserDesc denoiser = replay::denoiserFromFrame(frame, desc.sssr, 0, true);
    EffectPlan plan;
    std::string error;
    REQUIRE(planHybridReflections(desc, &denoiser, plan, &error) == Result::Ok);
    gpu::EffectRunner runner(context, plan, scene::findShader);
    runner.initialize();
    gpu::InputImages inputs(context, view.desc.size, false);
    vk::ResourceTable table = test::uploadInputs(inputs, view);
    buffers.addTo(table);
    runner.run(plan, table);
    TracedFrame out;
    const std::vector<std::uint32_t> counters = runner.readWords("hybrid_counters");
    out.rays = runner.readWords("hybrid_hw_ray_list", counters.at(5));
    out.hits = runner.readWords("hybrid_hits", 4 * out.rays.size());
    for (gpu::DecodedOutput& output : runner.readOutputs(plan, false))
        if (output.name == "denoised") out.denoised = std::move(output.pixels);
    const std::vector<std::byte> bytes = gpu::readbackImageBytes(context, runner.image("sssr_roughness"));
    out.alpha.resize(bytes.size() / 4);
    std::memcpy(out.alpha.data(), bytes.data(), bytes.size());
    return out;
}

// Per pixel: the luminance-weighted absolute difference relative to the reference (floored at
// 0.05), capped at 1, as the effect is scored (docs/hybrid.md).
double pixelError(const std::vector<float>& rgb, const std::vector<float>& reference, std::size_t i) {
    double difference = 0.0, luminance = 0.0;
    for (std::size_t c = 0; c < 3; ++c) {
        difference += kLuminance[c] * std::abs(double(rgb[3 * i + c]) - double(reference[3 * i + c]));
        luminance += kLuminance[c] * double(reference[3 * i + c]);
    }
    return std::min(difference / std::max(luminance, 0.05), 1.0);
}

void compareTracers(const char* file) {
    const scene::Scene scene = trianglesOnly(file);
    const scene::Simulation sim = scene::simulate(test::testContext(), scene);
    REQUIRE(sim.environment.has_value());
    scene::SceneBuffers buffers(test::testContext(), scene, true);
    const TracedFrame bvh = runTraced(sim.frames[0], *sim.environment, buffers, HybridTracer::Bvh);
    const TracedFrame rayQuery = runTraced(sim.frames[0], *sim.environment, buffers, HybridTracer::RayQuery);

    // The same rays (the list does not depend on the tracer), in the order the waves appended
    // them, which may differ: records are matched by the ray's pixel entry.
    REQUIRE(bvh.rays.size() > 100);
    std::map<std::uint32_t, std::size_t> rayQueryIndex;
    for (std::size_t i = 0; i < rayQuery.rays.size(); ++i) rayQueryIndex[rayQuery.rays[i]] = i;
    REQUIRE(rayQueryIndex.size() == bvh.rays.size());
    std::size_t hits = 0, ties = 0;
    double worstT = 0.0, worstBarycentric = 0.0;
    for (std::size_t ray = 0; ray < bvh.rays.size(); ++ray) {
        const auto other = rayQueryIndex.find(bvh.rays[ray]);
        REQUIRE(other != rayQueryIndex.end());
        const Record a = unpack(bvh.hits, ray), b = unpack(rayQuery.hits, other->second);
        INFO("ray " << ray << ": BVH t " << a.t << " primitive " << a.primitive << " (" << a.u << ", " << a.v
                    << ") instance " << a.instance << "; RayQuery t " << b.t << " primitive " << b.primitive
                    << " (" << b.u << ", " << b.v << ") instance " << b.instance);
        const bool hitA = a.t >= 0.0f, hitB = b.t >= 0.0f;
        if (!hitA && !hitB) continue;
        const double scale = kDistanceTolerance * std::max(1.0, double(std::max(a.t, b.t)));
        if (hitA && hitB && a.primitive == b.primitive) {
            ++hits;
            CHECK(std::abs(double(a.t) - double(b.t)) <= scale);
            CHECK(std::abs(a.u - b.u) <= kBarycentricTolerance);
            CHECK(std::abs(a.v - b.v) <= kBarycentricTolerance);
            CHECK(a.instance == scene::kSceneInstanceCustomIndex);
            CHECK(b.instance == scene::kSceneInstanceCustomIndex);
            worstT = std::max(worstT, std::abs(double(a.t) - double(b.t)) / std::max(1.0, double(a.t)));
            worstBarycentric = std::max({worstBarycentric, std::abs(a.u - b.u), std::abs(a.v - b.v)});
            continue;
        }
        // A tie: every hit on an edge, at the same distance when both hit.
        ++ties;
        CHECK((!hitA || onEdge(a)));
        CHECK((!hitB || onEdge(b)));
        if (hitA && hitB) CHECK(std::abs(double(a.t) - double(b.t)) <= scale);
    }
    INFO(file << ": " << bvh.rays.size() << " rays, " << hits << " equal hits, " << ties
              << " edge ties; worst relative t difference " << worstT << ", worst barycentric difference "
              << worstBarycentric);
    CHECK(hits > bvh.rays.size() / 2);
    // Edge ties are rare: a ray within 1e-3 of an edge of every triangle it meets.
    CHECK(ties * 100 <= bvh.rays.size());

    // The denoised error against the reference over the glossy pixels: a paired comparison, the
    // mean difference of the per-pixel errors within three standard errors of zero.
    const std::vector<float> reference = replay::layerChannels(sim.frames[0], "reference.reflection", 3);
    REQUIRE(bvh.denoised.size() == reference.size());
    REQUIRE(rayQuery.denoised.size() == reference.size());
    double sum = 0.0, sumSquares = 0.0, errorBvh = 0.0, errorRayQuery = 0.0;
    std::size_t glossy = 0;
    for (std::size_t i = 0; i < bvh.alpha.size(); ++i) {
        if (!(bvh.alpha[i] < HybridDesc{}.sssr.roughnessThreshold)) continue;
        const double e0 = pixelError(bvh.denoised, reference, i),
                     e1 = pixelError(rayQuery.denoised, reference, i);
        errorBvh += e0;
        errorRayQuery += e1;
        sum += e1 - e0;
        sumSquares += (e1 - e0) * (e1 - e0);
        ++glossy;
    }
    REQUIRE(glossy > 100);
    const double n = double(glossy), mean = sum / n;
    const double variance = std::max(sumSquares / n - mean * mean, 0.0);
    const double standardError = std::sqrt(variance / std::max(n - 1.0, 1.0));
    INFO(file << ": " << glossy << " glossy pixels, denoised error BVH " << errorBvh / n << ", RayQuery "
              << errorRayQuery / n << ", mean difference " << mean << " (standard error " << standardError
              << ")");
    CHECK(std::abs(mean) <= 3.0 * standardError);
}

// Why this process cannot run the ray-query tests, or "" when it can: the driver file the tests
// select (VK_DRIVER_FILES) is missing when scripts/setup.sh could not fetch it, and any other
// device may lack ray queries.
std::string rayQueryMissing() {
    const char* driver = std::getenv("VK_DRIVER_FILES");
    if (driver && *driver && !std::filesystem::exists(driver))
        return std::string("no ray-query lavapipe: ") + driver +
               " is missing (scripts/setup.sh debug fetches it)";
    if (!test::testContext().device.rayQuery)
        return "device '" + test::testContext().info.name +
               "' has no ray queries (select build/lavapipe-rayquery/lvp_icd.json with VK_DRIVER_FILES)";
    return "";
}

} // namespace

// Both scenes in one process: on a fresh machine lavapipe compiles each pipeline once per
// process (its shader cache is cold), which is most of this suite's time there.
TEST_CASE(
    "on the mirror corridor and the glossy room the RayQuery entry gives the BVH tracer's hit records and "
    "denoised error",
    "[hybrid][rayquery]") {
    if (const std::string missing = rayQueryMissing(); !missing.empty()) GLINT_SKIP(missing);
    for (const char* scene : {GLINT_SOURCE_DIR "/harness/scenes/mirror_corridor.toml",
                              GLINT_SOURCE_DIR "/harness/scenes/glossy_room.toml"}) {
        INFO(scene);
        compareTracers(scene);
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("an acceleration structure refuses a sphere in one line", "[hybrid][rayquery]") {
    if (const std::string missing = rayQueryMissing(); !missing.empty()) GLINT_SKIP(missing);
    scene::Scene scene = scene::loadScene(GLINT_SOURCE_DIR "/harness/scenes/glossy_room.toml");
    CHECK_THROWS_WITH(scene::SceneBuffers(test::testContext(), scene, true),
                      Catch::Contains("is a sphere; the structure holds triangles only"));
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
