// CPU references of SSSR tile classification (pass 2) and of the ray march of the
// intersection pass (pass 5) at texel granularity (docs/sssr.md, docs/conventions.md §2 and §8),
// written from the specification, independent of the shaders.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace glint::reference {

// ---------------------------------------------------------------------------------------------
// Shared rules

// Background (docs/conventions.md §2.2): non-finite, outside [0, 1], or within 1e-6 of the far
// plane.
// Evaluated in float, as the shaders do (1 - 1e-6 is not representable; the float
// constants 1.0f - 1e-6f and 1e-6f are the thresholds).
bool sssrIsBackground(float depth, bool reversedDepth);

// A normal is usable when all components are finite and its length exceeds 1e-6.
bool sssrNormalValid(float x, float y, float z);

// Ray-list entry (docs/conventions.md §8): x in bits 0-14, y in bits 15-28, copy H/V/D in
// 29/30/31.
std::uint32_t packSssrRay(std::uint32_t x, std::uint32_t y, bool copyH, bool copyV, bool copyD);
// Tile-list entry: the tile's top-left pixel, (x & 0xFFFF) | (y << 16).
std::uint32_t packSssrTile(std::uint32_t tileX, std::uint32_t tileY);

constexpr std::uint32_t kSssrCopyH = 1u << 29;
constexpr std::uint32_t kSssrCopyV = 1u << 30;
constexpr std::uint32_t kSssrCopyD = 1u << 31;

// ---------------------------------------------------------------------------------------------
// A. Classification

// Per-pixel class bits of SssrClassification::classes.
constexpr std::uint8_t kSssrReflective = 1u << 0;   // not background, valid normal
constexpr std::uint8_t kSssrGlossy = 1u << 1;       // reflective, alpha < roughnessThreshold
constexpr std::uint8_t kSssrMirror = 1u << 2;       // glossy, alpha < mirrorThreshold
constexpr std::uint8_t kSssrTraces = 1u << 3;       // has a ray-list entry
constexpr std::uint8_t kSssrRequiresCopy = 1u << 4; // takes its radiance from a donor
constexpr std::uint8_t kSssrPromoted = 1u << 5;     // needed a copy, found no donor, traces

struct SssrClassifyInputs {
    std::uint32_t width = 0, height = 0;
    std::vector<float> depth;    // W x H device depth
    std::vector<float> alpha;    // W x H GGX alpha (already converted); non-finite counts as 1
    std::vector<float> normals;  // xyz per pixel (3 floats), or empty: every normal valid
    std::vector<float> variance; // W x H reprojected variance; read only with varianceGuided
    bool reversedDepth = false;
    float roughnessThreshold = 0.2f;  // alpha
    float mirrorThreshold = 1e-4f;    // alpha
    std::uint32_t samplesPerQuad = 1; // 1, 2 or 4
    bool varianceGuided = false;
    float varianceThreshold = 0.0f; // traces when !(variance <= threshold): NaN counts as high
};

struct SssrClassification {
    std::vector<std::uint8_t> classes; // W x H, kSssr* bits
    std::vector<std::uint32_t> rays;   // packed entries, sorted ascending
    std::vector<std::uint32_t> tiles;  // packed entries of tiles with a glossy pixel, sorted
    std::uint32_t rayCount = 0, tileCount = 0;
    std::uint32_t glossyCount = 0, mirrorCount = 0, copyCount = 0, promotedCount = 0;
};

// Donor search order of a pixel that requires a copy: q^(1,0), q^(0,1), q^(1,1); the first
// inside the image that traces on its own (before promotion) is the donor, else q traces.
SssrClassification sssrClassify(const SssrClassifyInputs& inputs);

// ---------------------------------------------------------------------------------------------
// B. Brute-force ray march over level 0

// Trace space in pixel units: (px, py, d) with pixel (i, j) covering [i, i+1) x [j, j+1).
struct SssrDepthField {
    std::uint32_t width = 0, height = 0;
    std::vector<float> depth; // W x H device depth; background texels hold the far value
    bool reversedDepth = false;
};

struct SssrTraceRay {
    std::array<double, 3> origin{};    // (px, py, d)
    std::array<double, 3> direction{}; // per unit t
    double tEnd = 0.0;                 // already clipped to the image and the near plane
};

// Optional thickness: a texel where the ray is behind the surface is a hit only if the part
// of the segment that is behind comes within `thickness` (view-depth units) of the surface.
struct SssrThickness {
    bool enabled = false;
    double thickness = 0.0;
    std::array<double, 3> viewDepth{1.0, 1.0, 0.0}; // viewDepth(d) = [0] / ([1] + [2] d)
};

enum class SssrMiss : std::uint8_t {
    None,       // hit
    Degenerate, // |D.xy| < 0.01 pixels per unit t: no march
    Escaped,    // left [0,W) x [0,H) or passed tEnd
    WalkCap,    // walked more than W + H + 4 texels (safety net; a bug if it happens)
};

struct SssrMarchResult {
    bool hit = false;
    SssrMiss miss = SssrMiss::None;
    std::int32_t x = -1, y = -1; // hit texel, -1 on a miss
    double t = 0.0;              // hit parameter; on a miss where the walk stopped
    std::uint32_t texelsWalked = 0;
};

constexpr double kSssrMinScreenSpeed = 0.01;     // pixels per unit t
constexpr double kSssrBoundaryOvershoot = 0.005; // pixels past each crossed boundary

// The sanitized depth of texel (i, j): background (sssrIsBackground) holds the far value
// (1 standard, 0 reversed).
double sssrSurfaceDepth(const SssrDepthField& field, std::uint32_t i, std::uint32_t j);

// Walks every texel the ray crosses, after skipping the origin's own texel, and reports the
// first texel where the ray is behind the surface (and, with thickness, not past it).
SssrMarchResult sssrMarch(const SssrDepthField& field, const SssrTraceRay& ray,
                          const SssrThickness& thickness = {});

} // namespace glint::reference
