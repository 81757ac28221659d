#include "reference/sssr_reference.h"

#include "glint/common/glint_wire_formats.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace glint::reference {

bool sssrIsBackground(float depth, bool reversedDepth) {
    if (!std::isfinite(depth)) return true;
    if (reversedDepth) return depth <= 1e-6f || depth > 1.0f;
    return depth >= 1.0f - 1e-6f || depth < 0.0f;
}

bool sssrNormalValid(float x, float y, float z) {
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) return false;
    // In double: the squares of finite floats can overflow float but not double.
    const double dx = static_cast<double>(x), dy = static_cast<double>(y), dz = static_cast<double>(z);
    const double lengthSquared = dx * dx + dy * dy + dz * dz;
    return std::sqrt(lengthSquared) > 1e-6;
}

// Both entries are the wire formats the shaders write (glint/common/glint_wire_formats.h).
std::uint32_t packSssrRay(std::uint32_t x, std::uint32_t y, bool copyH, bool copyV, bool copyD) {
    assert(x < (1u << 15) && y < (1u << 14));
    return shared::GLINT_WIRE_PackRayEntry(
        x, y, (copyH ? kSssrCopyH : 0u) | (copyV ? kSssrCopyV : 0u) | (copyD ? kSssrCopyD : 0u));
}

std::uint32_t packSssrTile(std::uint32_t tileX, std::uint32_t tileY) {
    return shared::GLINT_WIRE_PackTileEntry(tileX * 8u, tileY * 8u);
}

SssrClassification sssrClassify(const SssrClassifyInputs& in) {
    const std::uint32_t w = in.width, h = in.height;
    const std::size_t count = std::size_t{w} * h;
    assert(w < (1u << 15) && h < (1u << 14));
    assert(in.depth.size() == count && in.alpha.size() == count);
    assert(in.normals.empty() || in.normals.size() == 3 * count);
    assert(!in.varianceGuided || in.variance.size() == count);
    assert(in.samplesPerQuad == 1 || in.samplesPerQuad == 2 || in.samplesPerQuad == 4);

    SssrClassification out;
    out.classes.assign(count, 0);
    std::vector<bool> tracesOnItsOwn(count, false); // traces0: before any promotion
    std::vector<bool> needsDenoiser(count, false);
    auto index = [w](std::uint32_t x, std::uint32_t y) { return std::size_t{y} * w + x; };

    for (std::uint32_t y = 0; y < h; ++y)
        for (std::uint32_t x = 0; x < w; ++x) {
            const std::size_t i = index(x, y);
            const bool normalValid =
                in.normals.empty() ||
                sssrNormalValid(in.normals[3 * i], in.normals[3 * i + 1], in.normals[3 * i + 2]);
            const bool reflective = !sssrIsBackground(in.depth[i], in.reversedDepth) && normalValid;
            const float alpha = std::isfinite(in.alpha[i]) ? in.alpha[i] : 1.0f;
            const bool glossy = reflective && alpha < in.roughnessThreshold;
            const bool mirror = glossy && alpha < in.mirrorThreshold;
            needsDenoiser[i] = glossy && !mirror;
            const bool base = in.samplesPerQuad == 4   ? true
                              : in.samplesPerQuad == 2 ? (x & 1u) == (y & 1u)
                                                       : (x & 1u) == 0 && (y & 1u) == 0;
            bool traces = glossy && (mirror || base);
            // Temporal-variance-guided tracing; written as !(v <= t) so that NaN counts as high.
            if (in.varianceGuided && needsDenoiser[i] && !traces && !(in.variance[i] <= in.varianceThreshold))
                traces = true;
            tracesOnItsOwn[i] = traces;
            std::uint8_t bits = 0;
            if (reflective) bits |= kSssrReflective;
            if (glossy) bits |= kSssrGlossy;
            if (mirror) bits |= kSssrMirror;
            if (traces) bits |= kSssrTraces;
            out.classes[i] = bits;
        }

    // Donors. Only pixels that trace on their own can donate, so the result does not depend
    // on the order in which pixels are visited.
    struct Neighbour {
        std::uint32_t dx, dy, flag;
    };
    constexpr Neighbour kDonorOrder[3] = {{1, 0, kSssrCopyH}, {0, 1, kSssrCopyV}, {1, 1, kSssrCopyD}};
    std::vector<std::uint32_t> copyFlags(count, 0u);
    for (std::uint32_t y = 0; y < h; ++y)
        for (std::uint32_t x = 0; x < w; ++x) {
            const std::size_t i = index(x, y);
            if (!needsDenoiser[i] || tracesOnItsOwn[i]) continue;
            bool found = false;
            for (const Neighbour& n : kDonorOrder) {
                const std::uint32_t dxX = x ^ n.dx, dyY = y ^ n.dy;
                if (dxX >= w || dyY >= h || !tracesOnItsOwn[index(dxX, dyY)]) continue;
                // The flag sits on the donor: its (x^dx, y^dy) neighbour copies from it.
                copyFlags[index(dxX, dyY)] |= n.flag;
                found = true;
                break;
            }
            out.classes[i] |= found ? kSssrRequiresCopy : std::uint8_t(kSssrTraces | kSssrPromoted);
        }

    const std::uint32_t tilesX = (w + 7) / 8, tilesY = (h + 7) / 8;
    std::vector<bool> tileGlossy(std::size_t{tilesX} * tilesY, false);
    for (std::uint32_t y = 0; y < h; ++y)
        for (std::uint32_t x = 0; x < w; ++x) {
            const std::size_t i = index(x, y);
            const std::uint8_t bits = out.classes[i];
            if (bits & kSssrGlossy) {
                ++out.glossyCount;
                tileGlossy[std::size_t{y / 8} * tilesX + x / 8] = true;
            }
            if (bits & kSssrMirror) ++out.mirrorCount;
            if (bits & kSssrRequiresCopy) ++out.copyCount;
            if (bits & kSssrPromoted) ++out.promotedCount;
            if (bits & kSssrTraces) out.rays.push_back(packSssrRay(x, y, false, false, false) | copyFlags[i]);
            // Only a tracing pixel can be a donor.
            assert(copyFlags[i] == 0 || (bits & kSssrTraces));
        }
    for (std::uint32_t ty = 0; ty < tilesY; ++ty)
        for (std::uint32_t tx = 0; tx < tilesX; ++tx)
            if (tileGlossy[std::size_t{ty} * tilesX + tx]) out.tiles.push_back(packSssrTile(tx, ty));

    std::sort(out.rays.begin(), out.rays.end());
    std::sort(out.tiles.begin(), out.tiles.end());
    out.rayCount = static_cast<std::uint32_t>(out.rays.size());
    out.tileCount = static_cast<std::uint32_t>(out.tiles.size());
    return out;
}

double sssrSurfaceDepth(const SssrDepthField& field, std::uint32_t i, std::uint32_t j) {
    assert(i < field.width && j < field.height);
    const float d = field.depth[std::size_t{j} * field.width + i];
    if (sssrIsBackground(d, field.reversedDepth)) return field.reversedDepth ? 0.0 : 1.0;
    return static_cast<double>(d);
}

SssrMarchResult sssrMarch(const SssrDepthField& field, const SssrTraceRay& ray,
                          const SssrThickness& thickness) {
    assert(field.depth.size() == std::size_t{field.width} * field.height);
    SssrMarchResult result;
    const auto& o = ray.origin;
    const auto& d = ray.direction;

    // Non-finite rays cannot be walked; they count as degenerate (no screen progress defined).
    bool finiteRay = !std::isnan(ray.tEnd);
    for (std::size_t axis = 0; axis < 3; ++axis)
        finiteRay = finiteRay && std::isfinite(o[axis]) && std::isfinite(d[axis]);
    if (!finiteRay || std::hypot(d[0], d[1]) < kSssrMinScreenSpeed) {
        result.miss = SssrMiss::Degenerate;
        return result;
    }

    const bool reversed = field.reversedDepth;
    auto behind = [reversed](double z, double surface) { return reversed ? z <= surface : z >= surface; };
    auto viewDepth = [&thickness](double z) {
        return thickness.viewDepth[0] / (thickness.viewDepth[1] + thickness.viewDepth[2] * z);
    };
    // t at which the ray leaves cell `cell` of one axis, `kSssrBoundaryOvershoot` past the
    // boundary so that the position lands inside the next cell.
    auto exitT = [&](double cell, std::size_t axis) {
        if (d[axis] == 0.0) return std::numeric_limits<double>::infinity();
        const double boundary =
            d[axis] > 0.0 ? cell + 1.0 + kSssrBoundaryOvershoot : cell - kSssrBoundaryOvershoot;
        return (boundary - o[axis]) / d[axis];
    };

    // Initial advance: leave the origin's own texel without a depth test.
    double tIn = std::min(exitT(std::floor(o[0]), 0), exitT(std::floor(o[1]), 1));
    const std::uint64_t walkCap = std::uint64_t{field.width} + field.height + 4;
    for (;;) {
        if (tIn > ray.tEnd) {
            result.miss = SssrMiss::Escaped;
            result.t = ray.tEnd;
            return result;
        }
        // The texel is where the position lies; the overshoot keeps it off the boundary. Near
        // a corner both coordinates can change at once, as in the shader's floor(pos / cell).
        const double cellX = std::floor(o[0] + tIn * d[0]);
        const double cellY = std::floor(o[1] + tIn * d[1]);
        if (cellX < 0.0 || cellY < 0.0 || cellX >= static_cast<double>(field.width) ||
            cellY >= static_cast<double>(field.height)) {
            result.miss = SssrMiss::Escaped;
            result.t = tIn;
            return result;
        }
        if (result.texelsWalked >= walkCap) {
            result.miss = SssrMiss::WalkCap;
            result.t = tIn;
            return result;
        }
        ++result.texelsWalked;

        const double rawExit = std::min(exitT(cellX, 0), exitT(cellY, 1));
        const double tOut = std::min(rawExit, ray.tEnd);
        const auto i = static_cast<std::uint32_t>(cellX);
        const auto j = static_cast<std::uint32_t>(cellY);
        const double surface = sssrSurfaceDepth(field, i, j);
        const double zIn = o[2] + tIn * d[2];
        const double zOut = o[2] + tOut * d[2];
        const bool behindIn = behind(zIn, surface);
        const bool behindOut = behind(zOut, surface);
        if (behindIn || behindOut) {
            // behindOut without behindIn implies d.z != 0: the ray crosses the surface plane.
            const double tHit = behindIn ? tIn : std::clamp((surface - o[2]) / d[2], tIn, tOut);
            bool accepted = true;
            if (thickness.enabled) {
                // The behind part of [tIn, tOut] ends at the crossing where one end is not
                // behind; there its depth is the surface's own (used exactly, no rounding).
                // View depth is monotonic along the segment, so the closest point is an end.
                const double zA = behindIn ? zIn : surface;
                const double zB = behindOut ? zOut : surface;
                const double closest = std::min(viewDepth(zA), viewDepth(zB));
                accepted = closest <= viewDepth(surface) + thickness.thickness;
            }
            if (accepted) {
                result.hit = true;
                result.x = static_cast<std::int32_t>(i);
                result.y = static_cast<std::int32_t>(j);
                result.t = tHit;
                return result;
            }
        }
        tIn = rawExit;
    }
}

} // namespace glint::reference
