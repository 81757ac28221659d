#include "reference/shadow_classify_reference.h"

#include "glint/common/glint_wire_formats.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <utility>

namespace glint::reference {
namespace {

// The shader's weights: exp(-3 i^2 / 81) normalized, rounded to multiples of 2^-20 so that a
// row's 17 sum to exactly 1 (row sums and their complements are exact in float).
constexpr float kGaussian[9] = {0.11083221435546875f,    0.10679912567138671875f, 0.09556865692138671875f,
                                0.0794124603271484375f,  0.06127643585205078125f, 0.04390621185302734375f,
                                0.02921390533447265625f, 0.01805019378662109375f, 0.010356903076171875f};

float viewDepthOf(float d, const float c[3]) {
    if (!std::isfinite(d) || !(d > 1e-6f && d < 1.0f - 1e-6f)) return -1.0f;
    const float z = c[0] / (c[1] + c[2] * d);
    return std::isfinite(z) && z > 0.0f ? z : -1.0f;
}

std::array<float, 4> transform(const std::array<float, 16>& m, const std::array<float, 4>& p) {
    std::array<float, 4> q{};
    for (std::size_t r = 0; r < 4; ++r)
        q[r] = m[4 * r] * p[0] + m[4 * r + 1] * p[1] + m[4 * r + 2] * p[2] + m[4 * r + 3] * p[3];
    return q;
}

bool finite(float v) {
    return std::isfinite(v);
}

// Anti-lag constants (docs/shadow_denoiser.md, "Convergence").
constexpr int kAntiLagRadius = 2;         // a 5x5 window
constexpr float kAntiLagThreshold = 1.5f; // binomial sigmas before the history is shortened
constexpr float kAntiLagSlack = 1.0f;     // samples of slack in both variances
constexpr float kAntiLagDepth = 0.1f;     // relative view depth of neighbours on the same surface
constexpr float kAntiLagLength = 4.0f;    // cap = kAntiLagLength / (z - threshold)^2

} // namespace

ShadowClassifyOutputs shadowClassify(const ShadowClassifyInputs& in) {
    const int w = static_cast<int>(in.width);
    const int h = static_cast<int>(in.height);
    const int tilesX = (w + 7) / 8;
    const int tilesY = (h + 3) / 4;
    auto idx = [w](int x, int y) { return std::size_t(y) * std::size_t(w) + std::size_t(x); };
    auto word = [&](int tx, int ty) {
        return in.mask[std::size_t(std::clamp(ty, 0, tilesY - 1)) * std::size_t(tilesX) +
                       std::size_t(std::clamp(tx, 0, tilesX - 1))];
    };
    auto z = [&](int x, int y) { return viewDepthOf(in.depth[idx(x, y)], in.viewDepth); };
    // The shader's penumbra width (glint_shadow_denoiser_penumbra.hlsli) and its 9 x 9 maximum.
    auto penumbraWidth = [&](int x, int y) {
        const float zq = z(x, y);
        if (!(zq > 0.0f) || !(in.penumbraScale > 0.0f)) return 0.0f;
        const std::uint32_t bit = shared::GLINT_WIRE_ShadowMaskBit(std::uint32_t(x), std::uint32_t(y));
        if ((word(x >> 3, y >> 2) >> bit) & 1u) return 0.0f; // lit: no penumbra
        const float b = in.blockerDistance[idx(x, y)];
        if (!finite(b) || b < 0.0f) return 64.0f;
        const float width = in.penumbraScale * b / zq;
        return finite(width) ? std::min(width, 64.0f) : 64.0f;
    };
    auto hard = [&](int x, int y) {
        if (!(in.penumbraScale >= 0.0f)) return false;
        float widest = 0.0f;
        for (int dy = -4; dy <= 4; ++dy)
            for (int dx = -4; dx <= 4; ++dx)
                widest = std::max(widest,
                                  penumbraWidth(std::clamp(x + dx, 0, w - 1), std::clamp(y + dy, 0, h - 1)));
        return widest <= 1.0f;
    };
    // Row y's mask bits from column x - 8 (bit 0) on, from the row's bytes of the three mask
    // tiles around x's (clamped to the mask).
    auto rowWindow = [&](int x, int y) {
        const int row = std::clamp(y, 0, h - 1);
        const std::uint32_t shift = shared::GLINT_WIRE_ShadowMaskBit(0u, static_cast<std::uint32_t>(row));
        const std::uint32_t left = (word((x >> 3) - 1, row >> 2) >> shift) & 0xFFu;
        const std::uint32_t centre = (word(x >> 3, row >> 2) >> shift) & 0xFFu;
        const std::uint32_t right = (word((x >> 3) + 1, row >> 2) >> shift) & 0xFFu;
        return (left | (centre << 8) | (right << 16)) >> (x & 7);
    };
    // This frame's lit samples in the 5x5 window around (x, y).
    auto litInWindow5 = [&](int x, int y) {
        int lit = 0;
        for (int dy = -2; dy <= 2; ++dy) lit += std::popcount((rowWindow(x, y + dy) >> 6) & 0x1Fu);
        return lit;
    };
    auto rowSum = [&](int x, int y) {
        const std::uint32_t window = rowWindow(x, y);
        // The Gaussian weight of the lit and of the shadowed samples, both exact (kGaussian); the
        // second is summed down the column on its own, since 1 - mean is ill-conditioned when
        // only a few edge samples are shadowed.
        float lit = 0.0f;
        for (int k = 0; k <= 16; ++k)
            if ((window >> k) & 1u) lit += kGaussian[std::abs(k - 8)];
        return std::pair{lit, 1.0f - lit};
    };

    auto maskBit = [](int x, int y) {
        return shared::GLINT_WIRE_ShadowMaskBit(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y));
    };
    auto sampleBit = [&](int x, int y) {
        return ((word(x >> 3, y >> 2) >> maskBit(x, y)) & 1u) ? 1.0f : 0.0f;
    };
    // Anti-lag: a static history predicts this frame's bits; a window whose bits contradict
    // last frame's accumulation (compared pixel for pixel, so the penumbra's own shape does not
    // count) caps the history length. Returns the cap (large when the window agrees).
    auto antiLagCap = [&](int x, int y, int px, int py, float zc) {
        const float zPrevious = viewDepthOf(in.previousDepth[idx(px, py)], in.viewDepth);
        float bits = 0.0f, predicted = 0.0f, signedVariance = 0.0f;
        float mismatch = 0.0f, mismatchVariance = 0.0f;
        for (int dy = -kAntiLagRadius; dy <= kAntiLagRadius; ++dy)
            for (int dx = -kAntiLagRadius; dx <= kAntiLagRadius; ++dx) {
                const int cx = x + dx, cy = y + dy, hx = px + dx, hy = py + dy;
                if (cx < 0 || cy < 0 || cx >= w || cy >= h || hx < 0 || hy < 0 || hx >= w || hy >= h)
                    continue;
                // Same surface as the centre in this frame and in the last one.
                const float zNow = z(cx, cy);
                const float zThen = viewDepthOf(in.previousDepth[idx(hx, hy)], in.viewDepth);
                if (!(zNow > 0.0f) || !(zThen > 0.0f) || std::abs(zNow - zc) > kAntiLagDepth * zc ||
                    std::abs(zThen - zPrevious) > kAntiLagDepth * zPrevious)
                    continue;
                // A history: a receiver's finite accumulated shadow with n > 0 samples.
                const float* history = &in.momentsHistory[4 * idx(hx, hy)];
                if (!finite(history[2]) || !finite(history[3]) || !(history[2] > 0.0f)) continue;
                const float n = std::min(history[2], 1023.0f);
                const float hv = std::clamp(history[3], 0.0f, 1.0f);
                const float b = sampleBit(cx, cy);
                // Signed: the bit count against the histories' sum. Binomial variance of a
                // probability regularised by a quarter sample on each side, widened by 1/(n+1)
                // for the history's own estimation error.
                const float p = (hv * n + 0.25f) / (n + 0.5f);
                bits += b;
                predicted += hv;
                signedVariance += p * (1.0f - p) * (1.0f + 1.0f / (n + 1.0f));
                // Absolute: |b - h| against its expectation under the Laplace-regularised
                // probability q; its variance is q(1 - q)(1 - 2h)^2 (|b - h| takes 1 - h or h).
                const float q = (hv * n + 1.0f) / (n + 2.0f);
                mismatch += std::abs(b - hv) - (q * (1.0f - hv) + (1.0f - q) * hv);
                mismatchVariance += q * (1.0f - q) * (1.0f - 2.0f * hv) * (1.0f - 2.0f * hv);
            }
        const float signedScore = std::abs(bits - predicted) / std::sqrt(signedVariance + kAntiLagSlack);
        const float absoluteScore = mismatch / std::sqrt(mismatchVariance + kAntiLagSlack);
        const float excess = std::max(signedScore, absoluteScore) - kAntiLagThreshold;
        return excess > 0.0f ? std::max(kAntiLagLength / (excess * excess), 1.0f) : 1024.0f;
    };

    ShadowClassifyOutputs out;
    const int groupsX = (w + 7) / 8;
    const int groupsY = (h + 7) / 8;
    out.metadata.assign(std::size_t(groupsX) * std::size_t(groupsY), 0u);
    out.shadowVariance.assign(2 * idx(0, h), 0.0f);
    out.moments.assign(4 * idx(0, h), 0.0f);
    for (int gy = 0; gy < groupsY; ++gy)
        for (int gx = 0; gx < groupsX; ++gx) {
            bool anyReceiver = false;
            for (int y = gy * 8; y < std::min(gy * 8 + 8, h); ++y)
                for (int x = gx * 8; x < std::min(gx * 8 + 8, w); ++x)
                    anyReceiver = anyReceiver || z(x, y) > 0.0f;
            std::uint32_t orMask = 0u, andMask = 0xFFFFFFFFu;
            for (int j = -2; j <= 3; ++j)
                for (int i = -1; i <= 1; ++i) {
                    orMask |= word(gx + i, gy * 2 + j);
                    andMask &= word(gx + i, gy * 2 + j);
                }
            const bool allLit = andMask == 0xFFFFFFFFu;
            const bool clear = !anyReceiver || allLit || orMask == 0u;
            out.metadata[std::size_t(gy) * std::size_t(groupsX) + std::size_t(gx)] =
                (clear ? GLINT_WIRE_SHADOW_TILE_CLEAR : 0u) |
                (clear && anyReceiver && allLit ? GLINT_WIRE_SHADOW_TILE_LIGHT : 0u);
            for (int y = gy * 8; y < std::min(gy * 8 + 8, h); ++y)
                for (int x = gx * 8; x < std::min(gx * 8 + 8, w); ++x) {
                    const std::size_t p = idx(x, y);
                    const float zc = z(x, y);
                    const bool receiver = zc > 0.0f;
                    if (clear) {
                        const float value = anyReceiver && allLit && receiver ? 1.0f : 0.0f;
                        out.shadowVariance[2 * p] = receiver ? value : 1.0f; // non-receivers: lit
                        out.moments[4 * p] = value;
                        out.moments[4 * p + 2] = receiver ? 1.0f : 0.0f;
                        out.moments[4 * p + 3] = value;
                        continue;
                    }
                    if (!receiver) {
                        out.shadowVariance[2 * p] = 1.0f; // (1, 0), moments zeros
                        continue;
                    }
                    if (hard(x, y)) {
                        const float sample = ((word(x >> 3, y >> 2) >> maskBit(x, y)) & 1u) ? 1.0f : 0.0f;
                        out.shadowVariance[2 * p] = sample;
                        out.moments[4 * p] = sample;
                        out.moments[4 * p + 2] = 1.0f;
                        out.moments[4 * p + 3] = sample;
                        continue;
                    }
                    float lit = 0.0f, shadowed = 0.0f;
                    for (int r = -8; r <= 8; ++r) {
                        const auto [rowLit, rowShadowed] = rowSum(x, y + r);
                        lit += kGaussian[std::abs(r)] * rowLit;
                        shadowed += kGaussian[std::abs(r)] * rowShadowed;
                    }
                    const float mean = std::clamp(lit, 0.0f, 1.0f);
                    // mean (1 - mean), with 1 - mean summed as such.
                    const float spatialVariance = std::max(mean * std::clamp(shadowed, 0.0f, 1.0f), 0.0f);
                    const float spatialSigma = std::sqrt(spatialVariance);
                    const float sample = ((word(x >> 3, y >> 2) >> maskBit(x, y)) & 1u) ? 1.0f : 0.0f;

                    int mx = x, my = y;
                    float closest = zc;
                    for (int q = 0; q < 4; ++q) {
                        const int ox = std::min((x & ~1) + (q & 1), w - 1);
                        const int oy = std::min((y & ~1) + (q >> 1), h - 1);
                        const float oz = z(ox, oy);
                        if (oz > 0.0f && oz < closest) {
                            closest = oz;
                            mx = ox;
                            my = oy;
                        }
                    }
                    const float u = (float(x) + 0.5f) / float(w);
                    const float v = (float(y) + 0.5f) / float(h);
                    const float up = u + in.motion[2 * idx(mx, my)];
                    const float vp = v + in.motion[2 * idx(mx, my) + 1];
                    bool disoccluded = in.reset || !finite(up) || !finite(vp) || up < 0.0f || vp < 0.0f ||
                                       up > 1.0f || vp > 1.0f;
                    const int px = std::min(int(up * float(w)), w - 1);
                    const int py = std::min(int(vp * float(h)), h - 1);
                    if (!disoccluded) {
                        const std::array<float, 4> ndc{2.0f * u - 1.0f, in.ndcYSign * (2.0f * v - 1.0f),
                                                       in.depth[p], 1.0f};
                        const std::array<float, 4> clip = transform(in.reprojection, ndc);
                        const float zr = viewDepthOf(clip[2] / clip[3], in.viewDepth);
                        const float zp = viewDepthOf(in.previousDepth[idx(px, py)], in.viewDepth);
                        const std::array<float, 4> world = transform(in.inverseViewProjection, ndc);
                        float e[3], n[3];
                        for (std::size_t k = 0; k < 3; ++k) {
                            e[k] = in.eye[k] - world[k] / world[3];
                            n[k] = in.normals[4 * p + k];
                        }
                        const float el = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
                        const float nl = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
                        float cosine = std::abs((e[0] * n[0] + e[1] * n[1] + e[2] * n[2]) / (el * nl));
                        cosine = finite(cosine) ? std::min(cosine, 1.0f) : 0.0f;
                        const float threshold = 0.01f + (0.1f - 0.01f) * std::pow(1.0f - cosine, 8.0f);
                        const float relative = std::abs(zp - zr) / zr;
                        disoccluded = !(zr > 0.0f) || !(zp > 0.0f) || !(relative < threshold);
                    }
                    float m = 0.0f, m2 = 0.0f, count = 0.0f, history = mean;
                    bool found = false;
                    if (!disoccluded) {
                        const std::size_t q = idx(px, py);
                        const float* loaded = &in.momentsHistory[4 * q];
                        const float fx = up * float(w) - 0.5f, fy = vp * float(h) - 0.5f;
                        const int bx = int(std::floor(fx)), by = int(std::floor(fy));
                        const float tx = fx - float(bx), ty = fy - float(by);
                        auto hist = [&](int hx, int hy) {
                            return in
                                .momentsHistory[4 * idx(std::clamp(hx, 0, w - 1), std::clamp(hy, 0, h - 1)) +
                                                3];
                        };
                        const float top = hist(bx, by) + (hist(bx + 1, by) - hist(bx, by)) * tx;
                        const float bottom =
                            hist(bx, by + 1) + (hist(bx + 1, by + 1) - hist(bx, by + 1)) * tx;
                        const float bilinear = top + (bottom - top) * ty;
                        if (finite(loaded[0]) && finite(loaded[1]) && finite(loaded[2]) && finite(bilinear)) {
                            m = std::clamp(loaded[0], 0.0f, 1.0f);
                            m2 = std::max(loaded[1], 0.0f);
                            count = std::clamp(loaded[2], 0.0f, 1023.0f);
                            history = std::clamp(bilinear, 0.0f, 1.0f);
                            found = true;
                        }
                    }
                    float n = count + 1.0f;
                    const float delta = sample - m;
                    const float newMean = m + delta / n;
                    const float newM2 = m2 + delta * (sample - newMean);
                    // The 5x5 samples' binomial variance: a first sample's (times 4, at most 1)
                    // and the least a young history lends the filter.
                    const float litShare = static_cast<float>(litInWindow5(x, y)) / 25.0f;
                    const float windowVariance = litShare * (1.0f - litShare);
                    const float temporalVariance =
                        n > 1.0f ? newM2 / (n - 1.0f) : std::min(4.0f * windowVariance, 1.0f);
                    // Wide clamp (2 sigma_s, widened to hold the sample), blend max(1/n, 1/64),
                    // variance of the mean scaled.
                    const float radius = 2.0f * spatialSigma;
                    const float clamped =
                        std::clamp(history, std::min(mean - radius, sample), std::max(mean + radius, sample));
                    const float deviation = (history - mean) / std::max(radius, 0.001f);
                    n *= std::exp(-deviation * deviation / 20.0f);
                    if (found && in.antiLag) n = std::min(n, antiLagCap(x, y, px, py, zc));
                    const float samples = std::max(n, 1.0f);
                    const float spread =
                        n < 16.0f ? std::max(temporalVariance, windowVariance) * std::max(16.0f - n, 1.0f)
                                  : temporalVariance;
                    const float variance = spread / samples * in.storedVarianceScale;
                    const float alpha = std::max(1.0f / samples, 1.0f / 64.0f);
                    float result = std::clamp(clamped + (sample - clamped) * alpha, 0.0f, 1.0f);
                    result = finite(result) ? result : 0.0f;
                    out.shadowVariance[2 * p] = result;
                    out.shadowVariance[2 * p + 1] = std::max(finite(variance) ? variance : 0.0f, 0.0f);
                    out.moments[4 * p] = std::clamp(finite(newMean) ? newMean : 0.0f, 0.0f, 1.0f);
                    out.moments[4 * p + 1] = std::max(finite(newM2) ? newM2 : 0.0f, 0.0f);
                    out.moments[4 * p + 3] = result;
                    out.moments[4 * p + 2] = finite(n) ? n : 0.0f;
                }
        }
    return out;
}

} // namespace glint::reference
