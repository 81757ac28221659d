// Synthetic inputs for the SSSR GPU tests: a perspective camera at the origin looking down
// -z (D3D-style NDC, identity view), and G-buffers built from view depths, so that the CPU
// side knows every surface exactly.
#pragma once

#include "glint/glint_sssr.h"

#include "support/test_sssr_runner.h"

#include <array>
#include <cstdint>

namespace glint::test {

struct SssrTestView {
    SssrDesc desc;
    gpu::SssrFrameInputs inputs;
};

// Column-vector projection (row-major storage): clip w = view depth, standard d in [0, 1] from
// near to far, or reversed.
std::array<double, 16> sssrPerspective(double fovY, double aspect, double nearPlane, double farPlane,
                                       bool reversed);
double sssrDeviceDepth(double viewDepth, double nearPlane, double farPlane, bool reversed);

// A W x H view with constant inputs: depth far everywhere (sky), normals +z, alpha 0
// (material channel 0, alpha convention), a checkerboard colour, zero motion, a 16 x 8
// environment with a vertical gradient.
SssrTestView makeSssrTestView(std::uint32_t width, std::uint32_t height, bool reversed);

void setViewDepth(SssrTestView& view, std::uint32_t x, std::uint32_t y, double viewDepth);

// Depth: a receding floor-like ramp plus random closer rectangles and a few sky pixels;
// normals: random unit vectors facing the camera (n.v >= 0.2).
void fillRandomSurfaces(SssrTestView& view, std::uint32_t seed);

// The pixel's mirror ray in the reference's trace space (pixels, device depth), its end derived
// in double from the geometry of the view-space ray (the near plane toward the camera, the far
// plane away from it), the screen clip as the parameter range, and the degenerate test.
struct SssrCpuRay {
    std::array<double, 3> origin{}, direction{}; // the segment: origin + t direction, t in [0, 1]
    double tEnd = 0.0;                           // the screen clip
    bool degenerate = false;
    bool towardCamera = false; // the view depth falls along the ray
    std::array<double, 3> viewPosition{}, viewDirection{};
};
SssrCpuRay sssrMirrorRay(const SssrTestView& view, std::uint32_t x, std::uint32_t y);

} // namespace glint::test
