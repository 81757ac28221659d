// GGX visible-normal sampling (hlsl/glint/common/glint_ggx.hlsli) on the device, through the
// harness shader test_ggx_sample, against densities written here in double from the textbook
// formulas (Heitz 2018; Dupuy and Benyoub 2023; docs/sssr.md, "Intersection": Direction):
//   - chi-square goodness of fit of the sampled reflections L over the whole sphere, with and
//     without Frostbite's importance-sample bias, and the same statistic failing for a wrong
//     alpha or a wrong bias (the test can tell);
//   - the reference densities integrate to one;
//   - finite results in the hard cases, the bent normal and the tangent frame.
#include "glint/glint_pass.h"
#include "glint/vulkan/vk_executor.h"
#include "scene/scene_shaders.h"
#include "support/gpu_test_context.h"

#include <gpu/gpu_plan_runner.h>
#include <gpu/gpu_transfer.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <random>
#include <span>
#include <utility>
#include <vector>

using namespace glint;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr std::uint32_t kSamples = 1u << 18;
constexpr std::uint32_t kGroupSize = 64; // test_ggx_sample.cs.hlsl's [numthreads]

// The shader's records (std430: float4 members, no padding between them).
struct GgxInput {
    std::array<float, 4> viewAlpha; // V, alpha
    std::array<float, 4> uBias;     // u.x, u.y, bias, unused
    std::array<float, 4> normal;    // n for the bend and the tangent frame
};
struct GgxOutput {
    std::array<float, 4> reflection; // L, ReflectionPdf(V.z, H.z)
    std::array<float, 4> microfacet; // H, SmithG1(V.z)
    std::array<float, 4> bent;       // BendNormalTowardView(n, V), D(H.z)
    std::array<float, 4> tangent;    // t, ToWorld(ToLocal(V)).x
    std::array<float, 4> bitangent;  // b, ToLocal(V).z
};
static_assert(sizeof(GgxInput) == 48 && sizeof(GgxOutput) == 80);

std::vector<GgxOutput> runGgxShader(const std::vector<GgxInput>& inputs) {
    gpu::Context& context = test::testContext();
    const auto count = static_cast<std::uint32_t>(inputs.size());
    EffectPlan plan;
    plan.effect = "test_ggx";
    plan.buffers = {{"ggx_inputs", count * sizeof(GgxInput), false},
                    {"ggx_outputs", count * sizeof(GgxOutput), false}};
    Pass pass;
    pass.name = "sample";
    pass.pipeline = "test_ggx_sample";
    pass.groupSize[0] = kGroupSize;
    pass.groupSize[1] = 1;
    pass.uses = {{"g_glint_ggx_inputs", "ggx_inputs", Access::Read},
                 {"g_glint_ggx_outputs", "ggx_outputs", Access::Write}};
    pass.constantsBinding = "g_glint_constants";
    const std::array<std::uint32_t, 4> constants = {count, 0, 0, 0};
    pass.constants.resize(sizeof(constants));
    std::memcpy(pass.constants.data(), constants.data(), sizeof(constants));
    pass.dispatch = DirectDispatch{(count + kGroupSize - 1) / kGroupSize, 1, 1};
    plan.passes.push_back(pass);

    struct Owned { // released even when a REQUIRE or the executor throws
        gpu::Context& context;
        gpu::PlanResources resources;
        vk::Executor executor;
        ~Owned() {
            vk::destroyExecutor(executor);
            gpu::destroyPlanResources(context, resources);
        }
    } owned{context, gpu::createPlanResources(context, plan), vk::createExecutor(context.device)};
    owned.executor.findShader = scene::findShader;
    gpu::uploadBuffer(context, owned.resources.buffers.at("ggx_inputs"), std::span<const GgxInput>(inputs));
    gpu::executePlan(context, owned.executor, plan, gpu::resourceTable(owned.resources));
    const std::vector<std::byte> bytes =
        gpu::readbackBuffer(context, owned.resources.buffers.at("ggx_outputs"));
    REQUIRE(bytes.size() == count * sizeof(GgxOutput));
    std::vector<GgxOutput> outputs(count);
    std::memcpy(outputs.data(), bytes.data(), bytes.size());
    return outputs;
}

// ---- double-precision references, from the formulas, not from the shader -----------------

struct Dir {
    double x = 0, y = 0, z = 0;
};
Dir operator+(Dir a, Dir b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
Dir operator*(double s, Dir a) {
    return {s * a.x, s * a.y, s * a.z};
}
double dot(Dir a, Dir b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
Dir cross(Dir a, Dir b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double length(Dir a) {
    return std::sqrt(dot(a, a));
}
Dir normalized(Dir a) {
    return (1.0 / length(a)) * a;
}
Dir xyz(const std::array<float, 4>& v) {
    return {v[0], v[1], v[2]};
}

double ggxD(double cosH, double alpha) {
    if (cosH <= 0) return 0;
    const double a2 = alpha * alpha;
    const double k = cosH * cosH * (a2 - 1) + 1;
    return a2 / (kPi * k * k);
}

double smithG1(double cosV, double alpha) {
    const double tan2 = (1 - cosV * cosV) / (cosV * cosV);
    return 2 / (1 + std::sqrt(1 + alpha * alpha * tan2));
}

// The sampler's setting: V (local, unit, V.z > 0), alpha, bias.
struct Lobe {
    Dir view;
    double alpha = 0;
    double bias = 0;
};

// Density of L per steradian without bias: G1(V) D(H) / (4 N.V) with H = normalize(V + L),
// zero where H.z <= 0 (no microfacet there), i.e. for L.z <= -V.z.
double unbiasedDensity(const Lobe& lobe, Dir l) {
    const Dir sum = lobe.view + l;
    const double sumLength = length(sum);
    if (sumLength == 0) return 0;
    const double hz = sum.z / sumLength;
    if (hz <= 0) return 0;
    return smithG1(lobe.view.z, lobe.alpha) * ggxD(hz, lobe.alpha) / (4 * lobe.view.z);
}

// With bias b the sampler draws the cap point c uniformly by area on the part of the
// stretched cap {c.z >= -Vh.z} with z in (zMin, 1], zMin = 1 - (1 - b)(1 + Vh.z) =
// b - (1 - b) Vh.z, a fraction (1 - zMin) / (1 + Vh.z) = 1 - b of the cap's area (area ~
// height), and maps c to L exactly as without bias. So its density is the unbiased one on the
// reachable part, divided by 1 - b. Inverting the map for a given L: H = normalize(V + L); the
// unstretch H ~ (a Nh.x, a Nh.y, Nh.z) gives the direction of Nh, n = normalize(H.x / a,
// H.y / a, H.z); Nh = c + Vh with |c| = 1 means Nh = t n with |t n - Vh| = 1, so t = 2 (n.Vh)
// and c = 2 (n.Vh) n - Vh (Vh mirrored about n). L is reachable iff c.z >= zMin. (Directions
// outside the unbiased support count as reachable: their density is zero anyway.)
bool reachableWithBias(const Lobe& lobe, Dir l) {
    const Dir sum = lobe.view + l;
    if (lobe.bias == 0 || length(sum) == 0 || sum.z <= 0) return true;
    const Dir h = normalized(sum);
    const double a = lobe.alpha;
    const Dir vh = normalized({a * lobe.view.x, a * lobe.view.y, lobe.view.z});
    const Dir n = normalized({h.x / a, h.y / a, h.z});
    const double capZ = 2 * dot(n, vh) * n.z - vh.z;
    return capZ >= lobe.bias - (1 - lobe.bias) * vh.z;
}

double reflectionDensity(const Lobe& lobe, Dir l) {
    return reachableWithBias(lobe, l) ? unbiasedDensity(lobe, l) / (1 - lobe.bias) : 0;
}

Dir direction(double cosTheta, double phi) {
    const double sinTheta = std::sqrt(std::max(0.0, 1 - cosTheta * cosTheta));
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

// The midpoint rule on an m x m grid over [cosTop, cosBottom] x [phi0, phi1]: each cell's
// exact solid angle (d cos theta d phi) times the density at its centre.
double cellIntegral(const Lobe& lobe, double cosTop, double cosBottom, double phi0, double phi1,
                    std::uint32_t m) {
    double sum = 0;
    const double dCos = (cosTop - cosBottom) / m, dPhi = (phi1 - phi0) / m;
    for (std::uint32_t i = 0; i < m; ++i)
        for (std::uint32_t j = 0; j < m; ++j)
            sum += reflectionDensity(lobe, direction(cosTop - (i + 0.5) * dCos, phi0 + (j + 0.5) * dPhi));
    return sum * dCos * dPhi;
}

// Bins over (cos theta, phi) on the whole sphere. Ring edges are cosines of equal steps in
// theta over [0, thetaMax], where thetaMax = acos(-V.z) is the edge of the density's support
// (L.z > -V.z); it is a ring edge so that no bin straddles that discontinuity. Every direction
// beyond it, where the density is zero, falls into one extra bin (index rings * sectors).
// Steps of 0.4 alpha keep several bins across the narrowest lobe.
struct SphereBins {
    std::uint32_t rings = 0, sectors = 0;
    double thetaMax = 0;
    std::size_t count() const { return std::size_t{rings} * sectors + 1; }
};

SphereBins binsFor(const Lobe& lobe) {
    SphereBins bins;
    bins.thetaMax = std::acos(-lobe.view.z);
    bins.rings =
        static_cast<std::uint32_t>(std::clamp(std::lround(bins.thetaMax / (0.4 * lobe.alpha)), 24L, 160L));
    bins.sectors = 2 * bins.rings;
    return bins;
}

std::size_t binOf(const SphereBins& bins, Dir l) {
    const Dir d = normalized(l);
    const double theta = std::acos(std::clamp(d.z, -1.0, 1.0));
    if (theta >= bins.thetaMax) return std::size_t{bins.rings} * bins.sectors;
    double phi = std::atan2(d.y, d.x);
    if (phi < 0) phi += 2 * kPi;
    const auto ring =
        std::min(static_cast<std::uint32_t>(theta / bins.thetaMax * bins.rings), bins.rings - 1);
    const auto sector =
        std::min(static_cast<std::uint32_t>(phi / (2 * kPi) * bins.sectors), bins.sectors - 1);
    return std::size_t{ring} * bins.sectors + sector;
}

// Probability of each bin: the density integrated with the midpoint rule over a sub x sub
// grid of cells per bin (error O(cell^2) relative where the density is smooth). The only
// discontinuities are the support's edge, which is a ring edge (binsFor), and the bias
// indicator's edge, which crosses cells along a curve. A cell whose corners disagree about
// the indicator is integrated on a further 64 x 64 grid: the midpoint rule on an indicator
// errs by up to half a cell along the edge, and along a ring-shaped edge (V = N) those errors
// all have one sign, so without this the expected counts of whole rings are off by percents
// (the chi-square for V = N, bias 0.3 failed at 758 for 416 cells); with it, 4x finer grids
// change the statistics by < 1.
std::vector<double> binProbabilities(const SphereBins& bins, const Lobe& lobe) {
    const std::uint32_t sub = 12, fine = 64;
    std::vector<double> probabilities(bins.count(), 0.0);
    const std::uint32_t cellRings = bins.rings * sub, cellSectors = bins.sectors * sub;
    const double dPhi = 2 * kPi / cellSectors;
    const auto ringCos = [&](std::uint32_t i) { return std::cos(bins.thetaMax * i / cellRings); };
    std::vector<char> top(cellSectors + 1), bottom(cellSectors + 1);
    const auto cornerRow = [&](std::uint32_t i, std::vector<char>& row) {
        if (lobe.bias == 0) return; // no indicator: rows stay equal
        for (std::uint32_t j = 0; j <= cellSectors; ++j)
            row[j] = reachableWithBias(lobe, direction(ringCos(i), j * dPhi)) ? 1 : 0;
    };
    cornerRow(0, top);
    for (std::uint32_t i = 0; i < cellRings; ++i) {
        cornerRow(i + 1, bottom);
        const double cosTop = ringCos(i), cosBottom = ringCos(i + 1);
        const double cosMid = 0.5 * (cosTop + cosBottom);
        double* ring = &probabilities[std::size_t{i / sub} * bins.sectors];
        for (std::uint32_t j = 0; j < cellSectors; ++j) {
            const bool mixed = top[j] != top[j + 1] || top[j] != bottom[j] || top[j] != bottom[j + 1];
            ring[j / sub] += mixed ? cellIntegral(lobe, cosTop, cosBottom, j * dPhi, (j + 1) * dPhi, fine)
                                   : reflectionDensity(lobe, direction(cosMid, (j + 0.5) * dPhi)) *
                                         (cosTop - cosBottom) * dPhi;
        }
        std::swap(top, bottom);
    }
    return probabilities;
}

// 0.999 quantile of chi-square with k degrees of freedom (Wilson-Hilferty: (X/k)^(1/3) is
// close to normal with mean 1 - 2/(9k) and variance 2/(9k); z = 3.0902 is the normal 0.999
// quantile). Accurate to ~0.1% for the k >= 65 used here.
double chiSquareBound(double k) {
    const double z = 3.090232306167813;
    const double v = 2 / (9 * k);
    return k * std::pow(1 - v + z * std::sqrt(v), 3);
}

struct ChiSquare {
    double statistic = 0;
    double bound = 0;
    std::size_t cells = 0;
};

// Pearson's statistic; bins expected to hold fewer than 5 samples are pooled into one cell
// (with the next-smallest bins until the pool expects 5), so that the chi-square
// approximation holds and samples where the density is (nearly) zero still count.
ChiSquare chiSquare(const std::vector<std::uint64_t>& observed, const std::vector<double>& probabilities) {
    std::vector<std::size_t> order(observed.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return probabilities[a] < probabilities[b]; });
    ChiSquare result;
    double pooledExpected = 0, pooledObserved = 0;
    bool pooling = false;
    for (std::size_t index : order) {
        const double expected = probabilities[index] * kSamples;
        const auto count = static_cast<double>(observed[index]);
        if (expected < 5 || (pooling && pooledExpected < 5)) {
            pooledExpected += expected;
            pooledObserved += count;
            pooling = true;
            continue;
        }
        result.statistic += (count - expected) * (count - expected) / expected;
        ++result.cells;
    }
    if (pooling) {
        result.statistic +=
            (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
        ++result.cells;
    }
    result.bound = chiSquareBound(static_cast<double>(result.cells - 1));
    return result;
}

Lobe lobeAt(double alpha, double thetaDegrees, double bias) {
    // An azimuth off the x axis so that the sampler's handling of both tangent components is
    // exercised. V goes through float exactly as the shader sees it.
    const double theta = thetaDegrees * kPi / 180, phi = 0.7;
    Lobe lobe;
    lobe.view = {static_cast<float>(std::sin(theta) * std::cos(phi)),
                 static_cast<float>(std::sin(theta) * std::sin(phi)), static_cast<float>(std::cos(theta))};
    lobe.alpha = static_cast<float>(alpha);
    lobe.bias = static_cast<float>(bias);
    return lobe;
}

// kSamples records for one lobe with u from a 64-bit Mersenne Twister (deterministic seed),
// each uniform the top 24 bits, i.e. exactly representable floats in [0, 1).
std::vector<GgxInput> lobeInputs(const Lobe& lobe, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    const auto uniform = [&rng] { return static_cast<float>(rng() >> 40) * 0x1p-24f; };
    std::vector<GgxInput> inputs(kSamples);
    for (GgxInput& input : inputs) {
        input.viewAlpha = {static_cast<float>(lobe.view.x), static_cast<float>(lobe.view.y),
                           static_cast<float>(lobe.view.z), static_cast<float>(lobe.alpha)};
        const float u1 = uniform();
        input.uBias = {u1, uniform(), static_cast<float>(lobe.bias), 0.0f};
        input.normal = {0.0f, 0.0f, 1.0f, 0.0f};
    }
    return inputs;
}

std::vector<std::uint64_t> histogram(const SphereBins& bins, const std::vector<GgxOutput>& outputs) {
    std::vector<std::uint64_t> counts(bins.count(), 0);
    for (const GgxOutput& output : outputs) ++counts[binOf(bins, xyz(output.reflection))];
    return counts;
}

// The library's pdf, G1 and D at the sampled H against the textbook formulas at the same
// (float) inputs. Only float rounding separates them: ~20 operations, ~1e-6 relative, and
// the stable rewrites in the shader remove the cancellations the textbook forms have in
// float; 1e-4 leaves a wide margin.
double maxRelativeError(const Lobe& lobe, const std::vector<GgxOutput>& outputs) {
    double worst = 0;
    const auto relative = [](double got, double want) {
        return std::abs(got - want) / std::max(want, 1e-30);
    };
    for (const GgxOutput& output : outputs) {
        const double hz = output.microfacet[2];
        const double g1 = smithG1(lobe.view.z, lobe.alpha), d = ggxD(hz, lobe.alpha);
        worst = std::max({worst, relative(output.reflection[3], g1 * d / (4 * lobe.view.z)),
                          relative(output.microfacet[3], g1), relative(output.bent[3], d)});
    }
    return worst;
}

bool allFinite(const GgxOutput& output) {
    for (const auto* v :
         {&output.reflection, &output.microfacet, &output.bent, &output.tangent, &output.bitangent})
        for (float x : *v)
            if (!std::isfinite(x)) return false;
    return true;
}

// The chi-square cases: every (alpha, theta_V) without bias, and with each bias the lobes
// whose bins resolve the narrower biased lobe (alpha >= 0.3 at 0.4 alpha per bin).
constexpr std::array<double, 4> kAlphas = {0.05, 0.3, 0.8, 1.0};
constexpr std::array<double, 3> kViewDegrees = {0.0, 45.0, 80.0};
constexpr std::array<double, 2> kBiases = {0.3, 0.7};
constexpr std::array<std::pair<double, double>, 4> kBiasedLobes = { // (alpha, theta_V degrees)
    {{0.3, 0.0}, {0.3, 45.0}, {0.8, 80.0}, {1.0, 45.0}}};

} // namespace

TEST_CASE(
    "unbiased VNDF reflections follow G1(V) D(H) / (4 N.V) over the whole sphere and a wrong alpha fails",
    "[vndf]") {
    std::uint64_t seed = 1;
    for (double alpha : kAlphas)
        for (double theta : kViewDegrees) {
            const Lobe lobe = lobeAt(alpha, theta, 0.0);
            const std::vector<GgxOutput> outputs = runGgxShader(lobeInputs(lobe, seed++));
            const SphereBins bins = binsFor(lobe);
            const std::vector<std::uint64_t> counts = histogram(bins, outputs);
            const ChiSquare fit = chiSquare(counts, binProbabilities(bins, lobe));
            Lobe wrong = lobe;
            wrong.alpha = 1.3 * lobe.alpha;
            const ChiSquare misfit = chiSquare(counts, binProbabilities(bins, wrong));
            INFO("alpha " << alpha << ", theta_V " << theta << ": chi2 " << fit.statistic << " < "
                          << fit.bound << " (" << fit.cells << " cells); alpha x1.3: " << misfit.statistic
                          << " > " << misfit.bound);
            CHECK(fit.statistic < fit.bound);
            CHECK(misfit.statistic > misfit.bound);
            CHECK(maxRelativeError(lobe, outputs) < 1e-4);
        }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE(
    "biased VNDF reflections follow the density restricted to the reduced cap and the unbiased one fails",
    "[vndf]") {
    std::uint64_t seed = 100;
    for (double bias : kBiases)
        for (const auto& [alpha, theta] : kBiasedLobes) {
            const Lobe lobe = lobeAt(alpha, theta, bias);
            const std::vector<GgxOutput> outputs = runGgxShader(lobeInputs(lobe, seed++));
            const SphereBins bins = binsFor(lobe);
            const std::vector<std::uint64_t> counts = histogram(bins, outputs);
            const ChiSquare fit = chiSquare(counts, binProbabilities(bins, lobe));
            Lobe unbiased = lobe;
            unbiased.bias = 0;
            const ChiSquare misfit = chiSquare(counts, binProbabilities(bins, unbiased));
            INFO("bias " << bias << ", alpha " << alpha << ", theta_V " << theta << ": chi2 " << fit.statistic
                         << " < " << fit.bound << " (" << fit.cells
                         << " cells); as unbiased: " << misfit.statistic << " > " << misfit.bound);
            CHECK(fit.statistic < fit.bound);
            CHECK(misfit.statistic > misfit.bound);
            // The pdf output is the unbiased formula whatever the bias (docs/sssr.md,
            // "Intersection": the stored pdf is bias-free).
            CHECK(maxRelativeError(lobe, outputs) < 1e-4);
        }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

// Checks the references themselves (G1, D, the Jacobian, the bias factor 1 / (1 - b)) and the
// integration the chi-square relies on: a missing factor or a lost part of the sphere shows
// as percents, integration error here is ~1e-4.
TEST_CASE("the reference reflection densities of the chi-square cases integrate to one over the sphere",
          "[vndf]") {
    const auto checkTotal = [](const Lobe& lobe) {
        const std::vector<double> p = binProbabilities(binsFor(lobe), lobe);
        const double total = std::accumulate(p.begin(), p.end(), 0.0);
        INFO("bias " << lobe.bias << ", alpha " << lobe.alpha << ", V.z " << lobe.view.z << ": " << total);
        CHECK(std::abs(total - 1) < 1e-3);
    };
    for (double alpha : kAlphas)
        for (double theta : kViewDegrees) checkTotal(lobeAt(alpha, theta, 0.0));
    for (double bias : kBiases)
        for (const auto& [alpha, theta] : kBiasedLobes) checkTotal(lobeAt(alpha, theta, bias));
}

TEST_CASE("hard inputs give finite samples and densities, alpha 0 mirrors and bias 1 gives the lobe centre",
          "[vndf]") {
    const float grazing = std::sqrt(1.0f - 1e-8f);
    const std::array<std::array<float, 3>, 5> views = {
        {{0, 0, 1}, {grazing, 0, 1e-4f}, {0, -grazing, 1e-4f}, {0.6f, 0, 0.8f}, {0.48f, -0.36f, 0.8f}}};
    const float below1 = 0.99999994f; // the largest float below 1
    std::vector<GgxInput> inputs;
    for (float alpha : {0.0f, 1e-7f, 1e-4f, 0.5f, 1.0f})
        for (const auto& v : views)
            for (float ux : {0.0f, 0.5f, below1})
                for (float uy : {0.0f, 0.5f, below1})
                    for (float bias : {0.0f, 0.3f, 1.0f})
                        inputs.push_back({{v[0], v[1], v[2], alpha}, {ux, uy, bias, 0}, {0, 0, 1, 0}});
    const std::vector<GgxOutput> outputs = runGgxShader(inputs);
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        const GgxInput& in = inputs[i];
        const GgxOutput& out = outputs[i];
        INFO("V (" << in.viewAlpha[0] << ", " << in.viewAlpha[1] << ", " << in.viewAlpha[2] << "), alpha "
                   << in.viewAlpha[3] << ", u (" << in.uBias[0] << ", " << in.uBias[1] << "), bias "
                   << in.uBias[2]);
        REQUIRE(allFinite(out));
        // Float directions are unit to a few ulp; 1e-5 is generous and still catches any
        // missing normalization.
        CHECK(std::abs(length(xyz(out.reflection)) - 1) < 1e-5);
        CHECK(std::abs(length(xyz(out.microfacet)) - 1) < 1e-5);
        CHECK(out.microfacet[2] >= 0.0f);
        CHECK(out.reflection[3] >= 0.0f);
        CHECK(out.microfacet[3] >= 0.0f);
        CHECK(out.microfacet[3] <= 1.0f);
        CHECK(out.bent[3] >= 0.0f);
        const Dir view = xyz(in.viewAlpha);
        const double alpha = std::max(static_cast<double>(in.viewAlpha[3]), 1e-4); // the library's floor
        // u.y = 0 or bias = 1: the cap's pole, c = N, so Nh = N + Vh, the bisector of N and Vh in
        // the stretched space (Dupuy and Benyoub 2023), unstretched. 1e-5: float rounding of a few
        // operations.
        if (in.uBias[1] == 0.0f || in.uBias[2] == 1.0f) {
            const Dir vh = normalized({alpha * view.x, alpha * view.y, view.z});
            const Dir centre = normalized({alpha * vh.x, alpha * vh.y, 1 + vh.z});
            CHECK(length(xyz(out.microfacet) + (-1.0) * centre) < 1e-5);
        }
        // A (floored) mirror with V = N away from the cap's rim: H within ~alpha of N, so L
        // within 2e-4 rad of N, cos > 1 - 2e-8; 1e-6 allows for float.
        if (in.viewAlpha[3] <= 1e-4f && in.viewAlpha[2] == 1.0f && in.uBias[1] <= 0.5f)
            CHECK(static_cast<double>(out.reflection[2]) > 1 - 1e-6);
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE("bending a normal towards the view gives a unit normal with n.V >= 1e-4 in the plane of n and V",
          "[vndf]") {
    const std::array<Dir, 4> views = {{{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, normalized({0.3, -0.5, 0.8})}};
    std::vector<GgxInput> inputs;
    for (const Dir& v : views) {
        // A unit vector across v, from a cross product with whichever axis is least parallel.
        const Dir across = normalized(cross(v, std::abs(v.x) < 0.9 ? Dir{1, 0, 0} : Dir{0, 1, 0}));
        const std::array<Dir, 7> normals = {v,
                                            -1.0 * v,
                                            across,
                                            normalized(across + -1e-3 * v),
                                            normalized(across + 1e-5 * v),
                                            normalized(across + 0.5 * v),
                                            normalized(-1.0 * across + -3.0 * v)};
        for (const Dir& n : normals)
            inputs.push_back(
                {{static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z), 0.5f},
                 {0.5f, 0.5f, 0, 0},
                 {static_cast<float>(n.x), static_cast<float>(n.y), static_cast<float>(n.z), 0}});
    }
    const std::vector<GgxOutput> outputs = runGgxShader(inputs);
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        const Dir v = xyz(inputs[i].viewAlpha), n = xyz(inputs[i].normal), bent = xyz(outputs[i].bent);
        INFO("v (" << v.x << ", " << v.y << ", " << v.z << "), n (" << n.x << ", " << n.y << ", " << n.z
                   << "), bent (" << bent.x << ", " << bent.y << ", " << bent.z << ")");
        REQUIRE(allFinite(outputs[i]));
        CHECK(std::abs(length(bent) - 1) < 1e-5);
        CHECK(dot(bent, v) >= 1e-4);
        // The library bends only below 2e-4 (twice the contract, against rounding) and then
        // to 2e-4: no further than needed. Normals facing V enough come back untouched.
        if (dot(n, v) >= 2e-4) {
            CHECK(length(bent + (-1.0) * n) == 0.0);
        } else {
            CHECK(dot(bent, v) < 3e-4);
            const Dir side = n + (-dot(n, v)) * v;
            if (length(side) > 1e-3) { // n not (anti)parallel to v: stay in their plane, on n's side
                CHECK(std::abs(dot(bent, normalized(cross(n, v)))) < 1e-5);
                CHECK(dot(bent, side) > 0);
            }
        }
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}

TEST_CASE(
    "the tangent frame is orthonormal, right-handed, inverts ToLocal and is continuous in each hemisphere",
    "[vndf]") {
    std::mt19937_64 rng(7);
    std::normal_distribution<double> gauss;
    const auto randomDir = [&] { return normalized({gauss(rng), gauss(rng), gauss(rng)}); };
    // Pairs of nearby normals (1e-3 apart) in the same hemisphere, including around both
    // poles, where a single-branch construction divides by zero, and just beside the equator.
    std::vector<std::pair<Dir, Dir>> pairs;
    for (const Dir& base :
         {Dir{0, 0, 1}, Dir{0, 0, -1}, Dir{1e-7, 0, -1}, normalized({1, 0, 1e-3}), normalized({0, 1, -1e-3})})
        pairs.emplace_back(normalized(base), normalized(base + 1e-3 * randomDir()));
    while (pairs.size() < 2000) {
        const Dir n = randomDir(), m = normalized(n + 1e-3 * randomDir());
        if ((n.z >= 0) == (m.z >= 0)) pairs.emplace_back(n, m);
    }
    std::vector<GgxInput> inputs;
    const auto toFloat4 = [](Dir d) {
        return std::array<float, 4>{static_cast<float>(d.x), static_cast<float>(d.y), static_cast<float>(d.z),
                                    0};
    };
    for (const auto& [n, m] : pairs)
        for (const Dir& normal : {n, m}) {
            std::array<float, 4> view = toFloat4(randomDir());
            view[3] = 0.5f;
            inputs.push_back({view, {0.5f, 0.5f, 0, 0}, toFloat4(normal)});
        }
    inputs.push_back(
        {{0.6f, 0, 0.8f, 0.5f}, {0.5f, 0.5f, 0, 0}, {0, 0, -0.0f, 0}}); // -0.0 must not divide by zero
    const std::vector<GgxOutput> outputs = runGgxShader(inputs);
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        const GgxOutput& out = outputs[i];
        const Dir n = xyz(inputs[i].normal), t = xyz(out.tangent), b = xyz(out.bitangent);
        INFO("n (" << n.x << ", " << n.y << ", " << n.z << ")");
        REQUIRE(allFinite(out));
        // Float rounding of a few products: 1e-5 is generous.
        const Dir nUnit = length(n) > 0.5 ? n : Dir{0, 0, 1}; // -0.0 behaves as the north pole
        CHECK(std::abs(length(t) - 1) < 1e-5);
        CHECK(std::abs(length(b) - 1) < 1e-5);
        CHECK(std::abs(dot(t, b)) < 1e-5);
        CHECK(std::abs(dot(t, nUnit)) < 1e-5);
        CHECK(std::abs(dot(b, nUnit)) < 1e-5);
        CHECK(length(cross(t, b) + (-1.0) * nUnit) < 1e-5);
        CHECK(std::abs(out.tangent[3] - inputs[i].viewAlpha[0]) < 1e-5f);
        CHECK(std::abs(static_cast<double>(out.bitangent[3]) - dot(xyz(inputs[i].viewAlpha), n)) < 1e-5);
    }
    // Continuity: for n.z >= 0, t = (1 - x^2/(1+z), -xy/(1+z), -x) has partial derivatives of
    // Frobenius norm <= 3 (|x|, |y| <= 1, 1 + z >= 1), likewise b, and the n.z < 0 branch is
    // its mirror image; so |t(n) - t(m)| <= 3 |n - m| within a hemisphere (plus float slop).
    for (std::size_t p = 0; p < pairs.size(); ++p) {
        const GgxOutput &a = outputs[2 * p], &c = outputs[2 * p + 1];
        const double step = length(pairs[p].first + (-1.0) * pairs[p].second);
        INFO("pair " << p << ", |n - m| " << step);
        CHECK(length(xyz(a.tangent) + (-1.0) * xyz(c.tangent)) <= 3 * step + 1e-5);
        CHECK(length(xyz(a.bitangent) + (-1.0) * xyz(c.bitangent)) <= 3 * step + 1e-5);
    }
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
