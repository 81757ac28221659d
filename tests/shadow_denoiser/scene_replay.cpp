#include "shadow_denoiser/scene_replay.h"

#include "support/test_replay.h"

#include <algorithm>
#include <cmath>

namespace glint::test {
namespace {

std::vector<std::uint8_t> hardPixels(const ShadowDenoiserDesc& desc, const ShadowInputs& inputs) {
    const int w = static_cast<int>(desc.size.width), h = static_cast<int>(desc.size.height);
    std::vector<std::uint8_t> hard(inputs.depth.size(), 0u);
    if (!(desc.penumbraAware && desc.lightTanHalfAngle >= 0.0f && desc.pixelAngularSize > 0.0f)) return hard;
    const double scale = 2.0 * double(desc.lightTanHalfAngle) / double(desc.pixelAngularSize);
    const double n = double(desc.nearPlane), f = double(desc.farPlane);
    const bool reversed = desc.depth == ShadowDenoiserDepth::Reversed;
    std::vector<double> width(inputs.depth.size(), 0.0);
    for (std::size_t i = 0; i < width.size(); ++i) {
        const double d = inputs.depth[i];
        if (!(d > 1e-6 && d < 1.0 - 1e-6) || inputs.visibility[i] >= 0.5f) continue; // lit or not a receiver
        // View depth of device depth d (docs/integration.md, 2.2).
        const double z = reversed ? (f > 0.0 ? n * f / (n + d * (f - n)) : n / d) : n * f / (f - d * (f - n));
        const double b = inputs.blockerDistance.empty() ? -1.0 : double(inputs.blockerDistance[i]);
        width[i] = scale == 0.0 ? 0.0 : (std::isfinite(b) && b >= 0.0 ? scale * b / z : 64.0);
    }
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double widest = 0.0;
            for (int dy = -4; dy <= 4; ++dy)
                for (int dx = -4; dx <= 4; ++dx)
                    widest =
                        std::max(widest, width[std::size_t(std::clamp(y + dy, 0, h - 1)) * std::size_t(w) +
                                               std::size_t(std::clamp(x + dx, 0, w - 1))]);
            hard[std::size_t(y) * std::size_t(w) + std::size_t(x)] = widest <= 1.0 ? 1u : 0u;
        }
    return hard;
}

} // namespace

SceneShadowReplay::Result SceneShadowReplay::run(const capture::Frame& frame, std::uint32_t index) {
    ShadowDenoiserDesc desc;
    replay::shadowDescFromFrame(frame, index, index == 0, desc);
    desc.penumbraAware = penumbraAware_;
    if (!runner_) runner_.emplace(desc);
    Result result;
    result.inputs = replay::shadowInputsFromFrame(frame, previousDepth_);
    result.outputs = runner_->run(desc, result.inputs);
    result.hard = hardPixels(desc, result.inputs);
    previousDepth_ = result.inputs.depth;
    return result;
}

} // namespace glint::test
