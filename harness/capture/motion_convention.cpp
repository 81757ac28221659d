#include "capture/motion_convention.h"

#include <cstddef>

namespace glint::capture {

Float2 toConventionA(Float2 stored, const MotionConvention& convention, std::uint32_t width,
                     std::uint32_t height, bool ndcYDown) {
    // Double arithmetic so that the UV/(1,1) case is exact and the others round once.
    const double dx = static_cast<double>(stored.x) * static_cast<double>(convention.scale.x);
    const double dy = static_cast<double>(stored.y) * static_cast<double>(convention.scale.y);
    double du = dx, dv = dy;
    switch (convention.units) {
    case MotionUnits::Uv:
        break;
    case MotionUnits::Pixels: // pixel +y is down, like v
        du = dx / static_cast<double>(width);
        dv = dy / static_cast<double>(height);
        break;
    case MotionUnits::Ndc: // NDC spans 2 units across the image; its y sign depends on the API
        du = 0.5 * dx;
        dv = ndcYDown ? 0.5 * dy : -0.5 * dy;
        break;
    }
    return {static_cast<float>(du), static_cast<float>(dv)};
}

void convertMotionToConventionA(Frame& frame) {
    Layer* motion = findLayer(frame, "motion");
    const MotionConvention declared = frame.motion;
    frame.motion = kConventionA;
    if (!motion) return;
    const int ix = channelIndex(motion->channels, "X");
    const int iy = channelIndex(motion->channels, "Y");
    if (ix < 0 || iy < 0) return; // validation reports this; nothing to convert
    const std::size_t stride = motion->channels.size();
    const auto x = static_cast<std::size_t>(ix);
    const auto y = static_cast<std::size_t>(iy);
    for (std::size_t i = 0; i + stride <= motion->pixels.size(); i += stride) {
        const Float2 a = toConventionA({motion->pixels[i + x], motion->pixels[i + y]}, declared, frame.width,
                                       frame.height, frame.camera.ndcYDown);
        motion->pixels[i + x] = a.x;
        motion->pixels[i + y] = a.y;
    }
}

} // namespace glint::capture
