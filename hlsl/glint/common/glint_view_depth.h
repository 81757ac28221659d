// View depth from device depth, compiled by both C++ and HLSL: every pass that needs a
// surface's distance takes the coefficients (A, B, C, 0) in its constants and computes
//   z_view = A / (B + C d)
// for device depth d (docs/conventions.md §2.1):
//   standard depth (near 0, far 1)  z = n f / (f - d (f - n)):  A = n f / (f - n), B = f / (f - n), C = -1
//   reversed depth (near 1, far 0)  z = n f / (n + d (f - n)):  A = n f / (f - n), B = n / (f - n), C = +1
//   reversed, infinite far plane    z = n / d:                  A = n,             B = 0,           C = +1
// with n, f the view depths of the near and far planes (f <= 0 selects the infinite form with
// reversed depth). The C++ form computes in double and rounds once, as glint's planners do.
#ifndef GLINT_VIEW_DEPTH_H
#define GLINT_VIEW_DEPTH_H

#include "glint/common/glint_shared_types.h"

#ifdef __cplusplus
namespace glint::shared {

inline float4 GLINT_ViewDepthCoefficients(bool reversed, double n, double f)
{
    if (reversed && !(f > 0.0))
        return {static_cast<float>(n), 0.0f, 1.0f, 0.0f};
    const double a = n * f / (f - n);
    if (!reversed)
        return {static_cast<float>(a), static_cast<float>(f / (f - n)), -1.0f, 0.0f};
    return {static_cast<float>(a), static_cast<float>(n / (f - n)), 1.0f, 0.0f};
}

inline float GLINT_ViewDepthFromDevice(float4 coefficients, float d)
{
    return coefficients.x / (coefficients.y + coefficients.z * d);
}

} // namespace glint::shared
#else
float4 GLINT_ViewDepthCoefficients(bool reversed, float n, float f)
{
    if (reversed && !(f > 0.0))
        return float4(n, 0.0, 1.0, 0.0);
    float a = n * f / (f - n);
    return reversed ? float4(a, n / (f - n), 1.0, 0.0) : float4(a, f / (f - n), -1.0, 0.0);
}

float GLINT_ViewDepthFromDevice(float4 coefficients, float d)
{
    return coefficients.x / (coefficients.y + coefficients.z * d);
}
#endif

#endif // GLINT_VIEW_DEPTH_H
