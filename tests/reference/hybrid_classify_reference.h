// CPU reference of the hybrid tile classification (docs/hybrid.md, "Classification"), written
// from the specification: the SSSR per-pixel decision (sssr_reference.h) decides which pixels
// own a ray; the feedback history, the per-tile lottery and the decision rule decide each
// tile's class; the class, the ray-tracing threshold and the material override route each ray.
#pragma once

#include "reference/sssr_reference.h"

#include <cstdint>
#include <map>
#include <set>
#include <vector>

namespace glint::reference {

constexpr std::uint32_t kHybridFullSw = 0, kHybridHalfSw = 1, kHybridFullHw = 2;

struct HybridClassifyInputs {
    SssrClassifyInputs sssr;            // G-buffer, thresholds, samples per quad
    std::vector<float> motion;          // W x H x 2: uv_prev = uv + motion (convention A)
    std::vector<std::uint32_t> history; // ceil(W/8) x ceil(H/8) feedback counters of last frame
    std::uint32_t frameIndex = 0;
    bool screenSpace = true, rayTracing = true, feedback = true, alternateCheckerboard = true;
    bool mirrorsRayTraced = false;
    float spawnRate = 0.02f, missWeight = 0.5f, rayTracingThreshold = 0.22f;
};

struct HybridClassification {
    std::uint32_t tilesX = 0, tilesY = 0;
    std::vector<std::uint32_t> tileClass; // per tile
    std::vector<std::uint32_t> feedback;  // per tile: the counter classification writes
    // Per tile (index y * tilesX + x): its screen-space entries, and its ray-traced ones.
    std::map<std::uint32_t, std::set<std::uint32_t>> screenSpace, rayTraced;
    std::vector<std::uint32_t> tiles; // the denoiser's tile list, sorted (as SSSR's)
};

// PCG hash (docs/hybrid.md): state = x * 747796405 + 2891336453; word = ((state >>
// ((state >> 28) + 4)) ^ state) * 277803737; result (word >> 22) ^ word, all mod 2^32.
std::uint32_t hybridHash(std::uint32_t x);

HybridClassification hybridClassify(const HybridClassifyInputs& inputs);

} // namespace glint::reference
