#include "reference/shadow_denoiser_reference.h"

#include "glint/common/glint_wire_formats.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace glint::reference {

std::vector<std::uint32_t> packShadowMask(const std::vector<float>& visibility, std::uint32_t width,
                                          std::uint32_t height) {
    const std::uint32_t tilesX = (width + 7) / 8;
    const std::uint32_t tilesY = (height + 3) / 4;
    std::vector<std::uint32_t> mask(std::size_t{tilesX} * tilesY, 0u);
    for (std::uint32_t ty = 0; ty < tilesY; ++ty)
        for (std::uint32_t tx = 0; tx < tilesX; ++tx) {
            std::uint32_t word = 0;
            for (std::uint32_t row = 0; row < 4; ++row)
                for (std::uint32_t column = 0; column < 8; ++column) {
                    const std::uint32_t x = std::min(tx * 8 + column, width - 1);
                    const std::uint32_t y = std::min(ty * 4 + row, height - 1);
                    if (visibility[std::size_t{y} * width + x] >= 0.5f)
                        word |= 1u << shared::GLINT_WIRE_ShadowMaskBit(column, row);
                }
            mask[std::size_t{ty} * tilesX + tx] = word;
        }
    return mask;
}

namespace {

struct Geometry {
    float z = -1.0f; // view depth, -1 for non-receivers
    std::array<float, 3> n{};
};

float viewDepthOf(float d, const float coefficients[3]) {
    if (!std::isfinite(d) || !(d > 1e-6f && d < 1.0f - 1e-6f)) return -1.0f;
    const float z = coefficients[0] / (coefficients[1] + coefficients[2] * d);
    return std::isfinite(z) && z > 0.0f ? z : -1.0f;
}

std::array<float, 3> unitOrZero(float x, float y, float z) {
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) return {};
    const float lengthSquared = x * x + y * y + z * z;
    if (!(lengthSquared > 1e-12f) || !std::isfinite(lengthSquared)) return {};
    const float inverse = 1.0f / std::sqrt(lengthSquared);
    return {x * inverse, y * inverse, z * inverse};
}

float kernel(int offset) {
    return offset == 0 ? 1.0f : 2.0f / 3.0f;
}

} // namespace

std::vector<float> shadowFilterPass(const ShadowFilterInputs& inputs, const std::vector<float>& meanVariance,
                                    std::uint32_t step, bool finalPass) {
    const int w = static_cast<int>(inputs.width);
    const int h = static_cast<int>(inputs.height);
    const std::size_t count = std::size_t(w) * std::size_t(h);
    std::vector<Geometry> geometry(count);
    std::vector<std::array<float, 2>> values(count);
    for (std::size_t i = 0; i < count; ++i) {
        const float mean = meanVariance[2 * i];
        const float variance = meanVariance[2 * i + 1];
        values[i] = {std::isfinite(mean) ? std::clamp(mean, 0.0f, 1.0f) : 0.0f,
                     std::isfinite(variance) ? std::max(variance, 0.0f) : 0.0f};
        geometry[i].z = viewDepthOf(inputs.depth[i], inputs.viewDepth);
        if (geometry[i].z > 0.0f)
            geometry[i].n =
                unitOrZero(inputs.normals[4 * i], inputs.normals[4 * i + 1], inputs.normals[4 * i + 2]);
    }
    auto at = [&](int x, int y) {
        return std::size_t(std::clamp(y, 0, h - 1)) * std::size_t(w) + std::size_t(std::clamp(x, 0, w - 1));
    };

    // Penumbra width in pixels each receiver's blocker implies (0 for lit or non-receivers, and
    // for every pixel under a light of size 0).
    std::vector<double> width(count, 0.0);
    if (inputs.penumbraScale > 0.0f)
        for (std::size_t i = 0; i < count; ++i) {
            if (geometry[i].z <= 0.0f) continue;
            const double b = inputs.blockerDistance.at(i);
            const double wide = 64.0; // unknown: wider than the full footprint needs
            width[i] = !std::isfinite(b) || b < 0.0
                           ? wide
                           : std::min(wide, double{inputs.penumbraScale} * b / double{geometry[i].z});
        }

    std::vector<float> out(2 * count, 0.0f);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t c = at(x, y);
            double footprint = 1.0;
            if (inputs.penumbraScale >= 0.0f) {
                double widest = 0.0;
                for (int j = -2; j <= 2; ++j)
                    for (int i = -2; i <= 2; ++i) widest = std::max(widest, width[at(x + i, y + j)]);
                footprint = std::clamp((widest - 1.0) / double(step), 0.0, 1.0);
            }
            if (geometry[c].z <= 0.0f) { // non-receivers: (1, 0), lit
                out[2 * c] = 1.0f;
                continue;
            }
            float filteredVariance = 0.0f;
            for (int j = -1; j <= 1; ++j)
                for (int i = -1; i <= 1; ++i)
                    filteredVariance +=
                        (i == 0 ? 0.5f : 0.25f) * (j == 0 ? 0.5f : 0.25f) * values[at(x + i, y + j)][1];
            if (!(footprint > 0.0)) { // no taps: the input as it is (then the remap, if asked)
                const float variance = values[c][1];
                const float mean =
                    finalPass ? std::pow(values[c][0], std::max(1.2f - variance, 1.0f)) : values[c][0];
                out[2 * c] = std::isfinite(mean) ? mean : 0.0f;
                out[2 * c + 1] = variance;
                continue;
            }
            const float sigma = std::sqrt(filteredVariance + 1e-9f);
            const float depthScale = std::max(inputs.depthSigma * geometry[c].z, 1e-20f);
            float weightSum = 1.0f;
            float meanSum = values[c][0];
            float varianceSum = values[c][1];
            for (int j = -1; j <= 1; ++j)
                for (int i = -1; i <= 1; ++i) {
                    if (i == 0 && j == 0) continue;
                    const int s = static_cast<int>(step);
                    const std::size_t q = at(x + s * i, y + s * j);
                    if (geometry[q].z <= 0.0f) continue;
                    const auto& a = geometry[c].n;
                    const auto& b = geometry[q].n;
                    const float cosine = std::max(a[0] * b[0] + a[1] * b[1] + a[2] * b[2], 0.0f);
                    const float weight = static_cast<float>(footprint) * kernel(i) * kernel(j) *
                                         std::exp(-std::abs(values[c][0] - values[q][0]) / sigma) *
                                         std::exp(-std::abs(geometry[c].z - geometry[q].z) / depthScale) *
                                         std::pow(cosine, inputs.normalPower);
                    weightSum += weight;
                    meanSum += weight * values[q][0];
                    varianceSum += weight * weight * values[q][1];
                }
            float mean = std::clamp(meanSum / weightSum, 0.0f, 1.0f);
            const float variance = std::max(varianceSum / (weightSum * weightSum), 0.0f);
            if (finalPass) mean = std::pow(mean, std::max(1.2f - variance, 1.0f));
            out[2 * c] = std::isfinite(mean) ? mean : 0.0f;
            out[2 * c + 1] = std::isfinite(variance) ? variance : 0.0f;
        }
    return out;
}

std::vector<float> shadowFilter(const ShadowFilterInputs& inputs) {
    std::vector<float> current = inputs.meanVariance;
    for (std::uint32_t pass = 0; pass < 3; ++pass)
        current = shadowFilterPass(inputs, current, 1u << pass, pass == 2 && inputs.contrastRemap);
    return current;
}

} // namespace glint::reference
