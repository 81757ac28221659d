// The composite against the split-sum formula evaluated on the CPU, L = L_lit + R (F0 A + B),
// with (A, B) interpolated bilinearly from glint::sssrBrdfLut() at (N.V, r) and V the pixel's
// own view vector: a tilted plane seen by a perspective camera, so N.V varies over the image.
#include "core/camera.h"
#include "glint/glint_reflections_denoiser.h"
#include "glint/glint_sssr_tables.h"
#include "sssr/sssr_test_scene.h"
#include "support/gpu_test_context.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace glint;

namespace {

// Bilinear fetch with clamp-to-edge at texel centres (i + 0.5) / size.
std::array<double, 2> sampleLut(const std::vector<float>& lut, std::uint32_t size, double u, double v) {
    const double x = std::clamp(u * size - 0.5, 0.0, size - 1.0),
                 y = std::clamp(v * size - 0.5, 0.0, size - 1.0);
    const auto x0 = static_cast<std::uint32_t>(x), y0 = static_cast<std::uint32_t>(y);
    const std::uint32_t x1 = std::min(x0 + 1, size - 1), y1 = std::min(y0 + 1, size - 1);
    const double fx = x - x0, fy = y - y0;
    std::array<double, 2> out{};
    for (std::size_t c = 0; c < 2; ++c) {
        auto at = [&](std::uint32_t i, std::uint32_t j) {
            return static_cast<double>(lut[2 * (j * size + i) + c]);
        };
        out[c] = (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x1, y0)) +
                 fy * ((1 - fx) * at(x0, y1) + fx * at(x1, y1));
    }
    return out;
}

} // namespace

TEST_CASE("the composite applies the reflection with split-sum specular per pixel", "[sssr][composite]") {
    const std::uint32_t w = 48, h = 32;
    test::SssrTestView view = test::makeSssrTestView(w, h, false);
    view.desc.composite = true;
    // With the denoiser, the composite must apply the denoised reflection (out.radiance is the
    // denoiser's output then), so the denoiser has to run before it.
    const bool denoise = GENERATE(false, true);
    INFO((denoise ? "with the denoiser" : "without the denoiser"));
    view.desc.denoise = denoise;
    view.desc.roughnessThreshold = 1.0f; // every pixel glossy: the composite sees each one's alpha
    // A plane y = -1 (normal +y) in front of the camera covers the lower half; the rest is sky.
    for (std::uint32_t y = h / 2 + 1; y < h; ++y)
        for (std::uint32_t x = 0; x < w; ++x) {
            const std::size_t i = std::size_t{y} * w + x;
            const double ndcY = -(2.0 * (y + 0.5) / h - 1.0); // D3D-style
            const double g = view.desc.projection[5];
            const double viewDepth = g / -ndcY; // the plane y = -1: y_view = ndcY z / g = -1
            test::setViewDepth(view, x, y, viewDepth);
            view.inputs.normals[4 * i + 0] = 0.0f;
            view.inputs.normals[4 * i + 1] = 1.0f;
            view.inputs.normals[4 * i + 2] = 0.0f;
            view.inputs.material[4 * i] = static_cast<float>(x) / static_cast<float>(w - 1); // alpha 0..1
            view.inputs.baseColorMetallic[4 * i + 0] = 0.9f;
            view.inputs.baseColorMetallic[4 * i + 1] = 0.5f;
            view.inputs.baseColorMetallic[4 * i + 2] = 0.1f;
            view.inputs.baseColorMetallic[4 * i + 3] = static_cast<float>(y % 3) * 0.5f; // metallic 0, 0.5, 1
        }
    gpu::SssrRunner runner(test::testContext(), view.desc);
    runner.upload(view.inputs);
    ReflectionsDenoiserDesc denoiser;
    denoiser.halfPrecisionStorage = view.desc.halfPrecisionStorage;
    denoiser.size = view.desc.size;
    denoiser.projection = view.desc.projection;
    denoiser.viewFromWorld = view.desc.viewFromWorld;
    denoiser.previousClipFromWorld = core::multiply(view.desc.projection, view.desc.viewFromWorld);
    denoiser.depth = view.desc.depth;
    denoiser.nearPlane = view.desc.nearPlane;
    denoiser.farPlane = view.desc.farPlane;
    denoiser.vulkanNdc = view.desc.vulkanNdc;
    denoiser.roughnessThreshold = view.desc.roughnessThreshold;
    denoiser.resetHistory = true;
    runner.run(view.desc, nullptr, denoise ? &denoiser : nullptr);
    const gpu::SssrFrameOutputs out = runner.readback();
    const std::vector<float> lut = sssrBrdfLut(kSssrBrdfLutSize);
    std::size_t checked = 0;
    for (std::uint32_t y = 0; y < h; ++y)
        for (std::uint32_t x = 0; x < w; ++x) {
            const std::size_t i = std::size_t{y} * w + x;
            INFO("pixel " << x << "," << y);
            const bool surface = y > h / 2;
            for (std::size_t c = 0; c < 3; ++c) {
                const double lit = view.inputs.color[4 * i + c];
                double expected = lit;
                if (surface) {
                    const double u = (x + 0.5) / w, v = (y + 0.5) / h;
                    const double ndcX = 2 * u - 1, ndcY = -(2 * v - 1);
                    const double g = view.desc.projection[5], ga = view.desc.projection[0];
                    const double z = g / -ndcY;
                    const std::array<double, 3> p{ndcX * z / ga, -1.0, -z};
                    const double length = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
                    const double nDotV = std::clamp(-p[1] / length, 0.0, 1.0); // N = +y, V = -p / |p|
                    const double alpha = view.inputs.material[4 * i];
                    const auto ab = sampleLut(lut, kSssrBrdfLutSize, nDotV, std::sqrt(alpha));
                    const double metallic = view.inputs.baseColorMetallic[4 * i + 3];
                    const double f0 =
                        0.04 +
                        (static_cast<double>(view.inputs.baseColorMetallic[4 * i + c]) - 0.04) * metallic;
                    expected = lit + static_cast<double>(out.radiance[4 * i + c]) * (f0 * ab[0] + ab[1]);
                    ++checked;
                }
                // GPU bilinear weights carry 8 fractional bits: up to 1/512 of a texel step of
                // the table (< 0.1 between neighbours) times a radiance of order 1.
                REQUIRE(out.composite[4 * i + c] == Approx(expected).margin(2e-3));
            }
        }
    CHECK(checked == 3u * w * (h - h / 2 - 1));
    GLINT_REQUIRE_NO_VALIDATION_ERRORS();
}
