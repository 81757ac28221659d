// The shared view-depth coefficients (glint/common/glint_view_depth.h) against device depths
// made by projecting known view depths through each convention's projection.
#include "glint/common/glint_view_depth.h"

#include <catch2/catch.hpp>

#include <cmath>

using glint::shared::GLINT_ViewDepthCoefficients;
using glint::shared::GLINT_ViewDepthFromDevice;

namespace {

// Device depth of view depth z: clip z / clip w of the standard, reversed and reversed-infinite
// perspective projections (clip w = z).
double standardDevice(double z, double n, double f) {
    return f / (f - n) - n * f / ((f - n) * z);
}
double reversedDevice(double z, double n, double f) {
    return n * f / ((f - n) * z) - n / (f - n);
}
double infiniteDevice(double z, double n) {
    return n / z;
}

} // namespace

TEST_CASE("view depth from device depth inverts each convention's projection", "[core][camera]") {
    const double n = 0.1, f = 1000.0;
    for (const double z : {0.1, 0.37, 1.0, 12.5, 250.0, 999.0}) {
        INFO("z " << z);
        const double standard = GLINT_ViewDepthFromDevice(GLINT_ViewDepthCoefficients(false, n, f),
                                                          static_cast<float>(standardDevice(z, n, f)));
        const double reversed = GLINT_ViewDepthFromDevice(GLINT_ViewDepthCoefficients(true, n, f),
                                                          static_cast<float>(reversedDevice(z, n, f)));
        const double infinite = GLINT_ViewDepthFromDevice(GLINT_ViewDepthCoefficients(true, n, 0.0),
                                                          static_cast<float>(infiniteDevice(z, n)));
        // Standard depth: B + C d cancels to about n / z, so the float rounding of d and of the
        // sum (about 1.2e-7 each) becomes a relative error of about 2.4e-7 z / n: 2.4e-6 z^2 at
        // n = 0.1; the bound allows under twice that. Reversed depth keeps float precision.
        CHECK(std::abs(standard - z) <= 4e-6 * z * z);
        CHECK(std::abs(reversed - z) <= 1e-5 * z);
        CHECK(std::abs(infinite - z) <= 1e-6 * z);
    }
    // The planes themselves.
    CHECK(GLINT_ViewDepthFromDevice(GLINT_ViewDepthCoefficients(false, n, f), 0.0f) ==
          Approx(n).epsilon(1e-6));
    CHECK(GLINT_ViewDepthFromDevice(GLINT_ViewDepthCoefficients(true, n, f), 0.0f) ==
          Approx(f).epsilon(1e-5));
}
