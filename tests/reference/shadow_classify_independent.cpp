#include "reference/shadow_classify_independent.h"

#include "glint/common/glint_wire_formats.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace glint::reference {
namespace {

// docs/shadow_denoiser.md, "Classification and temporal accumulation".
constexpr double kClampSigmas = 2.0; // the history is clamped to mu +- 2 sigma_s
constexpr double kHistoryCap = 64.0; // blend max(1/N, 1/64)
constexpr double kMaxCount = 1023.0; // n of a loaded history
constexpr int kAntiLagRadius = 2;    // 5x5
constexpr double kAntiLagThreshold = 1.5;
constexpr double kAntiLagLength = 4.0; // n' <= max(4 / (z - 1.5)^2, 1)
constexpr double kAntiLagSlack = 1.0;  // samples of slack in both variances
constexpr double kAntiLagDepth = 0.1;  // neighbours within 10 % of the centre's view depth

// Margins for decisions the device takes in float (see the header).
constexpr double kPixelEdgeMargin = 1e-4;  // pixels, for floor(uv_prev * size)
constexpr double kRelativeMargin = 1e-4;   // relative, for depth comparisons against thresholds
constexpr double kLengthStepMargin = 0.02; // samples, around the variance boost's step at n' = 16
// The device's float error on the bilinear history: uv_prev * size carries about 2e-7 * W
// pixels of rounding (4e-5 at W = 203), and the history changes by at most its range, 1, per
// pixel. It matters where sigma_s is small: the damping divides h - mu by max(2 sigma_s, 0.001).
constexpr double kHistorySlack = 5e-5;
// The device's float error on the anti-lag scores: sums of up to 25 terms below 25, each add
// rounding by half an ulp of 25 (1e-6), in each of the two sums, divided by at least 1.
constexpr double kScoreSlack = 1e-4;
// Hard shadows (docs/shadow_denoiser.md, "Hard shadows pass through"): a receiver whose 9 x 9
// neighbourhood holds no penumbra wider than one pixel passes through. The device computes the
// widths in float (relative error a few 1e-7): a widest width this close to 1 is ambiguous.
constexpr int kHardRadius = 4;
constexpr double kHardWidth = 1.0;
constexpr double kUnknownPenumbra = 64.0; // an unknown blocker: a wide penumbra
constexpr double kPenumbraMargin = 1e-5;

struct Image {
    int w = 0, h = 0;
    std::size_t at(int x, int y) const { return std::size_t(y) * std::size_t(w) + std::size_t(x); }
    bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < w && y < h; }
};

double viewDepth(float d, const float c[3]) {
    if (!std::isfinite(d) || !(d > 1e-6f && d < 1.0f - 1e-6f)) return -1.0;
    const double z = double(c[0]) / (double(c[1]) + double(c[2]) * double(d));
    return std::isfinite(z) && z > 0.0 ? z : -1.0;
}

std::array<double, 4> transform(const std::array<float, 16>& m, const std::array<double, 4>& p) {
    std::array<double, 4> q{};
    for (std::size_t r = 0; r < 4; ++r)
        for (std::size_t c = 0; c < 4; ++c) q[r] += double(m[4 * r + c]) * p[c];
    return q;
}

bool finite(double v) {
    return std::isfinite(v);
}

// What does not depend on the window mean, and the outputs as a function of it.
struct Pixel {
    double sample = 0.0;
    bool found = false; // a history was found
    double m = 0.0, m2 = 0.0, count = 0.0;
    double history = 0.0;        // bilinear accumulated shadow (when found)
    double windowVariance = 0.0; // binomial variance of this frame's 5x5 samples
    double antiLagScore = -1;    // the larger of the two scores (negative: no test)
};

double antiLagCap(double score) {
    const double excess = score - kAntiLagThreshold;
    return excess > 0.0 ? std::max(kAntiLagLength / (excess * excess), 1.0) : 1e30;
}

struct Result {
    double shadowVariance[2];
    double moments[4];
    double lengthBeforeClamp; // n' after damping and the cap
};

Result evaluate(const Pixel& p, double mean, double historyOffset, double scoreOffset,
                double storedVarianceScale) {
    mean = std::clamp(mean, 0.0, 1.0);
    const double spatialVariance = mean * (1.0 - mean);
    const double sigma = std::sqrt(spatialVariance);
    double n = p.count + 1.0;
    const double newMean = p.m + (p.sample - p.m) / n;
    const double newM2 = p.m2 + (p.sample - p.m) * (p.sample - newMean);
    // No history: four times the 5x5 samples' variance, at most 1.
    const double temporalVariance = n > 1.0 ? newM2 / (n - 1.0) : std::min(4.0 * p.windowVariance, 1.0);
    const double history = p.found ? std::clamp(p.history + historyOffset, 0.0, 1.0) : mean;
    const double radius = kClampSigmas * sigma;
    // The range holds this frame's sample (docs/shadow_denoiser.md, "Classification").
    const double clamped =
        std::clamp(history, std::min(mean - radius, p.sample), std::max(mean + radius, p.sample));
    const double deviation = (history - mean) / std::max(radius, 0.001);
    n *= std::exp(-deviation * deviation / 20.0);
    if (p.found && p.antiLagScore >= 0.0) n = std::min(n, antiLagCap(p.antiLagScore + scoreOffset));
    const double samples = std::max(n, 1.0);
    const double spread =
        n < 16.0 ? std::max(temporalVariance, p.windowVariance) * std::max(16.0 - n, 1.0) : temporalVariance;
    const double variance = spread / samples * storedVarianceScale;
    const double alpha = std::max(1.0 / samples, 1.0 / kHistoryCap);
    const double out = std::clamp(clamped + (p.sample - clamped) * alpha, 0.0, 1.0);
    Result r{};
    r.shadowVariance[0] = out;
    r.shadowVariance[1] = std::max(variance, 0.0);
    r.moments[0] = std::clamp(newMean, 0.0, 1.0);
    r.moments[1] = std::max(newM2, 0.0);
    r.moments[2] = n;
    r.moments[3] = out;
    r.lengthBeforeClamp = n;
    return r;
}

bool nearInteger(double v) {
    return std::abs(v - std::round(v)) < kPixelEdgeMargin;
}

} // namespace

ShadowClassifyRanges shadowClassifyIndependent(const ShadowClassifyInputs& in,
                                               const std::vector<float>& visibility) {
    const Image img{int(in.width), int(in.height)};
    const int w = img.w, h = img.h;
    const int tilesX = (w + 7) / 8, tilesY = (h + 3) / 4;
    const std::size_t count = img.at(0, h);

    // Lit samples: >= 0.5 (NaN is not).
    std::vector<double> litImage(count);
    for (std::size_t p = 0; p < count; ++p) litImage[p] = visibility[p] >= 0.5f ? 1.0 : 0.0;
    auto lit = [&](int x, int y) { return litImage[img.at(x, y)]; };
    // The documented addressing of the 17x17 window and of the uniform test's mask tiles: a
    // column outside the image reads the border tile (tile index clamped, same bit column), a
    // bit outside the image repeats the nearest pixel, a row outside it the border row.
    auto windowSample = [&](int c, int r) {
        const int tile = std::clamp(c >= 0 ? c / 8 : -((-c + 7) / 8), 0, tilesX - 1);
        const int column = std::min(tile * 8 + (((c % 8) + 8) % 8), w - 1);
        return lit(column, std::clamp(r, 0, h - 1));
    };
    auto tileBits = [&](int tx, int ty, bool& anyLit, bool& anyShadowed) {
        tx = std::clamp(tx, 0, tilesX - 1);
        ty = std::clamp(ty, 0, tilesY - 1);
        for (int by = 0; by < 4; ++by)
            for (int bx = 0; bx < 8; ++bx) {
                const bool on = lit(std::min(tx * 8 + bx, w - 1), std::min(ty * 4 + by, h - 1)) > 0.0;
                anyLit = anyLit || on;
                anyShadowed = anyShadowed || !on;
            }
    };

    double weights[17], total = 0.0;
    for (int i = -8; i <= 8; ++i) total += weights[i + 8] = std::exp(-3.0 * i * i / 81.0);
    for (double& weight : weights) weight /= total;

    std::vector<double> zImage(count), zPreviousImage(count);
    for (std::size_t p = 0; p < count; ++p) {
        zImage[p] = viewDepth(in.depth[p], in.viewDepth);
        zPreviousImage[p] = viewDepth(in.previousDepth[p], in.viewDepth);
    }
    auto z = [&](int x, int y) { return zImage[img.at(x, y)]; };
    auto zPrevious = [&](int x, int y) { return zPreviousImage[img.at(x, y)]; };
    // The 17x17 Gaussian is separable: each in-image row's horizontal sums first.
    std::vector<double> rowSums(count, 0.0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int k = -8; k <= 8; ++k) rowSums[img.at(x, y)] += weights[k + 8] * windowSample(x + k, y);
    // The widest penumbra W = scale * blocker / z over the 9 x 9 neighbourhood, coordinates
    // clamped to the image; non-receivers, lit samples (whatever their blocker) and a light of
    // size 0 imply none.
    std::vector<double> penumbraWidth(count, 0.0);
    for (std::size_t p = 0; in.penumbraScale > 0.0f && p < count; ++p) {
        const double zq = zImage[p];
        if (!(zq > 0.0) || litImage[p] > 0.5) continue; // lit: none
        const double b = in.blockerDistance[p];
        penumbraWidth[p] =
            std::isfinite(b) && b >= 0.0 ? double(in.penumbraScale) * b / zq : kUnknownPenumbra;
    }
    auto widestPenumbra = [&](int x, int y) {
        double widest = 0.0;
        for (int dy = -kHardRadius; dy <= kHardRadius; ++dy)
            for (int dx = -kHardRadius; dx <= kHardRadius; ++dx)
                widest = std::max(
                    widest,
                    penumbraWidth[img.at(std::clamp(x + dx, 0, w - 1), std::clamp(y + dy, 0, h - 1))]);
        return widest;
    };

    ShadowClassifyRanges out;
    const int groupsX = (w + 7) / 8, groupsY = (h + 7) / 8;
    out.metadata.assign(std::size_t(groupsX) * std::size_t(groupsY), 0u);
    out.shadowVarianceLow.assign(2 * count, 0.0);
    out.shadowVarianceHigh.assign(2 * count, 0.0);
    out.momentsLow.assign(4 * count, 0.0);
    out.momentsHigh.assign(4 * count, 0.0);
    out.ambiguous.assign(count, 0u);
    auto store = [&](std::size_t p, const double sv[2], const double moments[4]) {
        for (std::size_t c = 0; c < 2; ++c)
            out.shadowVarianceLow[2 * p + c] = out.shadowVarianceHigh[2 * p + c] = sv[c];
        for (std::size_t c = 0; c < 4; ++c)
            out.momentsLow[4 * p + c] = out.momentsHigh[4 * p + c] = moments[c];
    };

    for (int gy = 0; gy < groupsY; ++gy)
        for (int gx = 0; gx < groupsX; ++gx) {
            // Sky: no receiver in the block. Uniform: the 3x6 mask tiles around it, all lit or
            // all shadowed. Either clears it.
            bool anyReceiver = false;
            for (int y = gy * 8; y < std::min(gy * 8 + 8, h); ++y)
                for (int x = gx * 8; x < std::min(gx * 8 + 8, w); ++x)
                    anyReceiver = anyReceiver || z(x, y) > 0.0;
            bool anyLit = false, anyShadowed = false;
            for (int j = -2; j <= 3; ++j)
                for (int i = -1; i <= 1; ++i) tileBits(gx + i, 2 * gy + j, anyLit, anyShadowed);
            const bool allLit = !anyShadowed, allShadowed = !anyLit;
            const bool clear = !anyReceiver || allLit || allShadowed;
            out.metadata[std::size_t(gy) * std::size_t(groupsX) + std::size_t(gx)] =
                (clear ? GLINT_WIRE_SHADOW_TILE_CLEAR : 0u) |
                (clear && anyReceiver && allLit ? GLINT_WIRE_SHADOW_TILE_LIGHT : 0u);

            for (int y = gy * 8; y < std::min(gy * 8 + 8, h); ++y)
                for (int x = gx * 8; x < std::min(gx * 8 + 8, w); ++x) {
                    const std::size_t p = img.at(x, y);
                    const double zc = z(x, y);
                    const bool receiver = zc > 0.0;
                    if (clear) {
                        // (value, 0), moments (value, 0, receiver ? 1 : 0, value); a
                        // non-receiver's shadow is 1 (lit, docs/shadow_denoiser.md).
                        const double value = anyReceiver && allLit && receiver ? 1.0 : 0.0;
                        const double sv[2] = {receiver ? value : 1.0, 0.0};
                        const double moments[4] = {value, 0.0, receiver ? 1.0 : 0.0, value};
                        store(p, sv, moments);
                        continue;
                    }
                    if (!receiver) { // (1, 0), moments zeros
                        const double sv[2] = {1.0, 0.0};
                        const double moments[4] = {0.0, 0.0, 0.0, 0.0};
                        store(p, sv, moments);
                        continue;
                    }
                    if (in.penumbraScale >= 0.0f) {
                        const double widest = widestPenumbra(x, y);
                        if (std::abs(widest - kHardWidth) <= kPenumbraMargin) {
                            out.ambiguous[p] = 1u;
                            continue;
                        }
                        if (widest < kHardWidth) { // its sample, and a one-sample history
                            const double sample = lit(x, y);
                            const double sv[2] = {sample, 0.0};
                            const double moments[4] = {sample, 0.0, 1.0, sample};
                            store(p, sv, moments);
                            continue;
                        }
                    }

                    // The 17x17 Gaussian mean, in double with the exact weights.
                    double mean = 0.0;
                    for (int r = -8; r <= 8; ++r)
                        mean += weights[r + 8] * rowSums[img.at(x, std::clamp(y + r, 0, h - 1))];

                    Pixel px;
                    px.sample = lit(x, y);
                    double windowLit = 0.0;
                    for (int r = -2; r <= 2; ++r)
                        for (int k = -2; k <= 2; ++k) windowLit += windowSample(x + k, y + r);
                    px.windowVariance = windowLit / 25.0 * (1.0 - windowLit / 25.0);
                    bool ambiguous = false;

                    // The motion of the quad's closest receiver (the pixel's own unless another
                    // is strictly closer; a tie between different motions is ambiguous).
                    int mx = x, my = y;
                    double closest = zc;
                    for (int q = 0; q < 4; ++q) {
                        const int ox = std::min((x & ~1) + (q & 1), w - 1),
                                  oy = std::min((y & ~1) + (q >> 1), h - 1);
                        const double oz = z(ox, oy);
                        if (!(oz > 0.0)) continue;
                        const bool sameMotion =
                            in.motion[2 * img.at(ox, oy)] == in.motion[2 * img.at(mx, my)] &&
                            in.motion[2 * img.at(ox, oy) + 1] == in.motion[2 * img.at(mx, my) + 1];
                        if (!sameMotion && std::abs(oz - closest) <= kRelativeMargin * closest)
                            ambiguous = true;
                        if (oz < closest) {
                            closest = oz;
                            mx = ox;
                            my = oy;
                        }
                    }
                    const double u = (x + 0.5) / w, v = (y + 0.5) / h;
                    const double up = u + double(in.motion[2 * img.at(mx, my)]);
                    const double vp = v + double(in.motion[2 * img.at(mx, my) + 1]);
                    bool disoccluded = in.reset || !finite(up) || !finite(vp) || up < 0.0 || vp < 0.0 ||
                                       up > 1.0 || vp > 1.0;
                    int hx = 0, hy = 0;
                    double zp = -1.0;
                    if (!disoccluded) {
                        if (nearInteger(up * w) || nearInteger(vp * h) || std::abs(up) < 1e-6 ||
                            std::abs(vp) < 1e-6 || std::abs(up - 1.0) < 1e-6 || std::abs(vp - 1.0) < 1e-6)
                            ambiguous = true;
                        hx = std::min(int(std::floor(up * w)), w - 1);
                        hy = std::min(int(std::floor(vp * h)), h - 1);
                        // z_r: this point's view depth last frame; z_p: last frame's depth there.
                        const std::array<double, 4> ndc{2.0 * u - 1.0, double(in.ndcYSign) * (2.0 * v - 1.0),
                                                        double(in.depth[p]), 1.0};
                        const std::array<double, 4> clip = transform(in.reprojection, ndc);
                        const double zr = viewDepth(float(clip[2] / clip[3]), in.viewDepth);
                        zp = zPrevious(hx, hy);
                        const std::array<double, 4> world = transform(in.inverseViewProjection, ndc);
                        double e[3], nrm[3];
                        for (std::size_t k = 0; k < 3; ++k) {
                            e[k] = double(in.eye[k]) - world[k] / world[3];
                            nrm[k] = double(in.normals[4 * p + k]);
                        }
                        double cosine =
                            std::abs((e[0] * nrm[0] + e[1] * nrm[1] + e[2] * nrm[2]) /
                                     (std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]) *
                                      std::sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2])));
                        cosine = finite(cosine) ? std::min(cosine, 1.0) : 0.0;
                        const double threshold = 0.01 + (0.1 - 0.01) * std::pow(1.0 - cosine, 8.0);
                        if (zr > 0.0 && zp > 0.0) {
                            const double relative = std::abs(zp - zr) / zr;
                            if (std::abs(relative - threshold) <= kRelativeMargin * threshold + 1e-6)
                                ambiguous = true;
                            disoccluded = !(relative < threshold);
                        } else {
                            disoccluded = true;
                        }
                    }
                    if (!disoccluded) {
                        // (m, M2, n) at the previous pixel; the accumulated shadow bilinear at uv_prev
                        // (texel centres, addresses clamped).
                        const float* loaded = &in.momentsHistory[4 * img.at(hx, hy)];
                        const double fx = up * w - 0.5, fy = vp * h - 0.5;
                        const int bx = int(std::floor(fx)), by = int(std::floor(fy));
                        const double tx = fx - bx, ty = fy - by;
                        auto accumulated = [&](int ax, int ay) {
                            return double(in.momentsHistory[4 * img.at(std::clamp(ax, 0, w - 1),
                                                                       std::clamp(ay, 0, h - 1)) +
                                                            3]);
                        };
                        const double bilinear =
                            (1 - ty) * ((1 - tx) * accumulated(bx, by) + tx * accumulated(bx + 1, by)) +
                            ty * ((1 - tx) * accumulated(bx, by + 1) + tx * accumulated(bx + 1, by + 1));
                        if (finite(loaded[0]) && finite(loaded[1]) && finite(loaded[2]) && finite(bilinear)) {
                            px.found = true;
                            px.m = double(loaded[0]);
                            px.m2 = double(loaded[1]);
                            px.count = std::clamp(double(loaded[2]), 0.0, kMaxCount);
                            px.history = std::clamp(bilinear, 0.0, 1.0);
                        }
                    }
                    if (px.found && in.antiLag) {
                        // The two scores over the 5x5 window, in binomial sigmas, each with one
                        // sample of slack.
                        double bits = 0.0, predicted = 0.0, signedVariance = 0.0, mismatch = 0.0,
                               mismatchVariance = 0.0;
                        for (int dy = -kAntiLagRadius; dy <= kAntiLagRadius; ++dy)
                            for (int dx = -kAntiLagRadius; dx <= kAntiLagRadius; ++dx) {
                                const int cx = x + dx, cy = y + dy, ax = hx + dx, ay = hy + dy;
                                if (!img.inside(cx, cy) || !img.inside(ax, ay)) continue;
                                const double zNow = z(cx, cy), zThen = zPrevious(ax, ay);
                                if (!(zNow > 0.0) || !(zThen > 0.0)) continue;
                                const double dNow = std::abs(zNow - zc) - kAntiLagDepth * zc;
                                const double dThen = std::abs(zThen - zp) - kAntiLagDepth * zp;
                                if (std::abs(dNow) <= kRelativeMargin * zc ||
                                    std::abs(dThen) <= kRelativeMargin * zp)
                                    ambiguous = true;
                                if (dNow > 0.0 || dThen > 0.0) continue;
                                const float* history = &in.momentsHistory[4 * img.at(ax, ay)];
                                if (!finite(history[2]) || !finite(history[3]) || !(history[2] > 0.0f))
                                    continue;
                                const double n = std::min(double(history[2]), kMaxCount);
                                const double hv = std::clamp(double(history[3]), 0.0, 1.0);
                                const double b = lit(cx, cy);
                                const double pj = (hv * n + 0.25) / (n + 0.5);
                                bits += b;
                                predicted += hv;
                                signedVariance += pj * (1.0 - pj) * (1.0 + 1.0 / (n + 1.0));
                                const double qj = (hv * n + 1.0) / (n + 2.0);
                                mismatch += std::abs(b - hv) - (qj * (1.0 - hv) + (1.0 - qj) * hv);
                                mismatchVariance += qj * (1.0 - qj) * (1.0 - 2.0 * hv) * (1.0 - 2.0 * hv);
                            }
                        px.antiLagScore =
                            std::max(std::abs(bits - predicted) / std::sqrt(signedVariance + kAntiLagSlack),
                                     mismatch / std::sqrt(mismatchVariance + kAntiLagSlack));
                    }

                    // The outputs over the ranges of the mean, the history and the anti-lag score
                    // (the functions are piecewise monotone there, so their extremes lie at these
                    // points or on flat pieces).
                    double low[6], high[6];
                    bool first = true;
                    for (int s = 0; s < 5; ++s)
                        for (int hs = -1; hs <= 1; ++hs)
                            for (int zs = -1; zs <= 1; zs += 2) {
                                const Result r = evaluate(px, mean + kShadowClassifyMeanSlack * (s - 2) / 2.0,
                                                          kHistorySlack * hs, kScoreSlack * zs,
                                                          double(in.storedVarianceScale));
                                if (std::abs(r.lengthBeforeClamp - 16.0) <= kLengthStepMargin)
                                    ambiguous = true;
                                const double values[6] = {r.shadowVariance[0], r.shadowVariance[1],
                                                          r.moments[0],        r.moments[1],
                                                          r.moments[2],        r.moments[3]};
                                for (int c = 0; c < 6; ++c) {
                                    low[c] = first ? values[c] : std::min(low[c], values[c]);
                                    high[c] = first ? values[c] : std::max(high[c], values[c]);
                                }
                                first = false;
                            }
                    for (int c = 0; c < 2; ++c) {
                        out.shadowVarianceLow[2 * p + std::size_t(c)] = low[c];
                        out.shadowVarianceHigh[2 * p + std::size_t(c)] = high[c];
                    }
                    for (int c = 0; c < 4; ++c) {
                        out.momentsLow[4 * p + std::size_t(c)] = low[c + 2];
                        out.momentsHigh[4 * p + std::size_t(c)] = high[c + 2];
                    }
                    out.ambiguous[p] = ambiguous ? 1u : 0u;
                }
        }
    return out;
}

} // namespace glint::reference
