// The SSSR tables: the blue-noise tile against the properties that define blue noise (checked with
// a plain DFT, and shown to reject white noise), and the split-sum DFG table against closed-form
// limits and a brute-force hemisphere quadrature.
#include "glint/glint_sssr_tables.h"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <random>
#include <utility>
#include <vector>

using namespace glint;

namespace {

constexpr std::size_t kN = kSssrBlueNoiseSize;
constexpr std::size_t kTexels = kN * kN;
constexpr double kPi = 3.14159265358979323846;

std::vector<double> blueNoiseChannel(std::size_t channel) {
    const std::vector<float>& table = sssrBlueNoise();
    std::vector<double> values(kTexels);
    for (std::size_t texel = 0; texel < kTexels; ++texel) values[texel] = table[texel * 2 + channel];
    return values;
}

// The same values in a random order: white noise with exactly the same histogram. std::mt19937's
// sequence is fixed by the standard (unlike the distributions), so this is the same everywhere.
std::vector<double> shuffled(std::vector<double> values, std::uint32_t seed) {
    std::mt19937 random(seed);
    for (std::size_t i = values.size() - 1; i > 0; --i) std::swap(values[i], values[random() % (i + 1)]);
    return values;
}

// |DFT|^2 of the mean-removed tile, by a direct separable DFT (rows, then columns), row-major over
// frequency (v, u).
std::vector<double> powerSpectrum(const std::vector<double>& tile) {
    double mean = 0.0;
    for (double value : tile) mean += value;
    mean /= static_cast<double>(tile.size());
    std::vector<std::complex<double>> twiddle(kN);
    for (std::size_t k = 0; k < kN; ++k)
        twiddle[k] = std::polar(1.0, -2.0 * kPi * static_cast<double>(k) / static_cast<double>(kN));
    std::vector<std::complex<double>> rows(kTexels);
    for (std::size_t y = 0; y < kN; ++y)
        for (std::size_t u = 0; u < kN; ++u)
            for (std::size_t x = 0; x < kN; ++x)
                rows[y * kN + u] += (tile[y * kN + x] - mean) * twiddle[(u * x) % kN];
    std::vector<double> power(kTexels);
    for (std::size_t v = 0; v < kN; ++v) {
        for (std::size_t u = 0; u < kN; ++u) {
            std::complex<double> sum = 0.0;
            for (std::size_t y = 0; y < kN; ++y) sum += rows[y * kN + u] * twiddle[(v * y) % kN];
            power[v * kN + u] = std::norm(sum);
        }
    }
    return power;
}

// Radial frequency in cycles per tile, for DFT index k (the upper half are negative frequencies).
double signedFrequency(std::size_t k) {
    return k < kN / 2 ? static_cast<double>(k) : static_cast<double>(k) - static_cast<double>(kN);
}

// Mean power over 0 < |f| < kLowRadius divided by the mean over kHighFrom <= |f| <= kN / 2.
// White noise has a flat spectrum: the ratio is 1 up to sampling noise (the low band holds ~200
// frequencies, ~100 independent exponentially distributed powers: relative spread ~0.1).
constexpr double kLowRadius = 8.0; // wavelengths above 16 texels
constexpr double kHighFrom = 32.0; // wavelengths of 4 texels and below
double lowToHighPowerRatio(const std::vector<double>& tile) {
    const std::vector<double> power = powerSpectrum(tile);
    double low = 0.0;
    double high = 0.0;
    int lowCount = 0;
    int highCount = 0;
    for (std::size_t v = 0; v < kN; ++v) {
        for (std::size_t u = 0; u < kN; ++u) {
            const double radius = std::hypot(signedFrequency(u), signedFrequency(v));
            if (radius > 0.0 && radius < kLowRadius) {
                low += power[v * kN + u];
                ++lowCount;
            } else if (radius >= kHighFrom && radius <= static_cast<double>(kN / 2)) {
                high += power[v * kN + u];
                ++highCount;
            }
        }
    }
    return (low / lowCount) / (high / highCount);
}

double pearson(const std::vector<double>& a, const std::vector<double>& b) {
    double meanA = 0.0;
    double meanB = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        meanA += a[i];
        meanB += b[i];
    }
    meanA /= static_cast<double>(a.size());
    meanB /= static_cast<double>(b.size());
    double covariance = 0.0;
    double varianceA = 0.0;
    double varianceB = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        covariance += (a[i] - meanA) * (b[i] - meanB);
        varianceA += (a[i] - meanA) * (a[i] - meanA);
        varianceB += (b[i] - meanB) * (b[i] - meanB);
    }
    return covariance / std::sqrt(varianceA * varianceB);
}

// Mean |v(x) - v(x + 1)| over horizontal and vertical neighbour pairs, wrapping around the tile.
// Restricted to the pairs that straddle the wrap seams when seamsOnly is set.
double meanNeighbourDifference(const std::vector<double>& tile, bool seamsOnly) {
    double sum = 0.0;
    int count = 0;
    for (std::size_t y = 0; y < kN; ++y) {
        for (std::size_t x = 0; x < kN; ++x) {
            const double value = tile[y * kN + x];
            if (!seamsOnly || x == kN - 1) {
                sum += std::abs(value - tile[y * kN + (x + 1) % kN]);
                ++count;
            }
            if (!seamsOnly || y == kN - 1) {
                sum += std::abs(value - tile[((y + 1) % kN) * kN + x]);
                ++count;
            }
        }
    }
    return sum / count;
}

} // namespace

TEST_CASE("each blue-noise channel holds every level (rank + 0.5) / 16384 exactly once", "[blue_noise]") {
    const std::vector<float>& table = sssrBlueNoise();
    REQUIRE(table.size() == kTexels * 2);
    for (std::size_t channel = 0; channel < 2; ++channel) {
        std::vector<int> seen(kTexels, 0);
        bool allLevels = true;
        for (std::size_t texel = 0; texel < kTexels; ++texel) {
            const double rank =
                static_cast<double>(table[texel * 2 + channel]) * static_cast<double>(kTexels) - 0.5;
            const double rounded = std::round(rank);
            if (rank != rounded || rounded < 0.0 || rounded >= static_cast<double>(kTexels)) {
                allLevels = false;
                continue;
            }
            ++seen[static_cast<std::size_t>(rounded)];
        }
        CHECK(allLevels);
        int levelsSeenOnce = 0;
        for (int count : seen) levelsSeenOnce += count == 1 ? 1 : 0;
        CHECK(levelsSeenOnce == static_cast<int>(kTexels));
    }
}

TEST_CASE("the blue-noise tile is generated once and every call returns the same data", "[blue_noise]") {
    const std::vector<float>& first = sssrBlueNoise();
    const std::vector<float> copy = first;
    const std::vector<float>& second = sssrBlueNoise();
    CHECK(&first == &second);
    CHECK(copy == second);
}

TEST_CASE("blue noise has almost no low-frequency power, and the check rejects white noise", "[blue_noise]") {
    // Bound: the low band averages under 0.01 of the high band. A void-and-cluster map with a
    // sigma-1.9 filter reaches full power only around 36-40 cycles per tile, so the band below 8
    // cycles should be orders of magnitude down (about 3e-5 when this test was written, checked
    // with an independent FFT); 0.01 leaves a wide margin. Shuffling the same values (white
    // noise, ratio 1 +- 0.1) must land far above it, or the check would not discriminate.
    for (std::size_t channel = 0; channel < 2; ++channel) {
        const std::vector<double> tile = blueNoiseChannel(channel);
        const double blue = lowToHighPowerRatio(tile);
        const double white =
            lowToHighPowerRatio(shuffled(tile, 12345u + static_cast<std::uint32_t>(channel)));
        INFO("channel " << channel << ": blue " << blue << ", white " << white);
        CHECK(blue < 0.01);
        CHECK(white > 0.6);
    }
}

TEST_CASE("the two blue-noise channels are uncorrelated", "[blue_noise]") {
    // Independent permutations give r ~ N(0, 1 / sqrt(16384) = 0.0078); 0.05 is over 6 sigma.
    const double r = pearson(blueNoiseChannel(0), blueNoiseChannel(1));
    INFO("pearson r " << r);
    CHECK(std::abs(r) < 0.05);
}

TEST_CASE("neighbouring blue-noise texels differ more than white noise, across the seams too",
          "[blue_noise]") {
    // For independent uniform values E|a - b| = 1/3 with standard deviation sqrt(1/18) = 0.236 per
    // pair: over the 32768 neighbour pairs the white mean is 1/3 +- 0.0013, so 1/3 + 0.03 is far
    // outside it. The 256 seam pairs (+- 0.015 for white noise) must also be above 1/3 + 0.03,
    // which white noise, or a tile made without wrap-around (unrelated texels meet at its seams),
    // passes with probability ~0.02.
    constexpr double kWhite = 1.0 / 3.0;
    for (std::size_t channel = 0; channel < 2; ++channel) {
        const std::vector<double> tile = blueNoiseChannel(channel);
        const double all = meanNeighbourDifference(tile, false);
        const double seams = meanNeighbourDifference(tile, true);
        const double white = meanNeighbourDifference(shuffled(tile, 777u), false);
        INFO("channel " << channel << ": all " << all << ", seams " << seams << ", white " << white);
        CHECK(all > kWhite + 0.03);
        CHECK(seams > kWhite + 0.03);
        CHECK(std::abs(white - kWhite) < 0.01);
    }
}

namespace {

double lutAt(const std::vector<float>& lut, std::uint32_t size, std::uint32_t i, std::uint32_t j,
             std::size_t component) {
    return lut[(static_cast<std::size_t>(j) * size + i) * 2 + component];
}

double texelCentre(std::uint32_t index, std::uint32_t size) {
    return (index + 0.5) / size;
}

// GGX normal distribution and height-correlated Smith G2, written from the definitions (Walter et
// al. 2007; Heitz 2014): Lambda(w) = (-1 + sqrt(1 + 1 / a^2)) / 2, a = cot(theta) / alpha.
double ggxD(double nDotH, double alpha) {
    const double a2 = alpha * alpha;
    const double t = nDotH * nDotH * (a2 - 1.0) + 1.0;
    return a2 / (kPi * t * t);
}

double smithLambda(double cosTheta, double alpha) {
    const double a = cosTheta / (alpha * std::sqrt(1.0 - cosTheta * cosTheta));
    return 0.5 * (-1.0 + std::sqrt(1.0 + 1.0 / (a * a)));
}

// (A, B) by midpoint quadrature over the hemisphere of L in (theta, phi), with the full BRDF
// f = D G2 F / (4 N.L N.V) times N.L, split by F = F0 (1 - Fc) + Fc. Nothing is importance
// sampled; the integrand is smooth, so the error falls as the square of the step.
std::array<double, 2> bruteForceDfg(double nDotV, double alpha) {
    constexpr int kThetaSteps = 1024;
    constexpr int kPhiSteps = 512; // phi in [0, pi]: the integrand is symmetric about the V plane
    const double vx = std::sqrt(1.0 - nDotV * nDotV);
    const double vz = nDotV;
    const double dTheta = 0.5 * kPi / kThetaSteps;
    const double dPhi = kPi / kPhiSteps;
    const double lambdaV = smithLambda(nDotV, alpha);
    std::array<double, 2> sum{0.0, 0.0};
    for (int t = 0; t < kThetaSteps; ++t) {
        const double theta = (t + 0.5) * dTheta;
        const double nDotL = std::cos(theta);
        const double sinTheta = std::sin(theta);
        const double lambdaL = smithLambda(nDotL, alpha);
        const double g2 = 1.0 / (1.0 + lambdaV + lambdaL);
        for (int p = 0; p < kPhiSteps; ++p) {
            const double phi = (p + 0.5) * dPhi;
            const double lx = sinTheta * std::cos(phi);
            const double ly = sinTheta * std::sin(phi);
            const double hx = vx + lx;
            const double hy = ly;
            const double hz = vz + nDotL;
            const double hLength = std::sqrt(hx * hx + hy * hy + hz * hz);
            const double nDotH = hz / hLength;
            const double vDotH = (vx * hx + vz * hz) / hLength;
            const double fc = std::pow(1.0 - vDotH, 5.0);
            // f N.L dw = D G2 F / (4 N.V) sin(theta) dtheta dphi, doubled for phi in [pi, 2 pi].
            const double common = 2.0 * ggxD(nDotH, alpha) * g2 / (4.0 * nDotV) * sinTheta * dTheta * dPhi;
            sum[0] += (1.0 - fc) * common;
            sum[1] += fc * common;
        }
    }
    return sum;
}

} // namespace

TEST_CASE("the DFG table of a near-mirror is the Fresnel of the mirror direction", "[brdf_lut]") {
    // Row 0 has roughness 1/64 (alpha 2.4e-4): D is nearly a delta at H = N, so V.H = N.V, G2 = 1,
    // and A = 1 - (1 - N.V)^5, B = (1 - N.V)^5, A + B = 1. H strays from N by ~alpha, moving V.H by
    // at most ~alpha; |dFc / d(V.H)| <= 5 bounds the Fresnel change by ~1.2e-3, so 2e-3.
    const std::vector<float> lut = sssrBrdfLut();
    REQUIRE(lut.size() == kSssrBrdfLutSize * kSssrBrdfLutSize * 2);
    for (std::uint32_t i = 0; i < kSssrBrdfLutSize; ++i) {
        const double nDotV = texelCentre(i, kSssrBrdfLutSize);
        const double fc = std::pow(1.0 - nDotV, 5.0);
        const double a = lutAt(lut, kSssrBrdfLutSize, i, 0, 0);
        const double b = lutAt(lut, kSssrBrdfLutSize, i, 0, 1);
        INFO("N.V " << nDotV << ": A " << a << ", B " << b);
        CHECK(std::abs(a - (1.0 - fc)) < 2e-3);
        CHECK(std::abs(b - fc) < 2e-3);
        CHECK(std::abs(a + b - 1.0) < 2e-3);
    }
}

TEST_CASE("the DFG table is an energy fraction: 0 <= A, B and A + B <= 1", "[brdf_lut]") {
    for (std::uint32_t size : {1u, 7u, kSssrBrdfLutSize}) {
        const std::vector<float> lut = sssrBrdfLut(size);
        REQUIRE(lut.size() == static_cast<std::size_t>(size) * size * 2);
        for (std::uint32_t j = 0; j < size; ++j) {
            for (std::uint32_t i = 0; i < size; ++i) {
                const double a = lutAt(lut, size, i, j, 0);
                const double b = lutAt(lut, size, i, j, 1);
                INFO("size " << size << ", texel (" << i << ", " << j << "): A " << a << ", B " << b);
                CHECK(a >= 0.0);
                CHECK(b >= 0.0);
                CHECK(a + b <= 1.0 + 1e-6); // float rounding of two values below 1
            }
        }
    }
}

TEST_CASE("at normal incidence the DFG table's A falls as roughness grows", "[brdf_lut]") {
    // Rougher lobes lose more to masking-shadowing and reach larger Fresnel angles.
    const std::vector<float> lut = sssrBrdfLut();
    const std::uint32_t last = kSssrBrdfLutSize - 1;
    for (std::uint32_t j = 0; j + 1 < kSssrBrdfLutSize; ++j) {
        INFO("roughness rows " << j << ", " << j + 1);
        CHECK(lutAt(lut, kSssrBrdfLutSize, last, j + 1, 0) < lutAt(lut, kSssrBrdfLutSize, last, j, 0));
    }
}

TEST_CASE("the DFG table matches a brute-force hemisphere quadrature", "[brdf_lut]") {
    // The reference's midpoint rule has >= 40 steps across the narrowest lobe here (alpha 0.07),
    // so its error is far below 1e-4. The table's 1024-point Hammersley estimate differs from it
    // by at most 2.1e-4 over these texels; 2e-3 leaves ten times that. The check discriminates:
    // the separable G1(V) G1(L) instead of the height-correlated G2 moves A by 0.005 to 0.3 at
    // (0, 31), (0, 12), (3, 10) and (8, 24).
    const std::vector<float> lut = sssrBrdfLut();
    const std::array<std::array<std::uint32_t, 2>, 7> texels{
        {{0, 31}, {0, 12}, {3, 10}, {16, 16}, {31, 8}, {8, 24}, {31, 31}}};
    for (const auto& [i, j] : texels) {
        const double nDotV = texelCentre(i, kSssrBrdfLutSize);
        const double perceptualRoughness = texelCentre(j, kSssrBrdfLutSize);
        const std::array<double, 2> expected =
            bruteForceDfg(nDotV, perceptualRoughness * perceptualRoughness);
        const double a = lutAt(lut, kSssrBrdfLutSize, i, j, 0);
        const double b = lutAt(lut, kSssrBrdfLutSize, i, j, 1);
        INFO("N.V " << nDotV << ", roughness " << perceptualRoughness << ": A " << a << " vs " << expected[0]
                    << ", B " << b << " vs " << expected[1]);
        CHECK(std::abs(a - expected[0]) < 2e-3);
        CHECK(std::abs(b - expected[1]) < 2e-3);
    }
}

TEST_CASE("the DFG table refuses sizes outside 1..kSssrBrdfLutMaxSize", "[brdf_lut]") {
    CHECK(sssrBrdfLut(0).empty());
    CHECK(sssrBrdfLut(kSssrBrdfLutMaxSize + 1).empty());
}
