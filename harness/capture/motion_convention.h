// The one place where motion vectors are converted into the package's convention
// (docs/conventions.md §3, convention A): mv = uv_prev - uv_cur in UV units, +v down,
// unjittered, so the previous-frame position of pixel uv is uv + mv.
//
// A capture declares how its motion layer is stored: units (UV, pixels or NDC of the
// capture's own NDC, see Camera::ndcYDown) and a float2 scale. The stored vector times the
// scale is (previous - current) in those units. Other conventions are expressed through
// the scale's sign: convention B (NDC, current - previous) is {Ndc, (-1,-1)}, convention C
// (UV, current - previous) is {Uv, (-1,-1)}, pixel motion is {Pixels, (1,1)}.
#pragma once

#include "capture/capture_frame.h"

#include <cstdint>

namespace glint::capture {

inline constexpr MotionConvention kConventionA{MotionUnits::Uv, {1.0f, 1.0f}};

// One stored motion vector to convention A for a width x height image.
Float2 toConventionA(Float2 stored, const MotionConvention& convention, std::uint32_t width,
                     std::uint32_t height, bool ndcYDown);

// Converts the frame's "motion" layer (channels X,Y) in place and sets frame.motion to
// kConventionA. A frame without a motion layer only has its declaration reset.
void convertMotionToConventionA(Frame& frame);

} // namespace glint::capture
