#include "sssr/sssr_classify_view.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace glint::test {
namespace {

struct Rng {
    std::uint32_t state;
    float next() {
        state = state * 1664525u + 1013904223u;
        return static_cast<float>(state >> 8) / 16777216.0f;
    }
};

} // namespace

SssrTestView randomClassifyView(std::uint32_t width, std::uint32_t height, bool reversed,
                                std::uint32_t seed) {
    SssrTestView view = makeSssrTestView(width, height, reversed);
    view.desc.materialChannel = 1;
    view.desc.roughnessIsPerceptual = true;
    Rng rng{seed};
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (std::size_t i = 0; i < std::size_t{width} * height; ++i) {
        const float kind = rng.next();
        setViewDepth(view, static_cast<std::uint32_t>(i % width), static_cast<std::uint32_t>(i / width),
                     2.0 + 10.0 * static_cast<double>(rng.next()));
        if (kind < 0.05f) view.inputs.depth[i] = reversed ? 0.0f : 1.0f;
        if (kind >= 0.05f && kind < 0.07f) view.inputs.depth[i] = nan;
        const float r = rng.next();
        view.inputs.material[4 * i + 1] = r < 0.1f ? 0.0f : r < 0.12f ? nan : 0.6f * rng.next();
        if (rng.next() < 0.03f) view.inputs.normals[4 * i + 2] = rng.next() < 0.5f ? 0.0f : nan;
    }
    return view;
}

reference::SssrClassifyInputs classifyReferenceInputs(const SssrTestView& view) {
    reference::SssrClassifyInputs in;
    in.width = view.desc.size.width;
    in.height = view.desc.size.height;
    in.depth = view.inputs.depth;
    in.reversedDepth = view.desc.depth == DepthConvention::Reversed;
    in.roughnessThreshold = view.desc.roughnessThreshold;
    in.mirrorThreshold = view.desc.mirrorThreshold;
    in.samplesPerQuad = view.desc.samplesPerQuad;
    const std::size_t count = std::size_t{in.width} * in.height;
    for (std::size_t i = 0; i < count; ++i) {
        const float r = view.inputs.material[4 * i + view.desc.materialChannel];
        in.alpha.push_back(std::isfinite(r) ? std::clamp(r, 0.0f, 1.0f) * std::clamp(r, 0.0f, 1.0f) : 1.0f);
        for (std::size_t c = 0; c < 3; ++c) in.normals.push_back(view.inputs.normals[4 * i + c]);
    }
    return in;
}

} // namespace glint::test
