// CPU references of the deterministic parts of the reflections denoiser
// (docs/reflections_denoiser.md): the reproject pass's tile average, the prefilter pass, and
// the resolve pass's anti-lag, clip and blend for one pixel. Written from the documented rules, in
// double precision, independent of the shaders.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace glint::reference {

using Rgb = std::array<double, 3>;

// The denoiser's 8x8 tiles.
inline constexpr std::uint32_t kDenoiserTileSize = 8;

// The variance the prefilter (and the ratio path's reconstruction) stores for pixels that are
// not glossy: glossy pixels store a variance, never negative, so the resolve learns from it
// (in tiles listed this frame) which neighbours are glossy.
inline constexpr double kNotGlossyVariance = -1.0;

// A pixel offset (prefilter taps).
struct PixelOffset {
    int x = 0, y = 0;
    friend bool operator==(const PixelOffset&, const PixelOffset&) = default;
};

// The prefilter's 15 fixed taps: the first 15 Halton(2, 3) points (indices 1..15) mapped to
// whole pixels in [-3, 3] by trunc(8 h - 4), with the published table's one exception (see
// the .cpp).
std::array<PixelOffset, 15> prefilterTaps();

// Per-tile data of one frame: the reproject pass's average and weight sum, and whether
// SSSR's classification listed the tile this frame.
struct TileGrid {
    std::uint32_t tilesX = 0, tilesY = 0;
    std::vector<Rgb> average;   // per tile
    std::vector<double> weight; // per tile: weight sum (0: the tile has no glossy pixel)
    std::vector<std::uint8_t> listed;
};

// The tile-average reduction of the reproject pass for every listed tile (others get 0):
// each glossy pixel's contribution weighted by max(exp(-0.3 luma), 0.01), luma Rec. 709.
// `contribution` holds rgb per pixel, `glossy` a flag per pixel, `listed` a flag per tile.
TileGrid tileAverages(std::uint32_t width, std::uint32_t height, const std::vector<Rgb>& contribution,
                      const std::vector<std::uint8_t>& glossy, const std::vector<std::uint8_t>& listed);

// The tile average at a pixel: bilinear between the centres (8 i + 4) of the 2x2 surrounding
// tiles, renormalized over those that are listed and have a weight; 0 when none has.
Rgb averageAt(const TileGrid& tiles, std::uint32_t x, std::uint32_t y);

// How far the spatial filters reach, as a scale in [0, 1] (docs/reflections_denoiser.md,
// "Mirrors"): 0 for alpha at or below the mirror threshold, rising linearly in alpha to 1 at
// kFootprintRamp above it. The prefilter weighs a tap at distance d pixels by s^(d^2 / 2) and
// the resolve applies s times its pull toward the tile average.
inline constexpr double kFootprintRamp = 0.01;
double spatialFootprint(double alpha, double mirrorThreshold);

// The per-pixel surface the passes share.
struct DenoiserSurface {
    std::uint32_t width = 0, height = 0;
    std::vector<std::uint8_t> glossy;
    std::vector<Rgb> normal;       // unit
    std::vector<double> viewDepth; // > 0 where glossy
    std::vector<double> alpha;     // GGX alpha
};

struct RadianceVariance {
    Rgb rgb{};
    double variance = 0.0;
};

struct PrefilterInputs {
    const DenoiserSurface* surface = nullptr;
    std::vector<Rgb> radiance;    // reproject's clamped sample per pixel
    std::vector<double> variance; // reproject's temporal variance per pixel
    const TileGrid* tiles = nullptr;
    double mirrorThreshold = 1e-4;
};

// The prefilter pass for one frame: writes `out` (one entry per pixel) for every in-image
// pixel of a listed tile and leaves the others untouched. Pixels that are not glossy get rgb 0
// and variance kNotGlossyVariance.
void prefilter(const PrefilterInputs& inputs, std::vector<RadianceVariance>& out);

// One glossy pixel of the resolve pass.
struct ResolveInputs {
    // The prefiltered radiance of the 9x9 neighbourhood (offsets -4..4, row-major, the centre
    // at index 40), neighbour coordinates clamped to the image, and whether each is glossy.
    std::array<Rgb, 81> prefiltered{};
    std::array<bool, 81> glossy{};
    double variance = 0.0; // the centre's prefiltered variance
    Rgb average{};         // averageAt for the pixel
    Rgb history{};         // reprojected history
    bool historyValid = false;
    // The reprojected histories of the same 9x9 neighbourhood (the centre's at index 40 is
    // `history`), and whether each is valid: the anti-lag compares them with `prefiltered`.
    std::array<Rgb, 81> neighbourHistory{};
    std::array<bool, 81> neighbourHistoryValid{};
    double historyLength = 1.0; // reproject's
    double historyClipScale = 0.7;
    bool antiLag = true;
    double alpha = 1.0;            // the centre's GGX alpha
    double mirrorThreshold = 1e-4; // below it, the output is the centre's prefiltered sample
    // Added to the neighbourhood's sigma (clamped at 0): 0 for the pass itself; a test probes
    // how much a rounding error in sigma can move the result with it.
    Rgb sigmaOffset{};
};

// Resolve step 1: the Gaussian-weighted (exp(-3 i^2 / 25) per axis) mean, mean square and
// standard deviation of the glossy neighbours, and the clip box's half-extent.
struct NeighbourhoodStatistics {
    Rgb mean{}, meanSquare{}, sigma{}, extent{};
};
NeighbourhoodStatistics resolveStatistics(const ResolveInputs& inputs);

// The anti-lag's tolerance constants (docs/reflections_denoiser.md, "Resolve"): what noise
// explains of a mean luminance difference is kAntiLagNoise luma(sigma) + kAntiLagRelative
// luma(mean) + kAntiLagFloor, with the neighbourhood statistics of step 1.
inline constexpr double kAntiLagNoise = 1.0;
inline constexpr double kAntiLagRelative = 0.1;
inline constexpr double kAntiLagFloor = 0.001;

// The history length after the anti-lag: reproject's n when the anti-lag is off, the history
// is not valid or the pixel is a mirror; otherwise n / e^2 (at least 1, at most n), e the mean
// history-minus-sample luminance difference over the glossy neighbours (0 for those without a
// valid history) in units of the tolerance. The pass stores it for next frame.
double resolveHistoryLength(const ResolveInputs& inputs);

// The resolved radiance and the variance the pass stores for next frame (blended with the
// history length of resolveHistoryLength).
RadianceVariance resolvePixel(const ResolveInputs& inputs);

double luma(const Rgb& c);

} // namespace glint::reference
