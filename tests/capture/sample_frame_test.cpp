// The sample capture checked against an independent computation: unprojection with the
// inverse view-projection and reprojection with the previous view-projection.
#include "capture/capture_test_support.h"

#include <capture/frame_io.h>
#include <capture/frame_validation.h>
#include <capture/sample_frame.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace glint::capture;

namespace {
constexpr std::uint32_t kW = 64, kH = 48;

struct Point {
    double x, y, z;
};

double length(Point p) {
    return std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
}

Point unproject(const Mat4& invVp, double u, double v, double depth) {
    const Vec4 p = transform(invVp, {2.0 * u - 1.0, 1.0 - 2.0 * v, depth, 1.0}); // D3D-style NDC
    return {p.x / p.w, p.y / p.w, p.z / p.w};
}

float sampleAt(const Layer& layer, std::uint32_t x, std::uint32_t y, std::size_t channel) {
    return layer.pixels[(std::size_t{y} * kW + x) * layer.channels.size() + channel];
}
} // namespace

TEST_CASE("sample depths unproject onto the ground plane or the sphere, with matching unit normals",
          "[capture]") {
    const Frame f = makeSampleFrame(kW, kH, 1);
    const Layer& depth = *findLayer(f, "depth");
    const Layer& normal = *findLayer(f, "normal");
    const Mat4 invVp = *inverse(viewProjection(f.camera));
    const Vec4 eye4 = transform(*inverse(f.camera.view), {0.0, 0.0, 0.0, 1.0});
    const Point eye{eye4.x, eye4.y, eye4.z};
    const Point center{0.0, 0.6, 0.0};
    const double radius = 0.6;
    std::size_t onPlane = 0, onSphere = 0, sky = 0, wrong = 0;
    for (std::uint32_t y = 0; y < kH; ++y) {
        for (std::uint32_t x = 0; x < kW; ++x) {
            const double d = sampleAt(depth, x, y, 0);
            const Point n{sampleAt(normal, x, y, 0), sampleAt(normal, x, y, 1), sampleAt(normal, x, y, 2)};
            if (std::fabs(length(n) - 1.0) > 1e-6) ++wrong;
            if (d >= 1.0) {
                ++sky;
                continue;
            }
            const Point p = unproject(invVp, (x + 0.5) / kW, (y + 0.5) / kH, d);
            const double dist = length({p.x - eye.x, p.y - eye.y, p.z - eye.z});
            // A float depth carries half an ulp (< 6e-8) of error; at standard depth that
            // moves the point by about dist^2 * 6e-8 / near along the ray.
            const double tol = 1e-6 * dist * dist + 1e-6;
            const Point fromCenter{p.x - center.x, p.y - center.y, p.z - center.z};
            if (std::fabs(length(fromCenter) - radius) < tol) {
                ++onSphere;
                const double r = length(fromCenter);
                if (std::fabs(n.x - fromCenter.x / r) > 1e-4 || std::fabs(n.y - fromCenter.y / r) > 1e-4 ||
                    std::fabs(n.z - fromCenter.z / r) > 1e-4)
                    ++wrong;
            } else if (std::fabs(p.y) < tol) {
                ++onPlane;
                if (n.x != 0.0 || n.y != 1.0 || n.z != 0.0) ++wrong;
            } else {
                ++wrong;
            }
        }
    }
    CHECK(wrong == 0);
    // The view must show all three, or the checks above prove little.
    CHECK(onPlane > kW * kH / 10);
    CHECK(onSphere > kW * kH / 20);
    CHECK(sky > kW * kH / 20);
}

TEST_CASE("sample motion vectors equal an independent reprojection to within 1e-3 pixels, sky included",
          "[capture]") {
    const Frame f = makeSampleFrame(kW, kH, 1);
    const Layer& depth = *findLayer(f, "depth");
    const Layer& motion = *findLayer(f, "motion");
    const Mat4 invVp = *inverse(viewProjection(f.camera));
    const Vec4 eye = transform(*inverse(f.camera.view), {0.0, 0.0, 0.0, 1.0});
    double worstPx = 0.0, largestMotionPx = 0.0, largestSkyMotionPx = 0.0;
    for (std::uint32_t y = 0; y < kH; ++y) {
        for (std::uint32_t x = 0; x < kW; ++x) {
            const double u = (x + 0.5) / kW, v = (y + 0.5) / kH;
            const double d = sampleAt(depth, x, y, 0);
            const bool sky = d >= 1.0;
            const Point p = unproject(invVp, u, v, sky ? 1.0 : d);
            // The sky reprojects as a point at infinity: only the camera rotation moves it.
            const Vec4 world =
                sky ? Vec4{p.x - eye.x, p.y - eye.y, p.z - eye.z, 0.0} : Vec4{p.x, p.y, p.z, 1.0};
            const Vec4 prev = transform(f.camera.prevViewProjection, world);
            const double prevU = 0.5 * prev.x / prev.w + 0.5;
            const double prevV = 0.5 - 0.5 * prev.y / prev.w;
            const double mu = sampleAt(motion, x, y, 0), mv = sampleAt(motion, x, y, 1);
            const double errPx = std::hypot((u + mu - prevU) * kW, (v + mv - prevV) * kH);
            worstPx = std::max(worstPx, errPx);
            largestMotionPx = std::max(largestMotionPx, std::hypot(mu * kW, mv * kH));
            if (sky) largestSkyMotionPx = std::max(largestSkyMotionPx, std::hypot(mu * kW, mv * kH));
        }
    }
    CHECK(worstPx < 1e-3);
    CHECK(largestMotionPx > 0.2);     // the camera really moves
    CHECK(largestSkyMotionPx > 0.05); // and rotates: the sky is not still
}

TEST_CASE("sample roughness varies across the image and colour is finite", "[capture]") {
    const Frame f = makeSampleFrame(kW, kH, 0);
    REQUIRE(f.roughness.layer == "material");
    REQUIRE(f.roughness.channel == "G");
    CHECK(f.roughness.perceptual);
    const Layer& material = *findLayer(f, "material");
    const std::size_t g = static_cast<std::size_t>(channelIndex(material.channels, "G"));
    float lo = 1.0f, hi = 0.0f;
    for (std::size_t i = g; i < material.pixels.size(); i += material.channels.size()) {
        lo = std::min(lo, material.pixels[i]);
        hi = std::max(hi, material.pixels[i]);
    }
    CHECK(lo >= 0.0f);
    CHECK(lo < 0.1f);
    CHECK(hi > 0.9f);
    CHECK(hi <= 1.0f);
    CHECK(countNonFinite(findLayer(f, "color")->pixels) == 0);
}

TEST_CASE("the sample frame is a valid capture that survives a file round trip", "[capture]") {
    const Frame f = makeSampleFrame(kW, kH, 3);
    CHECK_FALSE(checkFrame(f).has_value());
    CHECK(f.effects == std::vector<std::string>{"reflections"});
    CHECK(f.camera.depth == DepthConvention::Standard);
    CHECK_FALSE(f.camera.ndcYDown);
    const auto file = test::freshTestDir("sample_round_trip") / "frame_0003.exr";
    writeFrame(file, f);
    const Frame read = readFrame(file);
    CHECK(read.frameIndex == 3);
    CHECK(findLayer(read, "motion")->pixels == findLayer(f, "motion")->pixels);
    CHECK(findLayer(read, "depth")->pixels == findLayer(f, "depth")->pixels);
}
