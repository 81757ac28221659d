// The ratio-estimator path's two passes, each run alone on a small synthetic frame (24 x 16,
// five of its six tiles listed) against the CPU references of
// tests/reference/reflections_denoiser_ratio_reference.h, and with NaN and Inf injected into
// every input they read.
#include "reference/reflections_denoiser_ratio_reference.h"
#include "support/gpu_test_context.h"

#include "glint/common/glint_wire_formats.h"
#include "glint/glint_reflections_denoiser.h"

#include <gpu/gpu_plan_runner.h>
#include <gpu/gpu_transfer.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>

using namespace glint;
using reference::Rgb;

namespace {

constexpr std::uint32_t kWidth = 24, kHeight = 16;
constexpr double kNear = 0.1, kFar = 100.0, kFocalX = 1.2, kFocalY = 1.8;

// The G-buffer and the passes' inputs, as uploaded (float) and as the reference reads them.
struct SyntheticFrame {
    ReflectionsDenoiserDesc desc;
    std::array<double, 9> worldFromView{}; // rotation, row-major
    std::vector<float> depth, normals, roughness, clamped, rays, variance, resolved, output;
    std::vector<std::uint32_t> tiles; // listed tile origins (GLINT_WIRE_PackTileEntry)
    std::vector<std::uint8_t> listed; // per pixel: in a listed tile
};

double deviceToViewDepth(double d) {
    return kNear * kFar / (kFar - d * (kFar - kNear));
}

Rgb rotate(const std::array<double, 9>& m, const Rgb& v) {
    return {m[0] * v[0] + m[1] * v[1] + m[2] * v[2], m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
            m[6] * v[0] + m[7] * v[1] + m[8] * v[2]};
}

Rgb unit(const Rgb& v) {
    const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return {v[0] / length, v[1] / length, v[2] / length};
}

// The world direction toward the camera at pixel (x, y) and device depth d.
Rgb worldView(const SyntheticFrame& frame, std::uint32_t x, std::uint32_t y, double d) {
    const double u = (x + 0.5) / kWidth, v = (y + 0.5) / kHeight, z = deviceToViewDepth(d);
    const Rgb toPoint =
        rotate(frame.worldFromView, {(2.0 * u - 1.0) * z / kFocalX, (2.0 * v - 1.0) * z / kFocalY, -z});
    const Rgb n = unit(toPoint);
    return {-n[0], -n[1], -n[2]};
}

// Depth: two tilted planes with a step between them and a few background pixels. Roughness:
// mostly full-radius glossy, with mirrors, rough pixels and smoother (smaller-radius) ones.
// Normals face the camera (n.v > 0.05, so no bending): random around the view direction, or a
// smooth field (for the cleanup, whose normal weight is a 128th power).
SyntheticFrame makeFrame(std::uint32_t seed, bool smoothNormals) {
    SyntheticFrame frame;
    ReflectionsDenoiserDesc& desc = frame.desc;
    desc.size = {kWidth, kHeight};
    desc.projection = {
        kFocalX, 0, 0,  0, 0, kFocalY, 0, 0, 0, 0, kFar / (kNear - kFar), kNear * kFar / (kNear - kFar),
        0,       0, -1, 0};
    const double a = 0.5, b = 0.2; // view from world: rotation about y by a, then about x by b
    const std::array<double, 9> rotation = {std::cos(a),
                                            0.0,
                                            std::sin(a),
                                            std::sin(b) * std::sin(a),
                                            std::cos(b),
                                            -std::sin(b) * std::cos(a),
                                            -std::cos(b) * std::sin(a),
                                            std::sin(b),
                                            std::cos(b) * std::cos(a)};
    const double translation[3] = {0.3, -0.2, 0.5};
    for (std::size_t r = 0; r < 3; ++r) {
        for (std::size_t c = 0; c < 3; ++c) {
            desc.viewFromWorld[4 * r + c] = rotation[3 * r + c];
            frame.worldFromView[3 * c + r] = rotation[3 * r + c];
        }
        desc.viewFromWorld[4 * r + 3] = translation[r];
    }
    desc.nearPlane = static_cast<float>(kNear);
    desc.farPlane = static_cast<float>(kFar);
    desc.spatialPath = SpatialPath::RatioEstimator;
    desc.frameIndex = 6 + 2 * seed; // even: the passes use the parity-0 histories

    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    auto random = [&](double low, double high) { return low + (high - low) * uniform(rng); };
    auto randomUnit = [&] {
        const double z = random(-1.0, 1.0), phi = random(0.0, 2.0 * 3.141592653589793);
        const double r = std::sqrt(1.0 - z * z);
        return Rgb{r * std::cos(phi), r * std::sin(phi), z};
    };
    const std::size_t pixels = std::size_t{kWidth} * kHeight;
    frame.depth.resize(pixels);
    frame.roughness.resize(pixels);
    frame.variance.resize(pixels);
    frame.normals.resize(4 * pixels);
    frame.clamped.resize(4 * pixels);
    frame.rays.resize(4 * pixels);
    frame.resolved.resize(4 * pixels);
    frame.output.resize(4 * pixels);
    frame.listed.resize(pixels);
    const Rgb smoothOffset = {0.3, 0.2, -0.1};
    const float varianceLevels[5] = {0.0f, 3e-5f, 5e-4f, 0.01f, 0.3f};
    for (std::uint32_t y = 0; y < kHeight; ++y)
        for (std::uint32_t x = 0; x < kWidth; ++x) {
            const std::size_t i = std::size_t{y} * kWidth + x;
            frame.listed[i] = !(x / 8 == 1 && y / 8 == 1);
            double d = 0.93 + 0.0015 * x + 0.001 * y + (x >= 13 ? 0.02 : 0.0);
            if (i % 19 == 7) d = 1.0;
            frame.depth[i] = static_cast<float>(d);
            double alpha = random(0.04, 0.19);
            if (i % 13 == 3) alpha = 5e-5;
            if (i % 17 == 5) alpha = 0.5;
            if (i % 23 == 11) alpha = random(0.01, 0.03);
            if (i % 29 == 2) alpha = random(0.001, 0.003);
            frame.roughness[i] = static_cast<float>(alpha);
            const Rgb V = worldView(frame, x, y, d);
            Rgb n = smoothNormals
                        ? Rgb{V[0] + smoothOffset[0], V[1] + smoothOffset[1], V[2] + smoothOffset[2]}
                        : Rgb{};
            const Rgb jitter = randomUnit();
            const double spread = smoothNormals ? 0.01 : 0.6;
            if (!smoothNormals) n = V;
            n = unit({n[0] + spread * jitter[0], n[1] + spread * jitter[1], n[2] + spread * jitter[2]});
            if (n[0] * V[0] + n[1] * V[1] + n[2] * V[2] < 0.05) n = V;
            const Rgb ray = randomUnit();
            const double pdf = std::exp(random(std::log(1e-3), std::log(1e3)));
            for (std::size_t c = 0; c < 3; ++c) {
                frame.normals[4 * i + c] = static_cast<float>(n[c]);
                frame.clamped[4 * i + c] = static_cast<float>(random(0.0, 4.0));
                frame.rays[4 * i + c] = i % 11 == 4 ? 0.0f : static_cast<float>(ray[c]);
                frame.resolved[4 * i + c] = static_cast<float>(random(0.0, 4.0));
                frame.output[4 * i + c] = static_cast<float>(random(0.0, 4.0));
            }
            frame.normals[4 * i + 3] = 0.0f;
            frame.clamped[4 * i + 3] = 10.0f;
            frame.rays[4 * i + 3] = i % 11 == 4 ? 0.0f : static_cast<float>(pdf);
            frame.resolved[4 * i + 3] = 1.0f;
            frame.output[4 * i + 3] = 7.5f + static_cast<float>(x);
            frame.variance[i] = varianceLevels[static_cast<std::size_t>(random(0.0, 4.999))];
        }
    for (std::uint32_t ty = 0; ty < kHeight / 8; ++ty)
        for (std::uint32_t tx = 0; tx < kWidth / 8; ++tx)
            if (!(tx == 1 && ty == 1))
                frame.tiles.push_back(shared::GLINT_WIRE_PackTileEntry(tx * 8, ty * 8));
    return frame;
}

// One pass of the ratio path's plan, alone, on the frame's inputs; returns the image it writes.
std::vector<float> runPass(const SyntheticFrame& frame, const std::string& passName, bool half) {
    gpu::Context& context = test::testContext();
    ReflectionsDenoiserDesc desc = frame.desc;
    desc.halfPrecisionStorage = half;
    EffectPlan full;
    std::string error;
    REQUIRE(planReflectionsDenoiser(desc, full, &error) == Result::Ok);
    const auto pass = std::find_if(full.passes.begin(), full.passes.end(),
                                   [&](const Pass& p) { return p.name == passName; });
    REQUIRE(pass != full.passes.end());
    const Format stored = half ? Format::RGBA16Float : Format::RGBA32Float;
    EffectPlan plan;
    plan.effect = "ratio_test";
    plan.passes = {*pass};
    plan.images = {{"depth", kWidth, kHeight, 1, Format::R32Float},
                   {"normals", kWidth, kHeight, 1, Format::RGBA32Float},
                   {"sssr_roughness", kWidth, kHeight, 1, Format::R32Float},
                   {"rd_clamped", kWidth, kHeight, 1, Format::RGBA32Float},
                   {"sssr_rays", kWidth, kHeight, 1, Format::RGBA32Float},
                   {"rd_variance0", kWidth, kHeight, 1, Format::R32Float},
                   {"rd_radiance0", kWidth, kHeight, 1, Format::RGBA32Float},
                   {"rd_prefiltered", kWidth, kHeight, 1, stored},
                   {"sssr_radiance", kWidth, kHeight, 1, stored}};
    plan.buffers = {{"sssr_tile_list", frame.tiles.size() * 4, false}, {"sssr_indirect_args", 24, true}};
    gpu::PlanResources resources = gpu::createPlanResources(context, plan);
    vk::Executor executor = vk::createExecutor(context.device);
    std::vector<float> written;
    try {
        auto upload = [&](const char* name, const std::vector<float>& texels, std::uint32_t channels) {
            gpu::uploadImage(context, resources.images.at(name), texels, channels);
        };
        upload("depth", frame.depth, 1);
        upload("normals", frame.normals, 4);
        upload("sssr_roughness", frame.roughness, 1);
        upload("rd_clamped", frame.clamped, 4);
        upload("sssr_rays", frame.rays, 4);
        upload("rd_variance0", frame.variance, 1);
        upload("rd_radiance0", frame.resolved, 4);
        upload("sssr_radiance", frame.output, 4);
        gpu::uploadBuffer(context, resources.buffers.at("sssr_tile_list"),
                          std::span<const std::uint32_t>(frame.tiles));
        const std::uint32_t arguments[6] = {0, 0, 0, static_cast<std::uint32_t>(frame.tiles.size()), 1, 1};
        gpu::uploadBuffer(context, resources.buffers.at("sssr_indirect_args"),
                          std::span<const std::uint32_t>(arguments));
        gpu::executePlan(context, executor, plan, gpu::resourceTable(resources));
        written = gpu::readbackImage(
            context, resources.images.at(passName == "reconstruct" ? "rd_prefiltered" : "sssr_radiance"));
    } catch (...) {
        vk::destroyExecutor(executor);
        gpu::destroyPlanResources(context, resources);
        throw;
    }
    vk::destroyExecutor(executor);
    gpu::destroyPlanResources(context, resources);
    return written;
}

// The surface the passes see, from the frame's G-buffer, in double.
reference::DenoiserSurface surfaceOf(const SyntheticFrame& frame) {
    reference::DenoiserSurface surface;
    surface.width = kWidth;
    surface.height = kHeight;
    const std::size_t pixels = std::size_t{kWidth} * kHeight;
    surface.glossy.assign(pixels, 0);
    surface.normal.resize(pixels);
    surface.viewDepth.assign(pixels, 0.0);
    surface.alpha.resize(pixels);
    for (std::size_t i = 0; i < pixels; ++i) {
        const double d = frame.depth[i];
        surface.normal[i] = unit({frame.normals[4 * i], frame.normals[4 * i + 1], frame.normals[4 * i + 2]});
        surface.alpha[i] = frame.roughness[i];
        surface.viewDepth[i] = deviceToViewDepth(d);
        surface.glossy[i] =
            d < 1.0 - 1e-6 && surface.alpha[i] < double{frame.desc.roughnessThreshold} ? 1u : 0u;
    }
    return surface;
}

Rgb rgbAt(const std::vector<float>& rgba, std::size_t i) {
    return {rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2]};
}

} // namespace

TEST_CASE("the ratio path's reconstruction and cleanup match their CPU references on a synthetic frame",
          "[reflections_denoiser][ratio]") {
    for (const bool smoothNormals : {false, true}) {
        INFO((smoothNormals ? "smooth normals" : "random normals"));
        const SyntheticFrame frame = makeFrame(smoothNormals ? 2u : 1u, smoothNormals);
        const reference::DenoiserSurface surface = surfaceOf(frame);
        const std::size_t pixels = std::size_t{kWidth} * kHeight;

        // Reconstruction: |gpu - ref| <= 1e-4 (1 + |ref|) for rgb and variance (measured on
        // lavapipe: 5e-6 at worst). float32 moves a sharp lobe's D through N.H (alpha >= 0.01
        // here), and the 6-decimal tap table moves taps by < 1e-6 px; pixels whose taps sit
        // within 1e-3 px of a rounding boundary are not compared.
        reference::ReconstructInputs inputs;
        inputs.surface = &surface;
        inputs.radius = frame.desc.reconstructionRadius;
        inputs.frameIndex = frame.desc.frameIndex;
        inputs.mirrorThreshold = frame.desc.mirrorThreshold;
        for (std::size_t i = 0; i < pixels; ++i) {
            const std::uint32_t x = static_cast<std::uint32_t>(i % kWidth),
                                y = static_cast<std::uint32_t>(i / kWidth);
            inputs.view.push_back(worldView(frame, x, y, frame.depth[i]));
            inputs.radiance.push_back(rgbAt(frame.clamped, i));
            inputs.rays.push_back({rgbAt(frame.rays, i), frame.rays[4 * i + 3]});
            inputs.variance.push_back(frame.variance[i]);
        }
        const std::vector<float> reconstructed = runPass(frame, "reconstruct", false);
        std::size_t compared = 0, ambiguous = 0, failed = 0, filtered = 0, moved = 0;
        double worst = 0.0;
        std::ostringstream first;
        for (std::size_t i = 0; i < pixels; ++i) {
            const std::uint32_t x = static_cast<std::uint32_t>(i % kWidth),
                                y = static_cast<std::uint32_t>(i / kWidth);
            if (!frame.listed[i]) {
                // Tiles nobody listed are not touched.
                for (std::size_t c = 0; c < 4; ++c) REQUIRE(std::isnan(reconstructed[4 * i + c]));
                continue;
            }
            const reference::ReconstructResult expected = reference::reconstructPixel(inputs, x, y);
            if (expected.ambiguous) {
                ++ambiguous;
                continue;
            }
            ++compared;
            const bool spatial = surface.glossy[i] && surface.alpha[i] >= double{frame.desc.mirrorThreshold};
            filtered += spatial ? 1u : 0u;
            moved +=
                spatial && std::abs(expected.value.rgb[0] - double{frame.clamped[4 * i]}) > 0.05 ? 1u : 0u;
            for (std::size_t c = 0; c < 4; ++c) {
                const double ref = c < 3 ? expected.value.rgb[c] : expected.value.variance;
                const double error = std::abs(double{reconstructed[4 * i + c]} - ref),
                             tolerance = 1e-4 * (1.0 + std::abs(ref));
                worst = std::max(worst, error / tolerance);
                if (error > tolerance && failed++ < 8)
                    first << "(" << x << ", " << y << ") channel " << c << ": gpu "
                          << reconstructed[4 * i + c] << ", reference " << ref << "\n";
            }
        }
        INFO(first.str());
        WARN("reconstruction: " << compared << " pixels compared (" << filtered << " filtered, " << moved
                                << " moved by more than 0.05 from their own sample), " << ambiguous
                                << " ambiguous, worst error " << worst << " of the tolerance");
        CHECK(failed == 0u);
        CHECK(ambiguous < compared / 10);
        CHECK(filtered > 150u);
        CHECK(moved > 100u);

        // Cleanup: |gpu - ref| <= 1e-4 (1 + |ref|); unfiltered pixels keep their output exactly,
        // and the alpha (hit distance) is kept everywhere.
        reference::CleanupInputs cleanupInputs;
        cleanupInputs.surface = &surface;
        cleanupInputs.sigma = frame.desc.cleanupSigma;
        cleanupInputs.variance = inputs.variance;
        for (std::size_t i = 0; i < pixels; ++i) cleanupInputs.resolved.push_back(rgbAt(frame.resolved, i));
        const std::vector<float> cleaned = runPass(frame, "cleanup", false);
        std::size_t blurred = 0, changed = 0;
        double worstCleanup = 0.0;
        for (std::size_t i = 0; i < pixels; ++i) {
            const std::uint32_t x = static_cast<std::uint32_t>(i % kWidth),
                                y = static_cast<std::uint32_t>(i / kWidth);
            REQUIRE(cleaned[4 * i + 3] == frame.output[4 * i + 3]);
            const std::optional<Rgb> expected =
                frame.listed[i] ? reference::cleanupPixel(cleanupInputs, x, y) : std::nullopt;
            if (!expected) {
                for (std::size_t c = 0; c < 3; ++c) REQUIRE(cleaned[4 * i + c] == frame.output[4 * i + c]);
                continue;
            }
            ++blurred;
            double distance = 0.0;
            for (std::size_t c = 0; c < 3; ++c) {
                const double error = std::abs(double{cleaned[4 * i + c]} - (*expected)[c]);
                const double tolerance = 1e-4 * (1.0 + std::abs((*expected)[c]));
                worstCleanup = std::max(worstCleanup, error / tolerance);
                CHECK(error <= tolerance);
                distance = std::max(distance, std::abs((*expected)[c] - double{frame.resolved[4 * i + c]}));
            }
            changed += distance > 0.05 ? 1u : 0u;
        }
        WARN("cleanup: " << blurred << " pixels filtered, " << changed
                         << " moved by more than 0.05, worst error " << worstCleanup << " of the tolerance");
        CHECK(blurred > 60u);
        if (smoothNormals) CHECK(changed > 30u);
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("NaN and Inf in every input of the reconstruction and the cleanup leave their outputs finite",
          "[reflections_denoiser][ratio][hard]") {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    const float poisons[3] = {nan, inf, -inf};
    for (const bool half : {false, true}) {
        INFO((half ? "16-bit storage" : "32-bit storage"));
        SyntheticFrame frame = makeFrame(3, true);
        const std::size_t pixels = std::size_t{kWidth} * kHeight;
        for (std::size_t i = 0; i < pixels; i += 3) {
            const float value = poisons[(i / 3) % 3];
            switch ((i / 9) % 8) {
            case 0:
                frame.rays[4 * i + (i % 3)] = value;
                break;
            case 1:
                frame.rays[4 * i + 3] = value;
                break;
            case 2:
                frame.clamped[4 * i + (i % 4)] = value;
                break;
            case 3:
                frame.variance[i] = value;
                break;
            case 4:
                frame.resolved[4 * i + (i % 3)] = value;
                break;
            case 5:
                frame.normals[4 * i + (i % 3)] = value;
                break;
            case 6:
                frame.depth[i] = value;
                break;
            default:
                frame.roughness[i] = value;
                break;
            }
        }
        for (std::size_t i = 0; i < pixels; i += 7) frame.output[4 * i + 3] = nan; // the kept hit distance
        const std::vector<float> reconstructed = runPass(frame, "reconstruct", half);
        const std::vector<float> cleaned = runPass(frame, "cleanup", half);
        std::size_t sanitized = 0;
        for (std::size_t i = 0; i < pixels; ++i) {
            if (!frame.listed[i]) continue;
            INFO("pixel " << i);
            for (std::size_t c = 0; c < 4; ++c) REQUIRE(std::isfinite(reconstructed[4 * i + c]));
            for (std::size_t c = 0; c < 3; ++c) REQUIRE(std::isfinite(cleaned[4 * i + c]));
            // The cleanup writes only the glossy pixels it filters (with a finite hit distance);
            // the others keep what the resolve wrote, here a poisoned alpha.
            REQUIRE((std::isfinite(cleaned[4 * i + 3]) || std::isnan(frame.output[4 * i + 3])));
            sanitized += std::isnan(frame.output[4 * i + 3]) && std::isfinite(cleaned[4 * i + 3]) ? 1u : 0u;
        }
        CHECK(sanitized > 0u);
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
