#include "reference/hybrid_classify_reference.h"

#include <algorithm>
#include <cmath>

namespace glint::reference {
namespace {

struct Counter {
    std::uint32_t hits, lastHits, misses, lastMisses;
};

Counter fields(std::uint32_t word) {
    return {word & 0xFFu, (word >> 8) & 0xFFu, (word >> 16) & 0xFFu, word >> 24};
}

// The lottery: the tile's index hashed with the hash of the frame; u from the top 24 bits.
std::uint32_t tileWord(std::uint32_t tileIndex, std::uint32_t frame) {
    return hybridHash(tileIndex ^ hybridHash(frame));
}

float lottery(std::uint32_t word) {
    return static_cast<float>(word >> 8) / 16777216.0f; // exact: 24 bits
}

// SW(h, m, u) := u <= s + h - w m, in float as the shader evaluates it (with the tests' miss
// weights w m is exact, so a fused multiply-add gives the same value).
bool prefersScreenSpace(const HybridClassifyInputs& in, std::uint32_t hits, std::uint32_t misses, float u) {
    const float spawnAndHits = in.spawnRate + static_cast<float>(hits);
    return u <= spawnAndHits - in.missWeight * static_cast<float>(misses);
}

} // namespace

std::uint32_t hybridHash(std::uint32_t x) {
    const std::uint32_t state = x * 747796405u + 2891336453u;
    const std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

HybridClassification hybridClassify(const HybridClassifyInputs& in) {
    const std::uint32_t w = in.sssr.width, h = in.sssr.height;
    HybridClassification out;
    out.tilesX = (w + 7) / 8;
    out.tilesY = (h + 7) / 8;
    const std::uint32_t tileCount = out.tilesX * out.tilesY;
    out.tileClass.assign(tileCount, kHybridFullSw);
    out.feedback.assign(tileCount, 0);

    for (std::uint32_t ty = 0; ty < out.tilesY; ++ty)
        for (std::uint32_t tx = 0; tx < out.tilesX; ++tx) {
            const std::uint32_t index = ty * out.tilesX + tx;
            // The random pixel of the tile this frame, clamped into the image.
            const std::uint32_t word = tileWord(index, in.frameIndex);
            const std::uint32_t px = std::min(tx * 8 + (word & 7u), w - 1);
            const std::uint32_t py = std::min(ty * 8 + ((word >> 3) & 7u), h - 1);
            // Its previous position, in float as the shader computes it.
            const float invW = 1.0f / static_cast<float>(w), invH = 1.0f / static_cast<float>(h);
            const float u =
                (static_cast<float>(px) + 0.5f) * invW + in.motion[2 * (std::size_t{py} * w + px)];
            const float v =
                (static_cast<float>(py) + 0.5f) * invH + in.motion[2 * (std::size_t{py} * w + px) + 1];
            std::uint32_t reprojected = 0; // no statistics off screen or for non-finite motion
            if (u >= 0.0f && u < 1.0f && v >= 0.0f && v < 1.0f) {
                const std::uint32_t qx =
                    std::min(static_cast<std::uint32_t>(u * static_cast<float>(w)), w - 1);
                const std::uint32_t qy =
                    std::min(static_cast<std::uint32_t>(v * static_cast<float>(h)), h - 1);
                reprojected = in.history[(qy / 8) * out.tilesX + qx / 8];
            }
            // The safe band: the 3x3 tiles at this tile's own position; most fresh hits wins,
            // but only when it beats the reprojected tile.
            std::uint32_t chosen = reprojected;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = static_cast<int>(tx) + dx, ny = static_cast<int>(ty) + dy;
                    if (nx < 0 || ny < 0 || nx >= static_cast<int>(out.tilesX) ||
                        ny >= static_cast<int>(out.tilesY))
                        continue;
                    const std::uint32_t candidate =
                        in.history[static_cast<std::size_t>(ny) * out.tilesX + static_cast<std::size_t>(nx)];
                    if (fields(candidate).hits > fields(chosen).hits) chosen = candidate;
                }
            const Counter c = fields(chosen);
            out.feedback[index] = (c.hits << 8) | (c.misses << 24);
            std::uint32_t tileClass = kHybridFullSw;
            if (!in.rayTracing)
                tileClass = kHybridFullSw;
            else if (!in.screenSpace)
                tileClass = kHybridFullHw;
            else if (in.feedback) {
                const bool now = prefersScreenSpace(in, c.hits, c.misses, lottery(word));
                const bool before = prefersScreenSpace(in, c.lastHits, c.lastMisses,
                                                       lottery(tileWord(index, in.frameIndex - 1u)));
                tileClass = now && before ? kHybridFullSw : !now && !before ? kHybridFullHw : kHybridHalfSw;
            }
            out.tileClass[index] = tileClass;
        }

    const SssrClassification pixels = sssrClassify(in.sssr);
    out.tiles = pixels.tiles;
    for (const std::uint32_t entry : pixels.rays) {
        const std::uint32_t x = entry & 0x7FFFu, y = (entry >> 15) & 0x3FFFu;
        const std::uint32_t tile = (y / 8) * out.tilesX + x / 8;
        const float alpha = in.sssr.alpha[std::size_t{y} * w + x];
        bool screenSpace;
        if (!in.rayTracing)
            screenSpace = true;
        else if (!in.screenSpace)
            screenSpace = false;
        else if (in.mirrorsRayTraced && alpha < in.sssr.mirrorThreshold)
            screenSpace = false;
        else if (!(alpha < in.rayTracingThreshold))
            screenSpace = true;
        else if (out.tileClass[tile] == kHybridHalfSw) {
            const std::uint32_t phase = in.alternateCheckerboard ? in.frameIndex : 0u;
            screenSpace = ((x ^ y ^ phase) & 1u) == 0;
        } else
            screenSpace = out.tileClass[tile] == kHybridFullSw;
        (screenSpace ? out.screenSpace : out.rayTraced)[tile].insert(entry);
    }
    return out;
}

} // namespace glint::reference
