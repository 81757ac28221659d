// The SSSR blue-noise tile: two independent void-and-cluster rank maps (Ulichney 1993).
//
// Why void-and-cluster: SSSR spends one ray per pixel and the denoiser averages neighbours, so the
// per-pixel random numbers should differ most from their neighbours' (no low frequencies: the error
// of a spatial average then falls off fast). A void-and-cluster rank map has that property for
// every threshold at once, it tiles seamlessly because the energy wraps around the torus, and it is
// a permutation of all 16384 levels, so each channel is exactly uniform. The Heitz et al. 2019
// scrambled-Sobol tile in FidelityFX needs Sobol tables and an optimisation of its own; this needs
// only the algorithm below.
//
// Energy filter: Gaussian with sigma 1.9 texels (the package's choice; Ulichney used 1.5), truncated to
// the disc of radius 8 texels (weight e^-8.9 = 1.4e-4 of the peak at the rim), so a toggle updates 197
// texels. Energies are integers (weights scaled by 2^24 and rounded; each product lies at least 0.02 from
// a rounding boundary, so a last-ulp difference in std::exp cannot change it), so sums are exact and
// independent of order, and ties break on the lowest row-major index: the tile is the same on every
// platform and standard library. The initial 10 % pattern comes from splitmix64 with a fixed seed per
// channel (the seeds are arbitrary; any seeds give equally good tiles).
//
// Phase 3 (ranking the majority half) inserts at the zero with the least energy: with a kernel
// whose sum over the torus is the same everywhere, the zeros' own energy is that sum minus the
// ones' energy, so Ulichney's "tightest cluster of zeros" is exactly that texel.
#include "glint/glint_sssr_tables.h"

#include <array>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>

namespace glint {
namespace {

constexpr int kSize = static_cast<int>(kSssrBlueNoiseSize);
constexpr int kTexels = kSize * kSize;
constexpr int kRadius = 8;
constexpr double kSigma = 1.9;
constexpr double kWeightScale = 16777216.0; // 2^24
constexpr int kInitialOnes = kTexels / 10;  // Ulichney: the minority pixels, <= 50 %
constexpr int kMaxRelaxSwaps = 4 * kTexels; // converges in far fewer; bounds the loop regardless
constexpr std::uint64_t kSeeds[2] = {0x676c696e74535353ull, 0x9e3779b97f4a7c15ull}; // arbitrary

struct SplitMix64 {
    std::uint64_t state;

    std::uint64_t next() {
        std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }

    // Uniform in [0, bound) by multiply-shift; the bias (< 2^-32) is irrelevant for a seed pattern.
    std::uint32_t below(std::uint32_t bound) {
        return static_cast<std::uint32_t>(((next() >> 32) * bound) >> 32);
    }
};

struct KernelTap {
    int dx;
    int dy;
    std::int64_t weight;
};

std::vector<KernelTap> energyKernel() {
    std::vector<KernelTap> taps;
    for (int dy = -kRadius; dy <= kRadius; ++dy) {
        for (int dx = -kRadius; dx <= kRadius; ++dx) {
            const int d2 = dx * dx + dy * dy;
            if (d2 > kRadius * kRadius) continue;
            const double weight = std::exp(-static_cast<double>(d2) / (2.0 * kSigma * kSigma));
            taps.push_back({dx, dy, std::llround(weight * kWeightScale)});
        }
    }
    return taps;
}

static_assert((kSize & (kSize - 1)) == 0, "wrap() masks the coordinate");
static_assert(2 * kRadius + 1 <= 2 * 16, "a toggle must touch at most 2 x 2 blocks");

int wrap(int coordinate) {
    return coordinate & (kSize - 1); // two's complement: -1 wraps to kSize - 1
}

// The binary pattern, its energy, and the search results of each 16 x 16 block, recomputed only
// for the (at most 2 x 2) blocks a toggle touched: a step reads ~1000 texels instead of 16384.
class VoidAndCluster {
  public:
    explicit VoidAndCluster(const std::vector<KernelTap>& kernel) : kernel_(kernel) {}

    void toggle(int texel) {
        const bool inserting = ones_[index(texel)] == 0;
        const std::int64_t sign = inserting ? 1 : -1;
        ones_[index(texel)] = inserting ? std::uint8_t{1} : std::uint8_t{0};
        const int x = texel % kSize;
        const int y = texel / kSize;
        for (const KernelTap& tap : kernel_)
            energy_[index(wrap(y + tap.dy) * kSize + wrap(x + tap.dx))] += sign * tap.weight;
        for (int dy : {-kRadius, kRadius}) {
            for (int dx : {-kRadius, kRadius}) {
                const int block = blockOf(wrap(x + dx), wrap(y + dy));
                clusterDirty_[index(block)] = 1u;
                voidDirty_[index(block)] = 1u;
            }
        }
    }

    // The one with the most energy, lowest index on ties (-1 if none).
    int tightestCluster() { return search(true); }

    // The zero with the least energy, lowest index on ties (-1 if none).
    int largestVoid() { return search(false); }

    void restore(const VoidAndCluster& other) {
        ones_ = other.ones_;
        energy_ = other.energy_;
        clusterDirty_.fill(1u);
        voidDirty_.fill(1u);
    }

  private:
    static constexpr int kBlock = 16;
    static constexpr int kBlocksPerRow = kSize / kBlock;
    static constexpr int kBlocks = kBlocksPerRow * kBlocksPerRow;

    static std::size_t index(int i) { return static_cast<std::size_t>(i); }
    static int blockOf(int x, int y) { return (y / kBlock) * kBlocksPerRow + x / kBlock; }

    // Searches the ones for the most energy (cluster) or the zeros for the least, as a search for
    // the largest key: energy for the ones, -energy for the zeros, and the lowest key for the rest.
    int search(bool cluster) {
        std::array<std::uint8_t, kBlocks>& dirty = cluster ? clusterDirty_ : voidDirty_;
        std::array<int, kBlocks>& found = cluster ? blockCluster_ : blockVoid_;
        const std::uint8_t wanted = cluster ? 1u : 0u;
        const std::int64_t sign = cluster ? 1 : -1;
        constexpr std::int64_t kExcluded = std::numeric_limits<std::int64_t>::min(); // below any -energy
        for (int block = 0; block < kBlocks; ++block) {
            if (!dirty[index(block)]) continue;
            const int x0 = (block % kBlocksPerRow) * kBlock;
            const int y0 = (block / kBlocksPerRow) * kBlock;
            int best = -1;
            std::int64_t bestKey = kExcluded;
            for (int y = y0; y < y0 + kBlock; ++y) {
                for (int texel = y * kSize + x0; texel < y * kSize + x0 + kBlock; ++texel) {
                    const std::int64_t key =
                        ones_[index(texel)] == wanted ? sign * energy_[index(texel)] : kExcluded;
                    if (key > bestKey) {
                        bestKey = key;
                        best = texel;
                    }
                }
            }
            found[index(block)] = best;
            dirty[index(block)] = 0u;
        }
        int best = -1;
        std::int64_t bestKey = kExcluded;
        for (int candidate : found) {
            if (candidate < 0) continue;
            const std::int64_t key = sign * energy_[index(candidate)];
            if (key > bestKey || (key == bestKey && candidate < best)) {
                bestKey = key;
                best = candidate;
            }
        }
        return best;
    }

    template <typename T> static std::array<T, kBlocks> filled(T value) {
        std::array<T, kBlocks> result;
        result.fill(value);
        return result;
    }

    const std::vector<KernelTap>& kernel_;
    std::vector<std::uint8_t> ones_ = std::vector<std::uint8_t>(kTexels, 0u);
    std::vector<std::int64_t> energy_ = std::vector<std::int64_t>(kTexels, 0);
    std::array<std::uint8_t, kBlocks> clusterDirty_ = filled<std::uint8_t>(1u);
    std::array<std::uint8_t, kBlocks> voidDirty_ = filled<std::uint8_t>(1u);
    std::array<int, kBlocks> blockCluster_ = filled<int>(-1);
    std::array<int, kBlocks> blockVoid_ = filled<int>(-1);
};

// Ranks 0..16383 in row-major texel order.
std::vector<int> rankMap(std::uint64_t seed, const std::vector<KernelTap>& kernel) {
    VoidAndCluster pattern(kernel);

    // Initial binary pattern: kInitialOnes distinct random texels (partial Fisher-Yates).
    SplitMix64 random{seed};
    std::vector<int> order(kTexels);
    for (int texel = 0; texel < kTexels; ++texel) order[static_cast<std::size_t>(texel)] = texel;
    for (int i = 0; i < kInitialOnes; ++i) {
        const std::uint32_t pick =
            static_cast<std::uint32_t>(i) + random.below(static_cast<std::uint32_t>(kTexels - i));
        std::swap(order[static_cast<std::size_t>(i)], order[pick]);
        pattern.toggle(order[static_cast<std::size_t>(i)]);
    }

    // Relax it: move the tightest cluster into the largest void until the move would undo itself.
    for (int swaps = 0; swaps < kMaxRelaxSwaps; ++swaps) {
        const int cluster = pattern.tightestCluster();
        pattern.toggle(cluster);
        const int emptiest = pattern.largestVoid();
        pattern.toggle(emptiest);
        if (emptiest == cluster) break;
    }

    std::vector<int> rank(kTexels, -1);
    VoidAndCluster prototype(kernel);
    prototype.restore(pattern);

    // Phase 1: remove the ones, tightest cluster first, ranking them downward.
    for (int next = kInitialOnes - 1; next >= 0; --next) {
        const int cluster = pattern.tightestCluster();
        assert(cluster >= 0);
        pattern.toggle(cluster);
        rank[static_cast<std::size_t>(cluster)] = next;
    }

    // Phases 2 and 3: from the prototype, fill the largest void, ranking upward.
    pattern.restore(prototype);
    for (int next = kInitialOnes; next < kTexels; ++next) {
        const int emptiest = pattern.largestVoid();
        assert(emptiest >= 0);
        pattern.toggle(emptiest);
        rank[static_cast<std::size_t>(emptiest)] = next;
    }
    return rank;
}

std::vector<float> generateBlueNoise() {
    const std::vector<KernelTap> kernel = energyKernel();
    std::vector<float> table(static_cast<std::size_t>(kTexels) * 2u);
    for (std::size_t channel = 0; channel < 2; ++channel) {
        const std::vector<int> rank = rankMap(kSeeds[channel], kernel);
        for (std::size_t texel = 0; texel < rank.size(); ++texel) {
            assert(rank[texel] >= 0);
            // (rank + 0.5) / 16384, exact in float.
            table[texel * 2 + channel] =
                static_cast<float>(2 * rank[texel] + 1) / static_cast<float>(2 * kTexels);
        }
    }
    return table;
}

} // namespace

const std::vector<float>& sssrBlueNoise() {
    static const std::vector<float> table = generateBlueNoise();
    return table;
}

} // namespace glint
