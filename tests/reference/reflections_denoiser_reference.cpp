#include "reference/reflections_denoiser_reference.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace glint::reference {
namespace {

// Every value the denoiser stores is finite and within the fp16 range (docs, "History
// management"); radiance is also non-negative.
constexpr double kHalfMax = 65504.0;

double clampStored(double v) {
    return std::isfinite(v) ? std::clamp(v, 0.0, kHalfMax) : 0.0;
}

Rgb clampStored(const Rgb& c) {
    return {clampStored(c[0]), clampStored(c[1]), clampStored(c[2])};
}

double radicalInverse(std::uint32_t index, std::uint32_t base) {
    double result = 0.0, scale = 1.0;
    for (; index > 0; index /= base) {
        scale /= static_cast<double>(base);
        result += scale * static_cast<double>(index % base);
    }
    return result;
}

double distance(const Rgb& a, const Rgb& b) {
    const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
    return std::sqrt(dx * dx + dy * dy + dz * dz);
}

double dot(const Rgb& a, const Rgb& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

Rgb mix(const Rgb& a, const Rgb& b, double t) {
    return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
}

// The point where the segment from the box centre to x leaves the box (Playdead's clip), or x
// when it lies inside. The half-extent gets 0.001 added so that a box of zero spread still
// has a size and the division is defined.
Rgb clipTowardCentre(const Rgb& x, const Rgb& centre, const Rgb& halfExtent) {
    double outside = 0.0; // the largest |offset| / extent over the channels: > 1 outside the box
    for (std::size_t c = 0; c < 3; ++c)
        outside = std::max(outside, std::abs(x[c] - centre[c]) / (halfExtent[c] + 0.001));
    if (outside <= 1.0) return x;
    return {centre[0] + (x[0] - centre[0]) / outside, centre[1] + (x[1] - centre[1]) / outside,
            centre[2] + (x[2] - centre[2]) / outside};
}

std::size_t clampedIndex(std::uint32_t width, std::uint32_t height, std::int64_t x, std::int64_t y) {
    x = std::clamp<std::int64_t>(x, 0, std::int64_t{width} - 1);
    y = std::clamp<std::int64_t>(y, 0, std::int64_t{height} - 1);
    return static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x);
}

// The prefilter's radiance weight of a sample against the tile average, with the centre's
// variance: bright departures from the local average (fireflies) weigh little.
double radianceWeight(const Rgb& average, const Rgb& sample, double centreVariance) {
    return std::max(std::exp(-(0.6 + 0.1 * centreVariance) * distance(average, sample)), 0.01);
}

} // namespace

double luma(const Rgb& c) {
    return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
}

std::array<PixelOffset, 15> prefilterTaps() {
    std::array<PixelOffset, 15> taps;
    for (std::uint32_t i = 1; i <= 15; ++i)
        taps[i - 1] = {static_cast<int>(std::trunc(8.0 * radicalInverse(i, 2) - 4.0)),
                       static_cast<int>(std::trunc(8.0 * radicalInverse(i, 3) - 4.0))};
    // The docs say "the first 15 Halton(2,3) points within +-3 pixels" without the mapping;
    // trunc(8 h - 4) is the one that reproduces FidelityFX's published table ("first 15
    // numbers of Halton(2,3) stretched to [-3,3]"), which the docs paraphrase, in 14 of 15
    // taps. The table's first tap is (0, 1) where Halton index 1, (1/2, 1/3), maps to (0, -1).
    // The published table is the specification, so the reference takes its first tap.
    taps[0].y = -taps[0].y;
    return taps;
}

TileGrid tileAverages(std::uint32_t width, std::uint32_t height, const std::vector<Rgb>& contribution,
                      const std::vector<std::uint8_t>& glossy, const std::vector<std::uint8_t>& listed) {
    TileGrid grid;
    grid.tilesX = (width + kDenoiserTileSize - 1) / kDenoiserTileSize;
    grid.tilesY = (height + kDenoiserTileSize - 1) / kDenoiserTileSize;
    const std::size_t tileCount = std::size_t{grid.tilesX} * grid.tilesY;
    assert(listed.size() == tileCount && contribution.size() == std::size_t{width} * height);
    grid.listed = listed;
    grid.average.assign(tileCount, Rgb{});
    grid.weight.assign(tileCount, 0.0);
    for (std::uint32_t ty = 0; ty < grid.tilesY; ++ty)
        for (std::uint32_t tx = 0; tx < grid.tilesX; ++tx) {
            const std::size_t tile = std::size_t{ty} * grid.tilesX + tx;
            if (!listed[tile]) continue;
            Rgb sum{};
            double total = 0.0;
            for (std::uint32_t y = ty * kDenoiserTileSize; y < std::min(height, (ty + 1) * kDenoiserTileSize);
                 ++y)
                for (std::uint32_t x = tx * kDenoiserTileSize;
                     x < std::min(width, (tx + 1) * kDenoiserTileSize); ++x) {
                    const std::size_t i = std::size_t{y} * width + x;
                    if (!glossy[i]) continue;
                    const double w = std::max(std::exp(-0.3 * luma(contribution[i])), 0.01);
                    for (std::size_t c = 0; c < 3; ++c) sum[c] += w * contribution[i][c];
                    total += w;
                }
            grid.weight[tile] = total;
            if (total > 0.0)
                grid.average[tile] = clampStored(Rgb{sum[0] / total, sum[1] / total, sum[2] / total});
        }
    return grid;
}

Rgb averageAt(const TileGrid& tiles, std::uint32_t x, std::uint32_t y) {
    // Position in tile units, relative to the centre of tile 0 (at pixel 4).
    const double px = (x + 0.5) / kDenoiserTileSize - 0.5, py = (y + 0.5) / kDenoiserTileSize - 0.5;
    const double fx = px - std::floor(px), fy = py - std::floor(py);
    const auto x0 = static_cast<std::int64_t>(std::floor(px)), y0 = static_cast<std::int64_t>(std::floor(py));
    Rgb sum{};
    double total = 0.0;
    for (std::int64_t dy = 0; dy <= 1; ++dy)
        for (std::int64_t dx = 0; dx <= 1; ++dx) {
            const std::int64_t tx = x0 + dx, ty = y0 + dy;
            if (tx < 0 || ty < 0 || tx >= tiles.tilesX || ty >= tiles.tilesY) continue;
            const std::size_t tile =
                static_cast<std::size_t>(ty) * tiles.tilesX + static_cast<std::size_t>(tx);
            if (!tiles.listed[tile] || !(tiles.weight[tile] > 0.0)) continue;
            const double w = (dx ? fx : 1.0 - fx) * (dy ? fy : 1.0 - fy);
            for (std::size_t c = 0; c < 3; ++c) sum[c] += w * tiles.average[tile][c];
            total += w;
        }
    if (!(total > 0.0)) return Rgb{};
    return {sum[0] / total, sum[1] / total, sum[2] / total};
}

double spatialFootprint(double alpha, double mirrorThreshold) {
    return std::clamp((alpha - mirrorThreshold) / kFootprintRamp, 0.0, 1.0);
}

void prefilter(const PrefilterInputs& in, std::vector<RadianceVariance>& out) {
    const DenoiserSurface& s = *in.surface;
    const TileGrid& tiles = *in.tiles;
    const std::uint32_t w = s.width, h = s.height;
    assert(out.size() == std::size_t{w} * h && in.radiance.size() == out.size());
    const std::array<PixelOffset, 15> taps = prefilterTaps();
    for (std::uint32_t y = 0; y < h; ++y)
        for (std::uint32_t x = 0; x < w; ++x) {
            if (!tiles.listed[std::size_t{y / kDenoiserTileSize} * tiles.tilesX + x / kDenoiserTileSize])
                continue;
            const std::size_t p = std::size_t{y} * w + x;
            const double variance = in.variance[p];
            // Pixels that are not glossy are marked as such for the resolve.
            if (!s.glossy[p]) {
                out[p] = {Rgb{}, kNotGlossyVariance};
                continue;
            }
            // Mirrors (kept sharp) and pixels with no variance are copied through.
            if (!(variance > 0.0) || s.alpha[p] < in.mirrorThreshold) {
                out[p] = {in.radiance[p], variance};
                continue;
            }
            const Rgb average = averageAt(tiles, x, y);
            // The centre's own weight is its radiance weight against the average, so a firefly
            // centre gives way to its neighbours.
            const double centreWeight = radianceWeight(average, in.radiance[p], variance);
            double weightSum = centreWeight;
            double varianceSum = centreWeight * centreWeight * variance;
            Rgb sum{centreWeight * in.radiance[p][0], centreWeight * in.radiance[p][1],
                    centreWeight * in.radiance[p][2]};
            const double varianceWeight = std::max(0.1, 1.0 - std::exp(-4.4 * variance));
            const double footprint = spatialFootprint(s.alpha[p], in.mirrorThreshold);
            for (const PixelOffset& tap : taps) {
                const std::size_t q = clampedIndex(w, h, std::int64_t{x} + tap.x, std::int64_t{y} + tap.y);
                if (!s.glossy[q]) continue;
                const double normalWeight = std::pow(std::max(0.0, dot(s.normal[p], s.normal[q])), 512.0);
                const double depthWeight =
                    std::exp(-4.0 * std::abs(s.viewDepth[p] - s.viewDepth[q]) / s.viewDepth[p]);
                // The footprint: a Gaussian in the tap's distance that narrows to nothing as
                // alpha falls to the mirror threshold (pow(0, d^2 / 2) = 0 for every tap).
                const double distanceWeight = std::pow(footprint, 0.5 * (tap.x * tap.x + tap.y * tap.y));
                const double weight = normalWeight * depthWeight *
                                      radianceWeight(average, in.radiance[q], variance) * varianceWeight *
                                      distanceWeight;
                for (std::size_t c = 0; c < 3; ++c) sum[c] += weight * in.radiance[q][c];
                varianceSum += weight * weight * in.variance[q];
                weightSum += weight;
            }
            // A weighted mean of independent samples: its variance is sum w^2 var / (sum w)^2.
            out[p] = {clampStored(Rgb{sum[0] / weightSum, sum[1] / weightSum, sum[2] / weightSum}),
                      clampStored(varianceSum / (weightSum * weightSum))};
        }
}

NeighbourhoodStatistics resolveStatistics(const ResolveInputs& in) {
    NeighbourhoodStatistics s;
    double total = 0.0;
    for (int dy = -4; dy <= 4; ++dy)
        for (int dx = -4; dx <= 4; ++dx) {
            const auto i = static_cast<std::size_t>((dy + 4) * 9 + dx + 4);
            if (!in.glossy[i]) continue;
            const double w = std::exp(-3.0 * (dx * dx + dy * dy) / 25.0);
            for (std::size_t c = 0; c < 3; ++c) {
                s.mean[c] += w * in.prefiltered[i][c];
                s.meanSquare[c] += w * in.prefiltered[i][c] * in.prefiltered[i][c];
            }
            total += w;
        }
    assert(total > 0.0); // the centre is glossy
    for (std::size_t c = 0; c < 3; ++c) {
        s.mean[c] /= total;
        s.meanSquare[c] /= total;
        s.sigma[c] =
            std::max(std::sqrt(std::abs(s.meanSquare[c] - s.mean[c] * s.mean[c])) + in.sigmaOffset[c], 0.0);
        // The box: spread plus distance from the tile average, scaled.
        s.extent[c] = (s.sigma[c] + std::abs(s.mean[c] - in.average[c])) * in.historyClipScale * 1.4;
    }
    return s;
}

double resolveHistoryLength(const ResolveInputs& in) {
    const double n = std::max(in.historyLength, 1.0);
    if (!in.antiLag || !in.historyValid || in.alpha < in.mirrorThreshold) return n;
    const NeighbourhoodStatistics statistics = resolveStatistics(in);
    // How far, on average over the neighbourhood, the histories lie from this frame's samples.
    // A neighbour without a history counts with difference 0; every glossy neighbour weighs.
    double difference = 0.0, total = 0.0;
    for (int dy = -4; dy <= 4; ++dy)
        for (int dx = -4; dx <= 4; ++dx) {
            const auto i = static_cast<std::size_t>((dy + 4) * 9 + dx + 4);
            if (!in.glossy[i]) continue;
            const double w = std::exp(-3.0 * (dx * dx + dy * dy) / 25.0);
            total += w;
            if (in.neighbourHistoryValid[i])
                difference += w * (luma(clampStored(in.neighbourHistory[i])) - luma(in.prefiltered[i]));
        }
    const double tolerance =
        kAntiLagNoise * luma(statistics.sigma) + kAntiLagRelative * luma(statistics.mean) + kAntiLagFloor;
    const double excess = std::abs(difference / total) / tolerance;
    // Within the tolerance the history stays; beyond it, its length falls with the square.
    if (excess <= 1.0) return n;
    return std::max(n / (excess * excess), 1.0);
}

RadianceVariance resolvePixel(const ResolveInputs& in) {
    // 1-2. Neighbourhood statistics and the clip box.
    const NeighbourhoodStatistics statistics = resolveStatistics(in);
    const Rgb& mean = statistics.mean;
    const Rgb& extent = statistics.extent;
    const Rgb boxCentre = mix(mean, in.average, 0.2);
    const Rgb current = in.prefiltered[40];
    // The anti-lag's history length stands for reproject's in every step below.
    const double n = resolveHistoryLength(in);
    // 3. The history, clipped toward the box centre (without one, the current sample stands in).
    const Rgb history = in.historyValid ? clipTowardCentre(in.history, boxCentre, extent) : current;
    // 4. The current sample pulled by 1/(n+1) toward a target that moves from the box centre
    // (n = 1) to the tile average as 1 - 1/n, then clipped around the average; of that move, the
    // spatial footprint's share is taken (none for mirrors).
    const Rgb target = mix(boxCentre, in.average, 1.0 - 1.0 / n);
    const Rgb pulled =
        mix(current, clipTowardCentre(mix(current, target, 1.0 / (n + 1.0)), in.average, extent),
            spatialFootprint(in.alpha, in.mirrorThreshold));
    // 5. Blend by history length. A mirror's sample is noise-free: it is the output.
    const bool mirror = in.alpha < in.mirrorThreshold;
    const double historyWeight = in.historyValid && !mirror ? 1.0 - 1.0 / n : 0.0;
    RadianceVariance out;
    out.rgb = clampStored(mix(pulled, history, historyWeight));
    // The variance for next frame: the squared relative luminance change against the history,
    // blended with the prefiltered variance like the radiance.
    const double lumaOut = std::max(luma(out.rgb), 0.001), lumaHistory = std::max(luma(history), 0.001);
    const double change = std::abs(lumaOut - lumaHistory) / std::max({lumaOut, lumaHistory, 0.5});
    out.variance = clampStored(change * change + historyWeight * (in.variance - change * change));
    return out;
}

} // namespace glint::reference
