#include "reference/depth_pyramid_reference.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace glint::reference {

namespace {

constexpr std::uint32_t kTileLevels = 7; // levels 0..6 are plain 2x2 reductions of a 64x64 tile

std::uint32_t bitsOf(float value) {
    return std::bit_cast<std::uint32_t>(value);
}

std::string describe(float value) {
    char text[64];
    std::snprintf(text, sizeof text, "%.9g (0x%08x)", static_cast<double>(value), bitsOf(value));
    return text;
}

} // namespace

float farDepth(DepthConvention convention) {
    return convention == DepthConvention::Standard ? 1.0f : 0.0f;
}

float sanitizeDepth(float depth, DepthConvention convention) {
    if (!std::isfinite(depth)) return farDepth(convention);
    // Below the smallest normal float (denormals, -0, negatives) is +0: devices that flush
    // denormals and devices that keep them then agree bit for bit.
    if (depth < std::numeric_limits<float>::min()) return 0.0f;
    if (depth > 1.0f) return 1.0f;
    return depth;
}

std::uint32_t paddedExtent(std::uint32_t extent) {
    return (extent + 63u) / 64u * 64u;
}

std::uint32_t fullLevelCount(std::uint32_t level0Width, std::uint32_t level0Height) {
    std::uint32_t largest = std::max(level0Width, level0Height);
    std::uint32_t levels = 1;
    while (largest > 1) {
        largest >>= 1;
        ++levels;
    }
    return levels;
}

Pyramid buildDepthPyramid(const std::vector<float>& depth, std::uint32_t width, std::uint32_t height,
                          DepthConvention convention, DepthPyramidChannels channels,
                          std::uint32_t requestedLevels) {
    const std::uint32_t w0 = paddedExtent(width);
    const std::uint32_t h0 = paddedExtent(height);
    const std::uint32_t levelCount = requestedLevels == 0 ? fullLevelCount(w0, h0) : requestedLevels;
    const std::uint32_t c = channels == DepthPyramidChannels::Closest ? 1u : 2u;
    const float far = farDepth(convention);
    const bool reversed = convention == DepthConvention::Reversed;
    auto closer = [reversed](float a, float b) { return reversed ? std::max(a, b) : std::min(a, b); };
    auto farther = [reversed](float a, float b) { return reversed ? std::min(a, b) : std::max(a, b); };

    Pyramid pyramid;
    pyramid.channels = c;
    pyramid.levels.resize(levelCount);

    PyramidLevel& base = pyramid.levels[0];
    base.width = w0;
    base.height = h0;
    base.texels.assign(static_cast<std::size_t>(w0) * h0 * c, far);
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            const float d = sanitizeDepth(depth[static_cast<std::size_t>(y) * width + x], convention);
            for (std::uint32_t ch = 0; ch < c; ++ch)
                base.texels[(static_cast<std::size_t>(y) * w0 + x) * c + ch] = d;
        }

    for (std::uint32_t k = 1; k < levelCount; ++k) {
        const PyramidLevel& prev = pyramid.levels[k - 1];
        PyramidLevel& out = pyramid.levels[k];
        out.width = std::max(1u, w0 >> k);
        out.height = std::max(1u, h0 >> k);
        out.texels.resize(static_cast<std::size_t>(out.width) * out.height * c);
        // Below level 7 every previous level has even sizes, so each texel is a plain 2x2
        // block; from level 7 on the last column/row also takes the previous level's leftover.
        for (std::uint32_t j = 0; j < out.height; ++j) {
            const std::uint32_t y0 = 2 * j;
            const std::uint32_t y1 =
                j == out.height - 1 ? prev.height - 1 : std::min(2 * j + 1, prev.height - 1);
            for (std::uint32_t i = 0; i < out.width; ++i) {
                const std::uint32_t x0 = 2 * i;
                const std::uint32_t x1 =
                    i == out.width - 1 ? prev.width - 1 : std::min(2 * i + 1, prev.width - 1);
                float nearest = far;
                float farthest = reversed ? 1.0f : 0.0f; // the near plane: anything is at least as far
                for (std::uint32_t y = y0; y <= y1; ++y)
                    for (std::uint32_t x = x0; x <= x1; ++x) {
                        const std::size_t at = (static_cast<std::size_t>(y) * prev.width + x) * c;
                        nearest = closer(nearest, prev.texels[at]);
                        if (c == 2) farthest = farther(farthest, prev.texels[at + 1]);
                    }
                const std::size_t at = (static_cast<std::size_t>(j) * out.width + i) * c;
                out.texels[at] = nearest;
                if (c == 2) out.texels[at + 1] = farthest;
            }
        }
    }
    return pyramid;
}

std::string checkDepthPyramid(const std::vector<float>& depth, std::uint32_t width, std::uint32_t height,
                              DepthConvention convention, std::uint32_t expectedLevels,
                              const Pyramid& pyramid, std::size_t maxFailures) {
    std::ostringstream report;
    std::size_t failures = 0;
    auto fail = [&]() -> std::ostream& {
        ++failures;
        return report;
    };

    // The contract's sizes, computed here on their own.
    const std::uint32_t w0 = width % 64 == 0 ? width : width - width % 64 + 64;
    const std::uint32_t h0 = height % 64 == 0 ? height : height - height % 64 + 64;
    if (pyramid.levels.size() != expectedLevels) {
        fail() << "pyramid has " << pyramid.levels.size() << " levels, expected " << expectedLevels << "\n";
        return report.str();
    }
    if (pyramid.channels != 1 && pyramid.channels != 2) return "pyramid has an unsupported channel count\n";
    for (std::uint32_t k = 0; k < expectedLevels; ++k) {
        const std::uint32_t lw = k < 32 && (w0 >> k) > 0 ? w0 >> k : 1;
        const std::uint32_t lh = k < 32 && (h0 >> k) > 0 ? h0 >> k : 1;
        const PyramidLevel& level = pyramid.levels[k];
        if (level.width != lw || level.height != lh ||
            level.texels.size() != static_cast<std::size_t>(lw) * lh * pyramid.channels) {
            fail() << "level " << k << " is " << level.width << "x" << level.height << " with "
                   << level.texels.size() << " floats, expected " << lw << "x" << lh << "\n";
            return report.str();
        }
    }

    // The sanitization rule, stated independently of sanitizeDepth: anything that is not a
    // finite number is far; the rest is clamped to [0, 1], and every value without a normal
    // exponent (both zeros, denormals) is stored as +0.
    const bool reversed = convention == DepthConvention::Reversed;
    const float far = reversed ? 0.0f : 1.0f;
    std::vector<float> pixels(static_cast<std::size_t>(width) * height);
    for (std::size_t p = 0; p < pixels.size(); ++p) {
        const std::uint32_t bits = bitsOf(depth[p]);
        const bool nonFinite = (bits & 0x7F800000u) == 0x7F800000u;
        float v = nonFinite ? far : depth[p];
        v = v < 0.0f ? 0.0f : (v > 1.0f ? 1.0f : v);
        if ((bitsOf(v) & 0x7F800000u) == 0) v = 0.0f;
        pixels[p] = v;
    }
    // true when a is at least as close as b
    auto atLeastAsClose = [reversed](float a, float b) { return reversed ? a >= b : a <= b; };

    // Footprint column/row ranges [start, end) in level-0 pixels, level by level.
    std::vector<std::uint32_t> colStart, colEnd, rowStart, rowEnd;
    for (std::uint32_t k = 0; k < expectedLevels && failures < maxFailures; ++k) {
        const PyramidLevel& level = pyramid.levels[k];
        auto nextRanges = [k](std::uint32_t count, std::vector<std::uint32_t>& start,
                              std::vector<std::uint32_t>& end) {
            std::vector<std::uint32_t> s(count), e(count);
            for (std::uint32_t i = 0; i < count; ++i) {
                if (k < kTileLevels) {
                    s[i] = i << k;
                    e[i] = (i + 1) << k;
                } else {
                    const std::uint32_t prevCount = static_cast<std::uint32_t>(start.size());
                    const std::uint32_t last = i == count - 1 ? prevCount - 1 : 2 * i + 1;
                    s[i] = start[2 * i];
                    e[i] = end[last];
                }
            }
            start = std::move(s);
            end = std::move(e);
        };
        nextRanges(level.width, colStart, colEnd);
        nextRanges(level.height, rowStart, rowEnd);

        for (std::uint32_t j = 0; j < level.height && failures < maxFailures; ++j) {
            for (std::uint32_t i = 0; i < level.width && failures < maxFailures; ++i) {
                const std::uint32_t x0 = colStart[i], x1 = colEnd[i], y0 = rowStart[j], y1 = rowEnd[j];
                const bool padding = x1 > width || y1 > height;
                const std::uint32_t xe = std::min(x1, width), ye = std::min(y1, height);
                // The footprint's extremes by brute force over its level-0 pixels.
                bool any = false;
                float smallest = 0.0f, largest = 0.0f;
                for (std::uint32_t y = y0; y < ye; ++y) {
                    const float* row = &pixels[static_cast<std::size_t>(y) * width];
                    for (std::uint32_t x = x0; x < xe; ++x) {
                        const float p = row[x];
                        if (!any) {
                            smallest = largest = p;
                            any = true;
                        }
                        smallest = p < smallest ? p : smallest;
                        largest = p > largest ? p : largest;
                    }
                }
                const float closestPixel = reversed ? largest : smallest;
                const float farthestPixel = reversed ? smallest : largest;
                for (std::uint32_t ch = 0; ch < pyramid.channels; ++ch) {
                    const float value = ch == 0 ? pyramid.closest(k, i, j) : pyramid.farthest(k, i, j);
                    const char* name = ch == 0 ? "closest" : "farthest";
                    auto where = [&]() -> std::ostream& {
                        return fail() << "level " << k << " texel (" << i << ", " << j << ") " << name << " "
                                      << describe(value) << ", footprint [" << x0 << ", " << x1 << ") x ["
                                      << y0 << ", " << y1 << ")" << (padding ? " with padding" : "") << ": ";
                    };
                    if (!std::isfinite(value) || value < 0.0f || value > 1.0f ||
                        bitsOf(value) == 0x80000000u) {
                        where() << "not a finite depth in [0, 1] (or -0)\n";
                        continue;
                    }
                    // Bound: at least as close (closest) / as far (farthest) as every pixel,
                    // i.e. as the footprint's extreme pixel in that direction.
                    const float extreme = ch == 0 ? closestPixel : farthestPixel;
                    const bool bounds =
                        !any || (ch == 0 ? atLeastAsClose(value, extreme) : atLeastAsClose(extreme, value));
                    if (!bounds) {
                        where() << "a pixel holds " << describe(extreme) << ", which is "
                                << (ch == 0 ? "closer" : "farther") << "\n";
                        continue;
                    }
                    // Value: one of the footprint's pixels, or far when the footprint reaches
                    // into the padding. With the bound above, a pixel value can only be the
                    // extreme one (sanitized pixels have no -0, so bits identify values).
                    const bool isPixel = any && bitsOf(value) == bitsOf(extreme);
                    const bool isPaddingFar = padding && bitsOf(value) == bitsOf(far);
                    if (!isPixel && !isPaddingFar)
                        where() << "equals no sanitized pixel of the footprint (nor far in padding)\n";
                }
            }
        }
    }
    if (failures >= maxFailures) report << "(stopped after " << maxFailures << " failures)\n";
    return report.str();
}

std::string compareBits(const Pyramid& expected, const Pyramid& actual, std::size_t maxFailures) {
    std::ostringstream report;
    if (expected.channels != actual.channels || expected.levels.size() != actual.levels.size()) {
        report << "shape differs: " << actual.levels.size() << " levels x " << actual.channels
               << " channels, expected " << expected.levels.size() << " x " << expected.channels << "\n";
        return report.str();
    }
    std::size_t failures = 0;
    std::size_t total = 0;
    for (std::size_t k = 0; k < expected.levels.size(); ++k) {
        const PyramidLevel& e = expected.levels[k];
        const PyramidLevel& a = actual.levels[k];
        if (e.width != a.width || e.height != a.height || e.texels.size() != a.texels.size()) {
            report << "level " << k << " is " << a.width << "x" << a.height << ", expected " << e.width << "x"
                   << e.height << "\n";
            return report.str();
        }
        std::size_t levelMismatches = 0;
        for (std::size_t t = 0; t < e.texels.size(); ++t) {
            if (bitsOf(e.texels[t]) == bitsOf(a.texels[t])) continue;
            ++levelMismatches;
            if (failures++ < maxFailures) {
                const std::size_t texel = t / expected.channels;
                report << "level " << k << " texel (" << texel % e.width << ", " << texel / e.width << ") "
                       << (t % expected.channels == 0 ? "closest" : "farthest") << ": got "
                       << describe(a.texels[t]) << ", expected " << describe(e.texels[t]) << "\n";
            }
        }
        if (levelMismatches) report << "level " << k << ": " << levelMismatches << " mismatching values\n";
        total += levelMismatches;
    }
    if (total) report << total << " mismatching values in all\n";
    return report.str();
}

} // namespace glint::reference
