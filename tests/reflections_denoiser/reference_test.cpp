// The deterministic parts of the reflections denoiser against the CPU references of
// tests/reference/reflections_denoiser_reference.h, pass by pass, each fed the GPU's own
// inputs of that pass (read back): the reproject pass's tile averages, the whole prefilter,
// and the resolve's anti-lag (the history length it stores), clip and blend. SSSR and the
// denoiser run on a simulated static scene for a few frames so that histories exist; every
// frame is checked, the first one with a reset.
#include "glint/common/glint_wire_formats.h"
#include "reference/reflections_denoiser_reference.h"
#include "reflections_denoiser/denoiser_scene.h"
#include "support/gpu_test_context.h"
#include "support/test_replay.h"

#include <gpu/gpu_snapshot.h>
#include <gpu/gpu_transfer.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

using namespace glint;
using reference::Rgb;

namespace {

// Counts and describes disagreements, keeping the largest error relative to its tolerance.
struct Comparison {
    const char* what;
    std::size_t checked = 0, failed = 0;
    double worst = 0.0; // max |gpu - ref| / tolerance
    std::ostringstream first;

    // |gpu - ref| <= absolute + relative * scale.
    void check(double gpu, double ref, double scale, double relative, double absolute, std::uint32_t x,
               std::uint32_t y, std::size_t channel) {
        ++checked;
        const double error = std::abs(gpu - ref), tolerance = absolute + relative * scale;
        worst = std::max(worst, error / tolerance);
        if (error <= tolerance) return;
        if (failed++ < 8)
            first << what << " (" << x << ", " << y << ") channel " << channel << ": gpu " << gpu
                  << ", reference " << ref << "\n";
    }
};

double maxAbs(const Rgb& c) {
    return std::max({std::abs(c[0]), std::abs(c[1]), std::abs(c[2])});
}

Rgb rgbAt(const std::vector<float>& rgba, std::size_t i) {
    return {rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2]};
}

// Octahedral decode of the guides' normal (signed form in [-1, 1]^2, docs/conventions.md §5).
Rgb decodeOctahedral(double px, double py) {
    double x = px, y = py;
    const double z = 1.0 - std::abs(x) - std::abs(y), fold = std::max(-z, 0.0);
    x -= x >= 0.0 ? fold : -fold;
    y -= y >= 0.0 ? fold : -fold;
    const double length = std::sqrt(x * x + y * y + z * z);
    return {x / length, y / length, z / length};
}

// The 16-bit permutation (halfPrecisionStorage) computes in 32 bits and rounds what it stores
// (radiance, variance, history length) to fp16; its groupshared spans narrow values read from
// fp16 images, which is lossless (rd_common.hlsli). The references are fed the stored (rounded)
// intermediates, so each compared value differs from the 32-bit permutation's arithmetic by its
// own store's rounding: at most 1 fp16 ulp (Vulkan leaves the direction of the conversion's
// rounding to the device), 2^-10 of the value for normal halves, 2^-24 absolute below 6.1e-5.
// The tile averages are stored in 32 bits, but reproject averages its in-register samples, which
// differ from the stored ones the reference reads by the same 2^-10 each: for non-negative
// radiance the weighted mean moves by at most 2^-10 of itself. Zero for the 32-bit permutation.
struct StorageRounding {
    double relative = 0.0, absolute = 0.0;
};

void checkPassesAgainstReferences(bool half);

} // namespace

TEST_CASE("the denoiser's tile averages, prefilter and resolve match their CPU references on the GPU's own "
          "intermediates",
          "[reflections_denoiser][reference]") {
    checkPassesAgainstReferences(false);
}

TEST_CASE(
    "16-bit storage: tile averages, prefilter and resolve match their CPU references within fp16 rounding",
    "[reflections_denoiser][reference][half]") {
    checkPassesAgainstReferences(true);
}

namespace {

void checkPassesAgainstReferences(bool half) {
    const StorageRounding fp16 =
        half ? StorageRounding{std::ldexp(1.0, -10), std::ldexp(1.0, -24)} : StorageRounding{};
    test::DenoiserScene scene = test::simulateDenoiserScene("glossy_room", 96, 54, 1);
    const capture::Frame& frame = scene.frames.at(0);
    SssrDesc desc = scene.desc;
    desc.denoise = true;
    desc.halfPrecisionStorage = half;
    // Mirrors (alpha below the threshold) are copied through by the prefilter; the default
    // threshold (1e-4) leaves none in this view of the floor's roughness ramp, 0.01 leaves a band.
    desc.mirrorThreshold = 0.01f;
    gpu::Context& context = test::testContext();
    gpu::SssrRunner runner(context, desc);
    runner.upload(scene.inputs);
    const std::uint32_t w = desc.size.width, h = desc.size.height;
    const std::size_t pixels = std::size_t{w} * h;
    const std::uint32_t tilesX = (w + 7) / 8, tilesY = (h + 7) / 8;

    const std::vector<std::string> passes = runner.passNames(desc, true);
    const std::size_t prefilterPass =
        static_cast<std::size_t>(std::find(passes.begin(), passes.end(), "prefilter") - passes.begin());
    REQUIRE(prefilterPass < passes.size());
    // The snapshot copies rd_variance as it is stored (vkCmdCopyImage needs the same texel size).
    gpu::Snapshot prefilterVariance(context, w, h, half ? VK_FORMAT_R16_SFLOAT : VK_FORMAT_R32_SFLOAT);
    // Reproject's history length, which the resolve reads and writes back after its anti-lag.
    gpu::Snapshot reprojectLength(context, w, h, half ? VK_FORMAT_R16_SFLOAT : VK_FORMAT_R32_SFLOAT);

    // The G-buffer as the denoiser reads it, in double: which pixels are glossy (finite,
    // in-range depth, a usable normal, alpha below the threshold) and their unit normals.
    const bool reversed = desc.depth != DepthConvention::Standard;
    for (std::size_t k : {8u, 9u, 12u, 13u}) REQUIRE(desc.projection[k] == 0.0); // no x, y in clip z, w
    std::vector<Rgb> normals(pixels);
    std::vector<std::uint8_t> surfaceOk(pixels, 0); // glossy but for alpha
    for (std::size_t i = 0; i < pixels; ++i) {
        const double d = scene.inputs.depth[i];
        const bool background =
            !std::isfinite(d) || (reversed ? (d <= 1e-6 || d > 1.0) : (d >= 1.0 - 1e-6 || d < 0.0));
        Rgb n;
        for (std::size_t c = 0; c < 3; ++c)
            n[c] = double{scene.inputs.normals[4 * i + c]} * double{desc.normalUnpackMul} +
                   double{desc.normalUnpackAdd};
        const double lengthSquared = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
        if (background || !(lengthSquared > 1e-12)) continue;
        const double inverse = 1.0 / std::sqrt(lengthSquared);
        normals[i] = {n[0] * inverse, n[1] * inverse, n[2] * inverse};
        surfaceOk[i] = 1;
    }

    constexpr std::uint32_t kFrames = 5;
    double worst[6] = {}; // per comparison, over the frames
    std::size_t totalShortened = 0;
    for (std::uint32_t index = 0; index < kFrames; ++index) {
        INFO("frame " << index);
        desc.frameIndex = index;
        const bool reset = index == 0;
        ReflectionsDenoiserDesc denoiser = replay::denoiserFromFrame(frame, desc, index, reset);
        denoiser.halfPrecisionStorage = half;
        const std::string parity = (index & 1u) != 0 ? "1" : "0";
        vk::PassHooks hooks;
        hooks.afterDispatch = [&](VkCommandBuffer cmd, std::size_t pass) {
            if (pass == prefilterPass) {
                prefilterVariance.record(cmd, runner.ownedImage("rd_variance" + parity));
                reprojectLength.record(cmd, runner.ownedImage("rd_length" + parity));
            }
        };
        runner.run(desc, nullptr, &denoiser, &hooks);
        const gpu::SssrFrameOutputs out = runner.readback();
        auto read = [&](const std::string& name) {
            return gpu::readbackImage(context, runner.ownedImage(name));
        };
        const std::vector<float> clamped = read("rd_clamped"), reprojected = read("rd_reprojected"),
                                 prefiltered = read("rd_prefiltered"), average = read("rd_average"),
                                 guides = read("rd_guides" + parity), length = read("rd_length" + parity),
                                 radiance = read("rd_radiance" + parity),
                                 variance = read("rd_variance" + parity),
                                 temporalVariance = gpu::readbackImage(context, prefilterVariance.image),
                                 inputLength = gpu::readbackImage(context, reprojectLength.image);
        REQUIRE(average.size() == 4 * std::size_t{tilesX} * tilesY);

        std::vector<std::uint8_t> listed(std::size_t{tilesX} * tilesY, 0);
        for (std::uint32_t tile : out.tileList)
            listed[std::size_t{shared::GLINT_WIRE_TileEntryY(tile) / 8} * tilesX +
                   shared::GLINT_WIRE_TileEntryX(tile) / 8] = 1;
        REQUIRE(!out.tileList.empty());
        auto inListedTile = [&](std::uint32_t x, std::uint32_t y) {
            return listed[std::size_t{y / 8} * tilesX + x / 8] != 0;
        };

        // The surface: glossy from the G-buffer and the alpha SSSR extracted, checked against
        // the guides reproject wrote (view depth 0: not glossy). Tiles nobody listed have no
        // glossy pixel (classification lists every tile with one), which the prefilter and
        // resolve rely on when they read apron pixels there.
        reference::DenoiserSurface surface;
        surface.width = w;
        surface.height = h;
        surface.glossy.assign(pixels, 0);
        surface.normal = normals;
        surface.viewDepth.assign(pixels, 0.0);
        surface.alpha.assign(pixels, 1.0);
        std::size_t glossyCount = 0, surfaceMismatches = 0, mirrorCount = 0;
        double worstViewDepthError = 0.0;
        for (std::uint32_t y = 0; y < h; ++y)
            for (std::uint32_t x = 0; x < w; ++x) {
                const std::size_t i = std::size_t{y} * w + x;
                const bool glossy = surfaceOk[i] && out.roughness[i] < desc.roughnessThreshold;
                surface.glossy[i] = glossy ? 1u : 0u;
                glossyCount += glossy ? 1u : 0u;
                if (!inListedTile(x, y)) {
                    surfaceMismatches += glossy ? 1u : 0u;
                    continue;
                }
                const float* g = &guides[4 * i];
                surfaceMismatches += glossy != (g[2] > 0.0f) ? 1u : 0u;
                if (!glossy) continue;
                // The guides' normal decodes to the G-buffer's within float rounding of the
                // encoding (a few 1e-7), and their alpha is SSSR's exactly.
                const Rgb decoded = decodeOctahedral(g[0], g[1]);
                const double normalError =
                    std::max({std::abs(decoded[0] - normals[i][0]), std::abs(decoded[1] - normals[i][1]),
                              std::abs(decoded[2] - normals[i][2])});
                surfaceMismatches += normalError > 1e-5 || g[3] != out.roughness[i] ? 1u : 0u;
                // The view depth is clip w of the point at device depth d (rows 2 and 3 of the
                // projection map view z to clip z and w). The GPU evaluates A / (B + C d) in
                // float32: a few ulp, times up to z / near where B + C d cancels (standard
                // depth); below 1e-5 relative for this scene's depths (measured 8e-8).
                const auto& P = desc.projection;
                const double d = scene.inputs.depth[i];
                const double viewZ = (P[11] - d * P[15]) / (d * P[14] - P[10]);
                const double expectedDepth = P[14] * viewZ + P[15];
                worstViewDepthError =
                    std::max(worstViewDepthError, std::abs(double{g[2]} - expectedDepth) / expectedDepth);
                surface.viewDepth[i] = g[2];
                surface.alpha[i] = g[3];
                mirrorCount += g[3] < desc.mirrorThreshold ? 1u : 0u;
            }
        REQUIRE(glossyCount > 0);
        REQUIRE(mirrorCount > 0u);
        REQUIRE(surfaceMismatches == 0u);
        CHECK(worstViewDepthError < 1e-5);

        // (b) Tile averages. A pixel's contribution is its clamped sample, blended 30 % toward
        // its history where it has one (reproject header; the docs do not say). On the reset
        // frame no pixel has a history, so the contribution is rd_clamped itself.
        std::vector<Rgb> contribution(pixels);
        for (std::size_t i = 0; i < pixels; ++i) {
            const bool valid = reprojected[4 * i + 3] > 0.5f;
            if (reset) REQUIRE(!valid);
            contribution[i] = rgbAt(clamped, i);
            if (valid)
                for (std::size_t c = 0; c < 3; ++c)
                    contribution[i][c] += 0.3 * (double{reprojected[4 * i + c]} - contribution[i][c]);
        }
        const reference::TileGrid expectedTiles =
            reference::tileAverages(w, h, contribution, surface.glossy, listed);
        // float32 sums of at most 64 terms each with an exp: relative error a few 1e-7 on
        // lavapipe; 1e-5 relative (plus 1e-6 absolute for channels near 0) leaves a wide margin.
        // With 16-bit storage the weights max(exp(-0.3 luma), 0.01) move too: luma by 2^-10 of
        // itself, each weight by at most 0.3 luma 2^-10 of itself (dw), so the weight sum by dw of
        // itself and the weighted mean by at most 2 dw times the tile's largest value.
        Comparison averages{"tile average"};
        for (std::uint32_t ty = 0; ty < tilesY; ++ty)
            for (std::uint32_t tx = 0; tx < tilesX; ++tx) {
                const std::size_t t = std::size_t{ty} * tilesX + tx;
                if (!listed[t]) continue;
                double largest = 0.0, largestLuma = 0.0;
                for (std::uint32_t y = ty * 8; y < std::min(h, ty * 8 + 8); ++y)
                    for (std::uint32_t x = tx * 8; x < std::min(w, tx * 8 + 8); ++x) {
                        const std::size_t i = std::size_t{y} * w + x;
                        if (!surface.glossy[i]) continue;
                        largest = std::max(largest, maxAbs(contribution[i]));
                        largestLuma = std::max(largestLuma, reference::luma(contribution[i]));
                    }
                const double weightShift = 0.3 * largestLuma * fp16.relative;
                const Rgb gpuAverage = rgbAt(average, t);
                for (std::size_t c = 0; c < 3; ++c)
                    averages.check(gpuAverage[c], expectedTiles.average[t][c],
                                   maxAbs(expectedTiles.average[t]), 1e-5 + fp16.relative,
                                   1e-6 + fp16.absolute + 2.0 * weightShift * largest, tx, ty, c);
                averages.check(average[4 * t + 3], expectedTiles.weight[t], expectedTiles.weight[t],
                               1e-5 + weightShift, 1e-6, tx, ty, 3);
            }

        // The GPU's own tile grid: what prefilter and resolve read.
        reference::TileGrid tiles;
        tiles.tilesX = tilesX;
        tiles.tilesY = tilesY;
        tiles.listed = listed;
        tiles.average.resize(listed.size());
        tiles.weight.resize(listed.size());
        for (std::size_t t = 0; t < listed.size(); ++t) {
            tiles.average[t] = rgbAt(average, t);
            tiles.weight[t] = average[4 * t + 3];
        }

        // (a) Prefilter on rd_clamped, the temporal variance it read, the surface and the tile grid.
        reference::PrefilterInputs prefilterInputs;
        prefilterInputs.surface = &surface;
        prefilterInputs.tiles = &tiles;
        prefilterInputs.mirrorThreshold = desc.mirrorThreshold;
        prefilterInputs.radiance.resize(pixels);
        prefilterInputs.variance.resize(pixels);
        for (std::size_t i = 0; i < pixels; ++i) {
            prefilterInputs.radiance[i] = rgbAt(clamped, i);
            prefilterInputs.variance[i] = temporalVariance[i];
        }
        std::vector<reference::RadianceVariance> expectedPrefiltered(pixels);
        reference::prefilter(prefilterInputs, expectedPrefiltered);
        // Tolerance 1e-4 of the pixel's largest channel + 1e-5. The output is a weighted mean
        // of 16 float32 samples; its error is at most the weights' relative error times the
        // samples' spread (of the order of the value). The largest weight error is the normal
        // term: pow(N.N_q, 512) turns float32 rounding of the normals and of the dot (a few
        // 1e-7) into 512 times that, ~1e-4 at worst; the exp terms add ~1e-6. Measured on
        // lavapipe: at most ~0.12 of the tolerance.
        // Pixels that are not glossy must carry the marking the resolve reads exactly: rgb 0,
        // variance kNotGlossyVariance in rd_prefiltered, and the same alpha in rd_clamped, whose
        // alpha is otherwise the temporal variance reproject also wrote to rd_variance.
        Comparison prefilterRgb{"prefiltered rgb"}, prefilterVar{"prefiltered variance"};
        std::size_t markMismatches = 0;
        const auto notGlossy = static_cast<float>(reference::kNotGlossyVariance);
        for (std::uint32_t y = 0; y < h; ++y)
            for (std::uint32_t x = 0; x < w; ++x) {
                if (!inListedTile(x, y)) continue;
                const std::size_t i = std::size_t{y} * w + x;
                markMismatches +=
                    clamped[4 * i + 3] != (surface.glossy[i] ? temporalVariance[i] : notGlossy) ? 1u : 0u;
                if (!surface.glossy[i]) {
                    markMismatches += prefiltered[4 * i] != 0.0f || prefiltered[4 * i + 1] != 0.0f ||
                                              prefiltered[4 * i + 2] != 0.0f ||
                                              prefiltered[4 * i + 3] != notGlossy
                                          ? 1u
                                          : 0u;
                    continue;
                }
                const reference::RadianceVariance& e = expectedPrefiltered[i];
                for (std::size_t c = 0; c < 3; ++c)
                    prefilterRgb.check(prefiltered[4 * i + c], e.rgb[c], maxAbs(e.rgb), 1e-4 + fp16.relative,
                                       1e-5 + fp16.absolute, x, y, c);
                prefilterVar.check(prefiltered[4 * i + 3], e.variance, e.variance, 1e-4 + fp16.relative,
                                   1e-5 + fp16.absolute, x, y, 3);
            }

        // (c) Resolve of every glossy pixel of a listed tile from the read-back prefiltered
        // radiance, reprojected histories, reproject's history length and tile grid: the
        // radiance, the variance and the history length the anti-lag stores.
        // Tolerance 1e-4 of the pixel's largest channel + 1e-5, plus what float32 cancellation
        // in sigma = sqrt(|E[c^2] - mean^2|) can do through the clip box. The 9x9 sums of 81
        // float32 terms carry a relative error below 81 * 2^-24 < 5e-6 each, so E[c^2] - mean^2
        // is off by up to k E[c^2] with k = 1e-5, and sigma by up to
        // ds = min(sqrt(k E[c^2]), k E[c^2] / sigma): negligible for a noisy neighbourhood, up
        // to ~3e-3 of the value for a flat one. The reference is evaluated with sigma +- ds, and
        // how far that moves its result is added to the tolerance: nothing where no clip is
        // active. Measured on lavapipe: at most ~0.12 of the tolerance. The anti-lag's tolerance
        // also scales with sigma, so the same probe covers the history length it stores (and
        // the output through that length); its mean difference is a sum of 81 float32 terms
        // like the mean's.
        Comparison resolveRgb{"resolved rgb"}, resolveVar{"resolved variance"},
            resolveLength{"anti-lag history length"};
        std::size_t shortened = 0, lengthMismatches = 0;
        std::size_t outputMismatches = 0;
        for (std::uint32_t y = 0; y < h; ++y)
            for (std::uint32_t x = 0; x < w; ++x) {
                if (!inListedTile(x, y)) continue;
                const std::size_t i = std::size_t{y} * w + x;
                if (!surface.glossy[i]) {
                    // Histories of pixels that are not glossy are defined zeros; their length is
                    // reproject's, untouched by the resolve.
                    outputMismatches += radiance[4 * i] != 0.0f || radiance[4 * i + 1] != 0.0f ||
                                                radiance[4 * i + 2] != 0.0f || variance[i] != 0.0f
                                            ? 1u
                                            : 0u;
                    lengthMismatches += length[i] != inputLength[i] ? 1u : 0u;
                    continue;
                }
                reference::ResolveInputs r;
                for (int dy = -4; dy <= 4; ++dy)
                    for (int dx = -4; dx <= 4; ++dx) {
                        const auto qx = static_cast<std::size_t>(
                            std::clamp<int>(static_cast<int>(x) + dx, 0, int(w) - 1));
                        const auto qy = static_cast<std::size_t>(
                            std::clamp<int>(static_cast<int>(y) + dy, 0, int(h) - 1));
                        const std::size_t q = qy * w + qx,
                                          k = static_cast<std::size_t>((dy + 4) * 9 + dx + 4);
                        r.glossy[k] = surface.glossy[q] != 0;
                        r.prefiltered[k] = rgbAt(prefiltered, q);
                        r.neighbourHistory[k] = rgbAt(reprojected, q);
                        r.neighbourHistoryValid[k] = reprojected[4 * q + 3] > 0.5f;
                    }
                r.variance = prefiltered[4 * i + 3];
                r.average = reference::averageAt(tiles, x, y);
                r.history = rgbAt(reprojected, i);
                r.historyValid = reprojected[4 * i + 3] > 0.5f;
                r.historyLength = inputLength[i];
                r.historyClipScale = denoiser.historyClipScale;
                r.antiLag = denoiser.antiLag;
                r.alpha = surface.alpha[i];
                r.mirrorThreshold = desc.mirrorThreshold;
                const reference::RadianceVariance e = reference::resolvePixel(r);
                const double expectedLength = reference::resolveHistoryLength(r);
                shortened += expectedLength < std::max(r.historyLength, 1.0) ? 1u : 0u;
                const reference::NeighbourhoodStatistics statistics = reference::resolveStatistics(r);
                Rgb move{};
                double varianceMove = 0.0, lengthMove = 0.0;
                for (const double sign : {-1.0, 1.0}) {
                    reference::ResolveInputs probe = r;
                    for (std::size_t c = 0; c < 3; ++c) {
                        const double k = 1e-5 * statistics.meanSquare[c];
                        probe.sigmaOffset[c] =
                            sign * std::min(std::sqrt(k), k / std::max(statistics.sigma[c], 1e-30));
                    }
                    const reference::RadianceVariance moved = reference::resolvePixel(probe);
                    for (std::size_t c = 0; c < 3; ++c)
                        move[c] = std::max(move[c], std::abs(moved.rgb[c] - e.rgb[c]));
                    varianceMove = std::max(varianceMove, std::abs(moved.variance - e.variance));
                    lengthMove = std::max(lengthMove,
                                          std::abs(reference::resolveHistoryLength(probe) - expectedLength));
                }
                for (std::size_t c = 0; c < 3; ++c)
                    resolveRgb.check(radiance[4 * i + c], e.rgb[c], maxAbs(e.rgb), 1e-4 + fp16.relative,
                                     1e-5 + fp16.absolute + move[c], x, y, c);
                resolveVar.check(variance[i], e.variance, e.variance, 1e-4 + fp16.relative,
                                 1e-5 + fp16.absolute + varianceMove, x, y, 0);
                resolveLength.check(length[i], expectedLength, expectedLength, 1e-4 + fp16.relative,
                                    1e-5 + fp16.absolute + lengthMove, x, y, 0);
                // The effect's output is the same value, written over sssr_radiance.
                for (std::size_t c = 0; c < 3; ++c)
                    outputMismatches += out.radiance[4 * i + c] != radiance[4 * i + c] ? 1u : 0u;
            }

        for (const Comparison* comparison :
             {&averages, &prefilterRgb, &prefilterVar, &resolveRgb, &resolveVar, &resolveLength}) {
            INFO(comparison->what << ": " << comparison->failed << " of " << comparison->checked
                                  << " outside tolerance, worst error / tolerance " << comparison->worst
                                  << "\n"
                                  << comparison->first.str());
            CHECK(comparison->checked > 0u);
            CHECK(comparison->failed == 0u);
        }
        CHECK(outputMismatches == 0u);
        CHECK(markMismatches == 0u);
        CHECK(lengthMismatches == 0u);
        totalShortened += shortened;
        const Comparison* all[] = {&averages,   &prefilterRgb, &prefilterVar,
                                   &resolveRgb, &resolveVar,   &resolveLength};
        for (std::size_t k = 0; k < 6; ++k) worst[k] = std::max(worst[k], all[k]->worst);
    }
    // The comparison covers lengths the anti-lag shortened, not only untouched ones: on this
    // static view, where young histories (a few frames) sometimes stray beyond the tolerance.
    CHECK(totalShortened > 0u);
    WARN((half ? "16-bit" : "32-bit")
         << " storage: worst error / tolerance over " << kFrames << " frames: tile averages " << worst[0]
         << ", prefilter rgb " << worst[1] << " variance " << worst[2] << ", resolve rgb " << worst[3]
         << " variance " << worst[4] << " history length " << worst[5] << " (" << totalShortened
         << " pixel-frames shortened by the anti-lag)");
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

} // namespace
