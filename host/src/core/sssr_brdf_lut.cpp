// The split-sum DFG table for the SSSR composite (Karis 2013, "Real Shading in Unreal Engine 4").
//
// With Schlick's Fresnel F = F0 + (1 - F0) Fc, Fc = (1 - V.H)^5, the directional albedo of the
// specular lobe splits into F0 * A + B:
//   A = integral of (1 - Fc) f_1 N.L dL,   B = integral of Fc f_1 N.L dL,
// where f_1 = D G2 / (4 N.L N.V) is the GGX microfacet BRDF without Fresnel. D is GGX with
// alpha = perceptualRoughness^2. G2 is the height-correlated Smith masking-shadowing
// G2 = 1 / (1 + Lambda(V) + Lambda(L)) (Heitz 2014): it accounts for a microfacet that is masked
// from V being more likely shadowed from L as well, which the separable form G1(V) G1(L) ignores
// (that form is never larger, so it darkens rough surfaces more than the Smith model says).
//
// Integration: importance sampling of the visible normals (Heitz 2018, VNDF) with a fixed
// 1024-point Hammersley set, identical for every texel. With H drawn from D_V(H) and L the mirror
// of V about H, the estimator of the integral of f_1 N.L is G2(V, L) / G1(V); samples with
// N.L <= 0 count as 0. That weight never exceeds 1, so 0 <= A, B and A + B <= 1 hold per sample,
// and its variance is far lower than with D-proportional sampling at grazing N.V.
#include "glint/glint_sssr_tables.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace glint {
namespace {

constexpr std::uint32_t kSampleCount = 1024;
constexpr double kPi = 3.14159265358979323846;

struct Vec3 {
    double x;
    double y;
    double z;
};

Vec3 operator*(double s, Vec3 v) {
    return {s * v.x, s * v.y, s * v.z};
}
Vec3 operator+(Vec3 a, Vec3 b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
double dot(Vec3 a, Vec3 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
Vec3 cross(Vec3 a, Vec3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Vec3 normalize(Vec3 v) {
    return (1.0 / std::sqrt(dot(v, v))) * v;
}

// Van der Corput radical inverse in base 2: the second Hammersley coordinate.
double radicalInverse2(std::uint32_t bits) {
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return static_cast<double>(bits) * (1.0 / 4294967296.0);
}

// Smith Lambda for GGX, direction at cosine c to the normal (c > 0).
double smithLambda(double c, double alpha) {
    const double tan2 = std::max(0.0, 1.0 - c * c) / (c * c);
    return 0.5 * (std::sqrt(1.0 + alpha * alpha * tan2) - 1.0);
}

// A point of the 1024-point Hammersley set, mapped to the unit disc (polar: radius sqrt(u1), angle
// 2 pi u2); the same for every texel, so computed once.
struct DiscSample {
    double x;
    double y;
};

std::vector<DiscSample> hammersleyDisc() {
    std::vector<DiscSample> samples(kSampleCount);
    for (std::uint32_t k = 0; k < kSampleCount; ++k) {
        const double radius = std::sqrt((k + 0.5) / kSampleCount);
        const double phi = 2.0 * kPi * radicalInverse2(k);
        samples[k] = {radius * std::cos(phi), radius * std::sin(phi)};
    }
    return samples;
}

// A visible normal for view v (tangent space, z = normal) from a disc sample (Heitz 2018).
Vec3 sampleVisibleNormal(Vec3 v, double alpha, DiscSample disc) {
    const Vec3 vh = normalize({alpha * v.x, alpha * v.y, v.z});
    const double lengthSquared = vh.x * vh.x + vh.y * vh.y;
    const Vec3 t1 =
        lengthSquared > 0.0 ? (1.0 / std::sqrt(lengthSquared)) * Vec3{-vh.y, vh.x, 0.0} : Vec3{1.0, 0.0, 0.0};
    const Vec3 t2 = cross(vh, t1);
    const double s = 0.5 * (1.0 + vh.z);
    const double p1 = disc.x;
    const double p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + s * disc.y;
    const Vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
    return normalize({alpha * nh.x, alpha * nh.y, std::max(0.0, nh.z)});
}

// (A, B) at N.V = nDotV (> 0) and alpha (> 0).
void integrateDfg(double nDotV, double alpha, const std::vector<DiscSample>& samples, float* out) {
    const Vec3 v{std::sqrt(1.0 - nDotV * nDotV), 0.0, nDotV};
    const double lambdaV = smithLambda(nDotV, alpha);
    double a = 0.0;
    double b = 0.0;
    for (const DiscSample& disc : samples) {
        const Vec3 h = sampleVisibleNormal(v, alpha, disc);
        const double vDotH = dot(v, h);
        const double nDotL = 2.0 * vDotH * h.z - v.z; // (2 (V.H) H - V).z
        if (nDotL <= 0.0 || vDotH <= 0.0) continue;
        const double weight = (1.0 + lambdaV) / (1.0 + lambdaV + smithLambda(nDotL, alpha)); // G2 / G1(V)
        const double c = 1.0 - vDotH;
        const double fc = (c * c) * (c * c) * c;
        a += (1.0 - fc) * weight;
        b += fc * weight;
    }
    out[0] = static_cast<float>(a / static_cast<double>(samples.size()));
    out[1] = static_cast<float>(b / static_cast<double>(samples.size()));
}

} // namespace

std::vector<float> sssrBrdfLut(std::uint32_t size) {
    if (size == 0 || size > kSssrBrdfLutMaxSize) return {};
    const std::vector<DiscSample> samples = hammersleyDisc();
    std::vector<float> table(static_cast<std::size_t>(size) * size * 2u);
    for (std::uint32_t j = 0; j < size; ++j) {
        const double perceptualRoughness = (j + 0.5) / size;
        const double alpha = perceptualRoughness * perceptualRoughness;
        for (std::uint32_t i = 0; i < size; ++i) {
            const double nDotV = (i + 0.5) / size;
            integrateDfg(nDotV, alpha, samples, &table[(static_cast<std::size_t>(j) * size + i) * 2u]);
        }
    }
    return table;
}

} // namespace glint
