// SSSR on simulated scenes (harness/scene): with a static camera, the per-pixel average of
// many frames of noisy SSSR samples against the capture's reference.reflection (docs/scenes.md:
// the GGX-VNDF mean of the radiance arriving along reflected rays, ray traced), over the pixels
// whose reflected geometry is on screen; and the half-resolution mode's coverage and stability.
#include "support/gpu_test_context.h"

#include "replay/replay_sssr.h"
#include "scene/scene_file.h"
#include "scene/scene_simulate.h"

#include <gpu/gpu_sssr_runner.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>

using namespace glint;

namespace {

constexpr std::uint32_t kWidth = 160, kHeight = 90;
constexpr std::uint32_t kFrames = 32;
constexpr double kLuminance[3] = {0.2126, 0.7152, 0.0722}; // Rec. 709

struct StaticCapture {
    SssrDesc desc;
    gpu::SssrFrameInputs inputs;
    std::vector<float> reference; // RGB
    std::vector<bool> glossy;     // from the capture, independently of the classification
    std::size_t glossyCount = 0;
};

// Frame 0 of a bundled scene at kWidth x kHeight with a reference of `spp` samples per pixel.
StaticCapture simulateStatic(const std::string& name, std::uint32_t spp) {
    scene::Scene scene = scene::loadScene(std::string(GLINT_SOURCE_DIR "/harness/scenes/") + name);
    scene.width = kWidth;
    scene.height = kHeight;
    scene.frameCount = 1;
    scene.reference.reflections = spp > 0;
    scene.reference.samplesPerPixel = std::max(spp, 1u);
    if (const char* t = std::getenv("GLINT_T_SEED")) scene.seed = static_cast<std::uint32_t>(std::stoul(t)); // TEMP
    if (const char* t = std::getenv("GLINT_T_SPP")) scene.reference.samplesPerPixel = static_cast<std::uint32_t>(std::stoul(t)); // TEMP
    const auto t0 = std::chrono::steady_clock::now();
    const scene::Simulation sim = scene::simulate(test::testContext(), scene);
    WARN("simulate " << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s");
    REQUIRE(sim.frames.size() == 1u);
    REQUIRE(sim.environment.has_value());
    StaticCapture capture;
    capture.desc.samplesPerQuad = 4;
    capture.desc.occupancyExitFraction = 0.0f;
    if (const char* t = std::getenv("GLINT_T_THICK")) capture.desc.thickness = std::stof(t); // TEMP
    replay::sssrFromFrame(sim.frames[0], *sim.environment, capture.desc, capture.inputs);
    if (spp > 0) capture.reference = replay::layerChannels(sim.frames[0], "reference.reflection", 3);
    // Glossy = on a surface (standard or reversed depth away from its far value) with GGX alpha
    // below the threshold, decoded from the capture's roughness as docs/scenes.md defines it.
    const bool reversed = capture.desc.depth == DepthConvention::Reversed;
    const std::size_t count = std::size_t{kWidth} * kHeight;
    capture.glossy.assign(count, false);
    for (std::size_t i = 0; i < count; ++i) {
        const float depth = capture.inputs.depth[i];
        const bool surface = reversed ? depth > 1e-6f : depth < 1.0f - 1e-6f;
        const float raw = std::clamp(capture.inputs.material[4 * i], 0.0f, 1.0f);
        const float alpha = capture.desc.roughnessIsPerceptual ? raw * raw : raw;
        capture.glossy[i] = surface && alpha < capture.desc.roughnessThreshold;
        capture.glossyCount += capture.glossy[i] ? 1u : 0u;
    }
    return capture;
}

struct Average {
    std::vector<double> rgb;         // mean radiance over the frames
    std::vector<double> confidence;  // mean confidence
    std::vector<float> firstRgb;     // frame 0 alone
    std::vector<float> lastRadiance; // RGBA of the last frame
    bool finite = true;
    float maxConfidence = 0.0f;
};

Average runFrames(gpu::SssrRunner& runner, SssrDesc desc, std::uint32_t frames) {
    const std::size_t count = std::size_t{kWidth} * kHeight;
    Average average;
    average.rgb.assign(3 * count, 0.0);
    average.confidence.assign(count, 0.0);
    for (std::uint32_t frame = 0; frame < frames; ++frame) {
        desc.frameIndex = frame;
        runner.run(desc);
        const gpu::SssrFrameOutputs out = runner.readback();
        REQUIRE(out.radiance.size() == 4 * count);
        for (std::size_t i = 0; i < count; ++i) {
            for (std::size_t c = 0; c < 4; ++c)
                average.finite = average.finite && std::isfinite(out.radiance[4 * i + c]);
            average.finite = average.finite && std::isfinite(out.confidence[i]);
            average.maxConfidence = std::max(average.maxConfidence, out.confidence[i]);
            for (std::size_t c = 0; c < 3; ++c)
                average.rgb[3 * i + c] += double(out.radiance[4 * i + c]) / double(frames);
            average.confidence[i] += double(out.confidence[i]) / double(frames);
        }
        if (frame == 0) {
            average.firstRgb.resize(3 * count);
            for (std::size_t i = 0; i < count; ++i)
                for (std::size_t c = 0; c < 3; ++c) average.firstRgb[3 * i + c] = out.radiance[4 * i + c];
        }
        if (frame + 1 == frames) average.lastRadiance = out.radiance;
    }
    return average;
}

// Luminance-weighted relative error, (sum_c w_c |a_c - r_c|) / max(lum(r), 0.05), averaged over
// the mask. The floor keeps near-black reference pixels from dominating.
template <typename T>
double relativeError(const std::vector<T>& value, const std::vector<float>& reference, const std::vector<bool>& mask,
                     double cap = 1e30, double* outlierFraction = nullptr, double* median = nullptr) {
    std::vector<double> errors;
    for (std::size_t i = 0; i < mask.size(); ++i) {
        if (!mask[i]) continue;
        double difference = 0.0, luminance = 0.0;
        for (std::size_t c = 0; c < 3; ++c) {
            difference += kLuminance[c] * std::abs(double(value[3 * i + c]) - double(reference[3 * i + c]));
            luminance += kLuminance[c] * double(reference[3 * i + c]);
        }
        errors.push_back(difference / std::max(luminance, 0.05));
    }
    if (errors.empty()) return 0.0;
    double sum = 0.0, outliers = 0.0;
    for (const double e : errors) {
        sum += std::min(e, cap);
        outliers += e > 1.0 ? 1.0 : 0.0;
    }
    if (outlierFraction) *outlierFraction = outliers / double(errors.size());
    if (median) {
        std::sort(errors.begin(), errors.end());
        *median = errors[errors.size() / 2];
    }
    return sum / double(errors.size());
}

// TEMP dump
template <typename T> void dumpPfm(const std::string& file, const std::vector<T>& v, std::size_t stride) {
    std::FILE* f = std::fopen(("/tmp/h_conv_dump/" + file + ".pfm").c_str(), "wb");
    if (!f) return;
    std::fprintf(f, "PF\n%u %u\n-1.0\n", kWidth, kHeight);
    for (int y = int(kHeight) - 1; y >= 0; --y)
        for (std::uint32_t x = 0; x < kWidth; ++x)
            for (std::size_t c = 0; c < 3; ++c) {
                const std::size_t i = std::size_t(y) * kWidth + x;
                const float value = float(v[i * stride + std::min(c, stride - 1)]);
                std::fwrite(&value, 4, 1, f);
            }
    std::fclose(f);
}

struct ConvergenceNumbers {
    double coverage = 0;  // mask / glossy pixels
    std::size_t mask = 0; // pixels
    double first = 0, converged = 0, environmentOnly = 0;
};

ConvergenceNumbers measureConvergence(const std::string& name, std::uint32_t spp) {
    const StaticCapture capture = simulateStatic(name, spp);
    REQUIRE(capture.glossyCount > 500u);
    { // TEMP debug
        SssrDesc d = capture.desc;
        d.debugOutput = true;
        gpu::SssrRunner dbg(test::testContext(), d);
        dbg.upload(capture.inputs);
        dbg.run(d);
        const gpu::SssrFrameOutputs o = dbg.readback();
        std::FILE* f = std::fopen(("/tmp/h_conv_dump/" + name + ".rayinfo.txt").c_str(), "w");
        for (std::size_t i = 0; i < std::size_t{kWidth} * kHeight; ++i)
            std::fprintf(f, "%zu %zu %g %g %g %g conf %g rad %g %g %g dist %g alpha %g depth %.9g n %g %g %g\n", i % kWidth, i / kWidth, double(o.rayInfo[4 * i]),
                         double(o.rayInfo[4 * i + 1]), double(o.rayInfo[4 * i + 2]), double(o.rayInfo[4 * i + 3]), double(o.confidence[i]),
                         double(o.radiance[4 * i]), double(o.radiance[4 * i + 1]), double(o.radiance[4 * i + 2]), double(o.radiance[4 * i + 3]),
                         double(o.roughness[i]), double(capture.inputs.depth[i]), double(capture.inputs.normals[4*i]), double(capture.inputs.normals[4*i+1]), double(capture.inputs.normals[4*i+2]));
        std::fclose(f);
    }
    gpu::SssrRunner runner(test::testContext(), capture.desc);
    runner.upload(capture.inputs);
    const Average traced = runFrames(runner, capture.desc, kFrames);
    SssrDesc missing = capture.desc;
    missing.maxTraversalIterations = 1; // one step never advances the 2 pixels a hit needs
    const Average environment = runFrames(runner, missing, kFrames);
    CHECK(traced.finite);
    CHECK(environment.finite);
    // Every ray of the baseline missed: its radiance is the environment alone.
    CHECK(environment.maxConfidence == 0.0f);

    // The mask: glossy pixels whose screen had an answer for nearly every sample (mean
    // confidence > 0.9). This is fair, not circular: confidence says only that the ray met an
    // on-screen surface (and how well it fits the depth), not what radiance it brought back,
    // while the reference ray traces the whole scene, so it also sees geometry that is off
    // screen or hidden behind other geometry, which no screen-space method can find. On the
    // pixels left out SSSR returns the environment by design. A wrong hit (thickness, a
    // wrong surface) still has a high confidence, so it stays in the mask and in the error.
    std::vector<bool> mask(capture.glossy.size(), false);
    ConvergenceNumbers numbers;
    for (std::size_t i = 0; i < mask.size(); ++i) {
        mask[i] = capture.glossy[i] && traced.confidence[i] > 0.9;
        numbers.mask += mask[i] ? 1u : 0u;
    }
    {
        dumpPfm(name + std::string(std::getenv("GLINT_T_TAG") ? std::getenv("GLINT_T_TAG") : "") + ".avg", traced.rgb, 3);
        dumpPfm(name + std::string(std::getenv("GLINT_T_TAG") ? std::getenv("GLINT_T_TAG") : "") + ".first", traced.firstRgb, 3);
        dumpPfm(name + std::string(std::getenv("GLINT_T_TAG") ? std::getenv("GLINT_T_TAG") : "") + ".env", environment.rgb, 3);
        dumpPfm(name + std::string(std::getenv("GLINT_T_TAG") ? std::getenv("GLINT_T_TAG") : "") + ".ref", capture.reference, 3);
        dumpPfm(name + std::string(std::getenv("GLINT_T_TAG") ? std::getenv("GLINT_T_TAG") : "") + ".conf", traced.confidence, 1);
        std::vector<float> m(mask.size()), g(mask.size());
        for (std::size_t i = 0; i < mask.size(); ++i) {
            m[i] = mask[i];
            g[i] = capture.glossy[i];
        }
        dumpPfm(name + std::string(std::getenv("GLINT_T_TAG") ? std::getenv("GLINT_T_TAG") : "") + ".mask", m, 1);
        dumpPfm(name + std::string(std::getenv("GLINT_T_TAG") ? std::getenv("GLINT_T_TAG") : "") + ".glossy", g, 1);
        dumpPfm(name + std::string(std::getenv("GLINT_T_TAG") ? std::getenv("GLINT_T_TAG") : "") + ".color", capture.inputs.color, 4);
    }
    numbers.coverage = double(numbers.mask) / double(capture.glossyCount);
    numbers.first = relativeError(traced.firstRgb, capture.reference, mask);
    numbers.converged = relativeError(traced.rgb, capture.reference, mask);
    numbers.environmentOnly = relativeError(environment.rgb, capture.reference, mask);
    { // TEMP stats
        std::vector<bool> glossyMask = mask, mirrorMask = mask;
        double meanConf = 0;
        for (std::size_t i = 0; i < mask.size(); ++i) {
            const float r = capture.inputs.material[4 * i];
            const bool mirror = r * r < 1e-4f;
            glossyMask[i] = mask[i] && !mirror;
            mirrorMask[i] = mask[i] && mirror;
            if (mask[i]) meanConf += traced.confidence[i];
        }
        for (const auto& [label, m] : {std::pair{"all", &mask}, std::pair{"nonmirror", &glossyMask}, std::pair{"mirror", &mirrorMask}}) {
            double o1 = 0, oN = 0, oE = 0, m1 = 0, mN = 0, mE = 0;
            const double c1 = relativeError(traced.firstRgb, capture.reference, *m, 1.0, &o1, &m1);
            const double cN = relativeError(traced.rgb, capture.reference, *m, 1.0, &oN, &mN);
            const double cE = relativeError(environment.rgb, capture.reference, *m, 1.0, &oE, &mE);
            WARN(name << " " << label << " n=" << std::count(m->begin(), m->end(), true) << " capped: 1f " << c1 << " Nf " << cN << " env " << cE
                      << " | uncapped 1f " << relativeError(traced.firstRgb, capture.reference, *m) << " Nf "
                      << relativeError(traced.rgb, capture.reference, *m) << " env "
                      << relativeError(environment.rgb, capture.reference, *m) << " | median 1f " << m1 << " Nf " << mN
                      << " env " << mE << " | >1 frac 1f " << o1 << " Nf " << oN << " env " << oE);
        }
        WARN("mean conf in mask " << meanConf / double(numbers.mask));
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
    return numbers;
}

} // namespace

TEST_CASE("static glossy room: the frame average converges to the reference where the screen has the answer",
          "[sssr][convergence]") {
    const ConvergenceNumbers n = measureConvergence("glossy_room.toml", 128);
    CHECK(n.mask > 500u);
    CHECK(n.converged < n.first * 0.6);
    CHECK(n.converged < n.environmentOnly * 0.5);
}

TEST_CASE(
    "static mirror corridor: the frame average converges to the reference where the screen has the answer",
    "[sssr][convergence]") {
    const ConvergenceNumbers n = measureConvergence("mirror_corridor.toml", 128);
    CHECK(n.mask > 500u);
    CHECK(n.converged < n.first * 0.6);
    CHECK(n.converged < n.environmentOnly * 0.5);
}

namespace {

std::vector<std::uint32_t> tracedPixels(const gpu::SssrFrameOutputs& out) {
    std::vector<std::uint32_t> pixels;
    for (const std::uint32_t entry : out.rayList) // x in bits 0-14, y in bits 15-28
        pixels.push_back((entry >> 15 & 0x3FFFu) * kWidth + (entry & 0x7FFFu));
    return pixels;
}

// Mean absolute luminance change of the raw radiance between consecutive frames, over the
// glossy pixels, relative to their mean luminance.
double frameToFrameChange(gpu::SssrRunner& runner, SssrDesc desc, const std::vector<bool>& glossy,
                          std::uint32_t frames, bool& finite) {
    std::vector<double> previous;
    double change = 0.0, level = 0.0;
    for (std::uint32_t frame = 0; frame < frames; ++frame) {
        desc.frameIndex = frame;
        runner.run(desc);
        const gpu::SssrFrameOutputs out = runner.readback();
        std::vector<double> luminance(glossy.size(), 0.0);
        for (std::size_t i = 0; i < glossy.size(); ++i) {
            for (std::size_t c = 0; c < 3; ++c) {
                finite = finite && std::isfinite(out.radiance[4 * i + c]);
                luminance[i] += kLuminance[c] * double(out.radiance[4 * i + c]);
            }
            if (!glossy[i]) continue;
            level += luminance[i];
            if (!previous.empty()) change += std::abs(luminance[i] - previous[i]);
        }
        previous = std::move(luminance);
    }
    const double pixels = double(std::count(glossy.begin(), glossy.end(), true));
    return (change / (pixels * (frames - 1))) / (level / (pixels * frames));
}

} // namespace

TEST_CASE("half resolution traces every glossy pixel once in four frames with a quarter of the rays",
          "[sssr][half]") {
    const StaticCapture capture = simulateStatic("glossy_room.toml", 0);
    REQUIRE(capture.glossyCount > 500u);
    gpu::SssrRunner runner(test::testContext(), capture.desc);
    runner.upload(capture.inputs);

    // Full resolution with 4 samples per quad: exactly the glossy pixels trace.
    runner.run(capture.desc);
    const std::vector<std::uint32_t> full = tracedPixels(runner.readback());
    CHECK(full.size() == capture.glossyCount);

    // Bounds from the rule alone: a quad with a glossy pixel traces at least one ray (its chosen
    // pixel, or every glossy pixel when the chosen one is not glossy), and at most one per
    // fully glossy quad plus one per glossy pixel of a partly glossy quad.
    std::size_t quadsWithGlossy = 0, upperBound = 0;
    for (std::uint32_t qy = 0; qy < kHeight / 2; ++qy)
        for (std::uint32_t qx = 0; qx < kWidth / 2; ++qx) {
            std::size_t n = 0;
            for (std::uint32_t k = 0; k < 4; ++k)
                n += capture.glossy[(2 * qy + k / 2) * kWidth + 2 * qx + k % 2] ? 1u : 0u;
            quadsWithGlossy += n > 0 ? 1u : 0u;
            upperBound += n == 4 ? 1u : n;
        }

    SssrDesc half = capture.desc;
    half.halfResolution = true;
    std::vector<int> tracedCount(capture.glossy.size(), 0);
    for (std::uint32_t frame = 0; frame < 4; ++frame) {
        half.frameIndex = 100 + frame; // any four consecutive frames
        runner.run(half);
        const std::vector<std::uint32_t> pixels = tracedPixels(runner.readback());
        INFO("frame " << half.frameIndex << ": " << pixels.size() << " rays, full resolution "
                      << full.size());
        CHECK(pixels.size() >= quadsWithGlossy);
        CHECK(pixels.size() <= upperBound);
        CHECK(std::set<std::uint32_t>(pixels.begin(), pixels.end()).size() == pixels.size());
        for (const std::uint32_t p : pixels) {
            REQUIRE(p < tracedCount.size());
            CHECK(capture.glossy[p]);
            ++tracedCount[p];
        }
        WARN("half resolution, frame " << half.frameIndex << ": " << pixels.size()
                                       << " rays = " << double(pixels.size()) / double(full.size())
                                       << " of full resolution (" << full.size() << ")");
    }
    std::size_t untraced = 0;
    for (std::size_t i = 0; i < tracedCount.size(); ++i) untraced += capture.glossy[i] && tracedCount[i] == 0;
    CHECK(untraced == 0u);

    // Stability: half resolution changes the pixel that traces each frame, so its raw output
    // changes more from frame to frame than one ray per quad at full resolution. Recorded in
    // the docs; only finiteness is checked.
    bool finite = true;
    SssrDesc quarter = capture.desc;
    quarter.samplesPerQuad = 1;
    const double fullChange = frameToFrameChange(runner, quarter, capture.glossy, 8, finite);
    const double halfChange = frameToFrameChange(runner, half, capture.glossy, 8, finite);
    CHECK(finite);
    CHECK(std::isfinite(fullChange));
    CHECK(std::isfinite(halfChange));
    WARN("frame-to-frame mean |change| of the raw luminance over glossy pixels, relative to their mean: full "
         "resolution (1 sample per quad) "
         << fullChange << ", half resolution " << halfChange);
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
