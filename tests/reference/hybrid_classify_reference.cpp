// Written from docs/hybrid.md ("Feedback counter", "Classification", "Parameters"), not from the
// shader: each tile's class is a vote of two lottery draws against its chosen statistics, the
// statistics are the best of a candidate list, and every ray of the SSSR per-pixel decision
// (sssr_reference.h) walks the documented routing rules top to bottom.
#include "reference/hybrid_classify_reference.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace glint::reference {
namespace {

// docs/hybrid.md, "Feedback counter": four 8-bit fields, bits 0-7, 8-15, 16-23, 24-31.
struct FeedbackFields {
    std::uint32_t hitsThisFrame, hitsLastFrame, missesThisFrame, missesLastFrame;
};

std::uint32_t byteAt(std::uint32_t word, std::uint32_t firstBit) {
    return (word >> firstBit) % 256u;
}

FeedbackFields unpackFeedback(std::uint32_t word) {
    return {byteAt(word, 0), byteAt(word, 8), byteAt(word, 16), byteAt(word, 24)};
}

std::uint32_t packFeedback(const FeedbackFields& f) {
    return f.hitsThisFrame | f.hitsLastFrame << 8 | f.missesThisFrame << 16 | f.missesLastFrame << 24;
}

struct Image {
    std::uint32_t width, height, tilesX, tilesY;
};

// Step 1: r = hash(tileIndex xor hash(frame)).
std::uint32_t randomWord(const Image& image, std::uint32_t tx, std::uint32_t ty, std::uint32_t frame) {
    return hybridHash((ty * image.tilesX + tx) ^ hybridHash(frame));
}

// u = (r >> 8) / 2^24: a 24-bit integer scaled by a power of two, exact in float.
float lotteryNumber(std::uint32_t r) {
    return std::ldexp(static_cast<float>(r >> 8), -24);
}

// Step 4's rule SW(h, m, u) := u <= s + h - w m, in float.
bool screenSpaceWins(const HybridClassifyInputs& in, std::uint32_t hits, std::uint32_t misses, float u) {
    float bound = in.spawnRate;
    bound += static_cast<float>(hits);
    bound -= in.missWeight * static_cast<float>(misses);
    return u <= bound;
}

// Step 2: the counter of the history tile the random pixel came from, or nothing.
std::optional<std::uint32_t> reprojectedCounter(const HybridClassifyInputs& in, const Image& image,
                                                std::uint32_t tx, std::uint32_t ty) {
    const std::uint32_t r = randomWord(image, tx, ty, in.frameIndex);
    const std::uint32_t x = std::min(8 * tx + r % 8, image.width - 1);
    const std::uint32_t y = std::min(8 * ty + r / 8 % 8, image.height - 1);
    const std::size_t pixel = std::size_t{y} * image.width + x;
    const float mx = in.motion[2 * pixel], my = in.motion[2 * pixel + 1];
    if (!std::isfinite(mx) || !std::isfinite(my)) return std::nullopt;
    const float w = static_cast<float>(image.width), h = static_cast<float>(image.height);
    const float previousU = (static_cast<float>(x) + 0.5f) / w + mx;
    const float previousV = (static_cast<float>(y) + 0.5f) / h + my;
    const bool onScreen = previousU >= 0.0f && previousU < 1.0f && previousV >= 0.0f && previousV < 1.0f;
    if (!onScreen) return std::nullopt;
    const auto previousX = std::min(static_cast<std::uint32_t>(std::floor(previousU * w)), image.width - 1);
    const auto previousY = std::min(static_cast<std::uint32_t>(std::floor(previousV * h)), image.height - 1);
    return in.history[std::size_t{previousY / 8} * image.tilesX + previousX / 8];
}

// Steps 2-3: the reprojected counter (0 without statistics) unless a tile of the safe band has
// strictly more fresh hits; std::max_element returns the first of equal maxima, and the band is
// listed in row order, which is the documented tie rule.
std::uint32_t chosenHistory(const HybridClassifyInputs& in, const Image& image, std::uint32_t tx,
                            std::uint32_t ty) {
    const std::uint32_t reprojected = reprojectedCounter(in, image, tx, ty).value_or(0u);
    std::vector<std::uint32_t> band;
    for (std::uint32_t y = ty == 0 ? 0 : ty - 1; y <= std::min(ty + 1, image.tilesY - 1); ++y)
        for (std::uint32_t x = tx == 0 ? 0 : tx - 1; x <= std::min(tx + 1, image.tilesX - 1); ++x)
            band.push_back(in.history[std::size_t{y} * image.tilesX + x]);
    const auto freshHits = [](std::uint32_t a, std::uint32_t b) {
        return unpackFeedback(a).hitsThisFrame < unpackFeedback(b).hitsThisFrame;
    };
    const std::uint32_t best = *std::max_element(band.begin(), band.end(), freshHits);
    return freshHits(reprojected, best) ? best : reprojected;
}

// Step 4: the switches first, then two votes for screen space, one per frame's statistics.
std::uint32_t tileClassFrom(const HybridClassifyInputs& in, const Image& image, std::uint32_t tx,
                            std::uint32_t ty, const FeedbackFields& stats) {
    if (!in.rayTracing || !in.feedback) return kHybridFullSw;
    if (!in.screenSpace) return kHybridFullHw;
    const float uThisFrame = lotteryNumber(randomWord(image, tx, ty, in.frameIndex));
    const float uLastFrame = lotteryNumber(randomWord(image, tx, ty, in.frameIndex - 1u));
    const int votes = int{screenSpaceWins(in, stats.hitsThisFrame, stats.missesThisFrame, uThisFrame)} +
                      int{screenSpaceWins(in, stats.hitsLastFrame, stats.missesLastFrame, uLastFrame)};
    return votes == 2 ? kHybridFullSw : votes == 1 ? kHybridHalfSw : kHybridFullHw;
}

// The routing rules of docs/hybrid.md, the first that applies.
bool routedToScreenSpace(const HybridClassifyInputs& in, std::uint32_t tileClass, std::uint32_t x,
                         std::uint32_t y, float alpha) {
    if (!in.rayTracing) return true;
    if (!in.screenSpace) return false;
    const bool mirror = alpha < in.sssr.mirrorThreshold;
    if (in.mirrorsRayTraced && mirror) return false;
    if (alpha >= in.rayTracingThreshold) return true;
    switch (tileClass) {
    case kHybridFullSw:
        return true;
    case kHybridFullHw:
        return false;
    default: {
        const std::uint32_t phase = in.alternateCheckerboard ? in.frameIndex : 0u;
        return (x + y + phase) % 2 == 0; // the low bit of x xor y xor phase is that of the sum
    }
    }
}

} // namespace

std::uint32_t hybridHash(std::uint32_t x) {
    const std::uint32_t s = x * 747796405u + 2891336453u;
    const std::uint32_t w = ((s >> ((s >> 28) + 4)) ^ s) * 277803737u;
    return (w >> 22) ^ w;
}

HybridClassification hybridClassify(const HybridClassifyInputs& in) {
    const Image image{in.sssr.width, in.sssr.height, (in.sssr.width + 7) / 8, (in.sssr.height + 7) / 8};
    HybridClassification out;
    out.tilesX = image.tilesX;
    out.tilesY = image.tilesY;
    out.tileClass.resize(std::size_t{image.tilesX} * image.tilesY);
    out.feedback.resize(out.tileClass.size());

    const SssrClassification pixels = sssrClassify(in.sssr);
    out.tiles = pixels.tiles;

    // Each ray asks for its tile's class; tiles without a ray are decided after, since their
    // class and counter are written too.
    std::vector<bool> decided(out.tileClass.size(), false);
    const auto decide = [&](std::uint32_t tx, std::uint32_t ty) {
        const std::size_t tile = std::size_t{ty} * image.tilesX + tx;
        if (!decided[tile]) {
            const FeedbackFields stats = unpackFeedback(chosenHistory(in, image, tx, ty));
            out.tileClass[tile] = tileClassFrom(in, image, tx, ty, stats);
            out.feedback[tile] = packFeedback({0, stats.hitsThisFrame, 0, stats.missesThisFrame});
            decided[tile] = true;
        }
        return static_cast<std::uint32_t>(tile);
    };
    for (const std::uint32_t entry : pixels.rays) {
        const std::uint32_t x = entry & 0x7FFFu, y = (entry >> 15) & 0x3FFFu;
        const std::uint32_t tile = decide(x / 8, y / 8);
        const float alpha = in.sssr.alpha[std::size_t{y} * image.width + x];
        auto& list =
            routedToScreenSpace(in, out.tileClass[tile], x, y, alpha) ? out.screenSpace : out.rayTraced;
        list[tile].insert(entry);
    }
    for (std::uint32_t ty = 0; ty < image.tilesY; ++ty)
        for (std::uint32_t tx = 0; tx < image.tilesX; ++tx) decide(tx, ty);
    return out;
}

} // namespace glint::reference
