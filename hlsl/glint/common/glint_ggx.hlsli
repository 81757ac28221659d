// GGX microfacet math shared by the reflection passes: the NDF, Smith masking, visible-normal
// (VNDF) sampling with Frostbite's importance-sample bias, the pdf of the sampled reflection,
// and the tangent frame that takes world directions into the sampler's local frame.
//
// Integration: include from any glint header; defines no resources and needs no callbacks.
// No entry function, constants or dispatch of its own.
// Conventions (docs/conventions.md §4 and §5):
//   - every function takes GGX alpha (= perceptualRoughness^2), never perceptual roughness;
//   - "local" means a tangent frame with z = the shading normal N (GLINT_GGX_TangentFrame);
//   - V points away from the surface (towards the viewer), unit length, V.z > 0. A shading
//     normal that faces away from V must go through GLINT_GGX_BendNormalTowardView first.
// Every function returns finite values for finite input with alpha in [0, 1] and u in
// [0, 1), including alpha = 0, grazing V and V = N.
#ifndef GLINT_GGX_HLSLI
#define GLINT_GGX_HLSLI

#include "glint/common/glint_math.hlsli"

#define GLINT_GGX_PI 3.14159265358979

// alpha below this is treated as this. alpha = 0 is a mirror (a delta NDF) that no float
// pdf can express; 1e-4 is the references' mirror threshold (docs/conventions.md §4), so
// everything the passes call "mirror" samples and evaluates as the same narrow, finite lobe:
// D peaks at 1 / (pi alpha^2) ~ 3.2e7, far inside float range, and the lobe is ~1e-4 rad wide,
// far below a texel's footprint.
#define GLINT_GGX_MIN_ALPHA 1e-4

// GLINT_GGX_BendNormalTowardView makes N.V at least this. It is twice the 1e-4 that
// docs/conventions.md §5 asks for, so that rounding in the bend (~1e-7) cannot take the
// result below 1e-4.
#define GLINT_GGX_BENT_NDOTV 2e-4

// alpha in [GLINT_GGX_MIN_ALPHA, 1]: a non-finite alpha becomes 1 (the widest lobe, the one
// least likely to look like a sharp artefact), and alpha > 1 is outside the roughness range.
float GLINT_GGX_ClampAlpha(float alpha)
{
    return clamp(GLINT_FiniteOr(alpha, 1.0), GLINT_GGX_MIN_ALPHA, 1.0);
}

// normalize(v), or `fallback` when v is (nearly) zero, where normalize would divide by zero.
float3 GLINT_GGX_SafeNormalize(float3 v, float3 fallback)
{
    float lengthSquared = dot(v, v);
    return lengthSquared > 1e-30 ? v * rsqrt(lengthSquared) : fallback;
}

// GGX (Trowbridge-Reitz) NDF: alpha^2 / (pi ((N.H)^2 (alpha^2 - 1) + 1)^2), zero for N.H <= 0.
// The bracket is written as (1 - c^2) + c^2 alpha^2: with alpha^2 ~ 1e-8 the textbook form
// rounds alpha^2 - 1 to -1 in float and the bracket to 0 at c = 1 (D = inf). The rewritten
// bracket is a convex combination of 1 and alpha^2, so it never drops below alpha^2.
float GLINT_GGX_D(float NdotH, float alpha)
{
    float a = GLINT_GGX_ClampAlpha(alpha);
    float a2 = a * a;
    float c = GLINT_Saturate(GLINT_FiniteOr(NdotH, 0.0));
    float sin2 = max((1.0 - c) * (1.0 + c), 0.0);
    float bracket = sin2 + c * c * a2;
    return NdotH > 0.0 ? a2 / (GLINT_GGX_PI * bracket * bracket) : 0.0;
}

// The shared denominator of G1 and the pdf: c + sqrt(alpha^2 + c^2 (1 - alpha^2)), which is
// c (1 + sqrt(1 + alpha^2 tan^2)) with tan^2 = (1 - c^2) / c^2 multiplied through by c, so
// no tangent (infinite at grazing) and no division by c appear. It is >= alpha > 0.
float GLINT_GGX_SmithDenominator(float NdotV, float alpha)
{
    float a = GLINT_GGX_ClampAlpha(alpha);
    float a2 = a * a;
    float c = GLINT_Saturate(GLINT_FiniteOr(NdotV, 0.0));
    return c + sqrt(a2 + c * c * (1.0 - a2));
}

// Smith masking for GGX: 2 / (1 + sqrt(1 + alpha^2 tan^2(theta_V))) = 2c / (c + sqrt(...))
// (see GLINT_GGX_SmithDenominator). 0 for a back-facing V (N.V <= 0).
float GLINT_GGX_SmithG1(float NdotV, float alpha)
{
    float c = GLINT_Saturate(GLINT_FiniteOr(NdotV, 0.0));
    return 2.0 * c / GLINT_GGX_SmithDenominator(NdotV, alpha);
}

// Density (per steradian) of the reflected direction L = reflect(-V, H) when H is drawn by
// GLINT_GGX_SampleVndf with bias 0: the VNDF G1(V) max(0, V.H) D(H) / (N.V) times the
// reflection Jacobian 1 / (4 V.H), i.e. G1(V) D(H) / (4 N.V). V.H cancels, and so does N.V
// against the c in G1 = 2c / denominator, leaving D / (2 denominator): finite even for
// N.V -> 0. NdotH = N.normalize(V + L). Directions below the horizon (N.L <= 0) have this
// density too: the sampler produces them and the pdf must count them.
// With bias b > 0 the sampler's true density differs (it is this one restricted to the
// reachable cap and divided by 1 - b); callers deliberately keep this one (docs/sssr.md,
// "Intersection": the stored pdf and the environment LOD are bias-free).
float GLINT_GGX_ReflectionPdf(float NdotV, float NdotH, float alpha)
{
    return GLINT_GGX_D(NdotH, alpha) / (2.0 * GLINT_GGX_SmithDenominator(NdotV, alpha));
}

// Visible-normal sampling (Heitz 2018) in the spherical-cap form (Dupuy & Benyoub 2023).
// Vlocal: unit view direction in the local frame (z = N, Vlocal.z > 0); u in [0, 1)^2;
// bias in [0, 1]. Returns the microfacet normal H in the local frame (H.z >= 0).
//
// Stretching by alpha turns the GGX surface into the hemisphere configuration, whose visible
// normals are Nh = c + Vh with c uniform on the spherical cap {c.z >= -Vh.z} of the unit
// sphere. Uniform area on a cap = uniform height z and uniform azimuth (Archimedes), so
// z = 1 - s (1 + Vh.z) with s = u.y in [0, 1) runs from the cap's pole (s = 0) to its rim
// (s -> 1). At s = 0, c = (0, 0, 1) and Nh = N + Vh bisects N and Vh: the lobe centre, whose
// reflection is the stretched mirror direction; larger s moves away from it.
//
// Importance-sample bias (Frostbite; docs/sssr.md, "Parameters"): s = (1 - bias) u.y shrinks s
// towards 0, i.e. towards the lobe centre: samples come only from the part of the cap nearest
// the pole, z in (bias - (1 - bias) Vh.z, 1], which sharpens the reflection and lowers noise at
// the cost of a biased estimate. bias = 0 is the unbiased sampler; bias = 1 always returns the
// lobe centre.
float3 GLINT_GGX_SampleVndf(float3 Vlocal, float alpha, float2 u, float bias)
{
    float a = GLINT_GGX_ClampAlpha(alpha);
    float3 Vh = GLINT_GGX_SafeNormalize(float3(a * Vlocal.x, a * Vlocal.y, Vlocal.z), float3(0.0, 0.0, 1.0));
    float b = GLINT_Saturate(GLINT_FiniteOr(bias, 0.0));
    float s = (1.0 - b) * GLINT_Saturate(GLINT_FiniteOr(u.y, 0.0));
    // z = (1 - s)(1 + Vh.z) - Vh.z, but the cap radius sqrt(1 - z^2) is taken from 1 - z and
    // 1 + z written without cancellation: from z itself, the rounding of z near the pole
    // (~1e-7) became a radius of ~5e-4, moving the densest samples by up to ~1e-4 rad and
    // putting s = 0 off the lobe centre. Both factors below are sums of non-negative terms.
    float oneMinusZ = s * (1.0 + Vh.z);
    float onePlusZ = (1.0 - s) * (1.0 + Vh.z) + (1.0 - Vh.z);
    float z = 1.0 - oneMinusZ;
    float r = sqrt(max(oneMinusZ * onePlusZ, 0.0));
    float phi = 2.0 * GLINT_GGX_PI * GLINT_Saturate(GLINT_FiniteOr(u.x, 0.0));
    float3 Nh = float3(r * cos(phi), r * sin(phi), z) + Vh;
    // Nh.z >= 0 in exact arithmetic (z >= -Vh.z); max() removes rounding below it. Nh is zero
    // only at the single rim point c = -Vh, where any normal is as good as another.
    return GLINT_GGX_SafeNormalize(float3(a * Nh.x, a * Nh.y, max(Nh.z, 0.0)), float3(0.0, 0.0, 1.0));
}

// reflect(-V, H) = 2 (V.H) H - V: the mirror of V about the microfacet normal H.
float3 GLINT_GGX_Reflect(float3 V, float3 H)
{
    return 2.0 * dot(V, H) * H - V;
}

// The sampled reflection direction L (local frame) for GLINT_GGX_SampleVndf's arguments; its
// density for bias 0 is GLINT_GGX_ReflectionPdf(Vlocal.z, H.z, alpha). L may point below the
// horizon (L.z <= 0); callers decide what that means (the reference keeps such rays).
float3 GLINT_GGX_SampleReflection(float3 Vlocal, float alpha, float2 u, float bias)
{
    return GLINT_GGX_Reflect(Vlocal, GLINT_GGX_SampleVndf(Vlocal, alpha, u, bias));
}

// An orthonormal, right-handed frame (t, b, n) around the unit normal n, without branches on
// the hot path (Duff et al. 2017, "Building an orthonormal basis, revisited"): for n.z >= 0
// it is the frame that rotates (0, 0, 1) to n about the axis z x n, and for n.z < 0 the same
// construction mirrored through the xy plane, so each hemisphere's frame is continuous and
// exact down to n = (0, 0, -1), where the unmirrored formula divides by zero. A frame that
// is continuous everywhere does not exist (hairy-ball theorem); the seam is the equator.
// Isotropic GGX does not care which frame it gets, only that the sampled noise has no seams
// inside a surface, which this gives away from n.z = 0.
void GLINT_GGX_TangentFrame(float3 n, out float3 t, out float3 b)
{
    // sign(0) must be +1 here (HLSL's sign() returns 0), and -0.0 must not divide by zero:
    // n.z >= 0 is true for -0.0, so the denominator is 1 + n.z >= 1.
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float k = -1.0 / (s + n.z);
    float xy = n.x * n.y * k;
    t = float3(1.0 + s * n.x * n.x * k, s * xy, -s * n.x);
    b = float3(xy, s + n.y * n.y * k, -n.y);
}

// World direction -> local frame (t, b, n) from GLINT_GGX_TangentFrame.
float3 GLINT_GGX_ToLocal(float3 v, float3 t, float3 b, float3 n)
{
    return float3(dot(v, t), dot(v, b), dot(v, n));
}

// Local direction -> world; the inverse of GLINT_GGX_ToLocal for an orthonormal frame.
float3 GLINT_GGX_ToWorld(float3 v, float3 t, float3 b, float3 n)
{
    return v.x * t + v.y * b + v.z * n;
}

// A unit shading normal facing the unit view direction v: n itself when n.v >= 2e-4,
// otherwise n rotated towards v in the plane of n and v until n.v = 2e-4 (the smallest
// change that makes V sampleable; docs/conventions.md §5, VNDF needs V.z > 0). Normal maps
// produce such back-facing normals at grazing angles. When n = -v the plane is undefined and
// any direction perpendicular to v serves; the frame around v supplies one.
float3 GLINT_GGX_BendNormalTowardView(float3 n, float3 v)
{
    float NdotV = dot(n, v);
    if (NdotV >= GLINT_GGX_BENT_NDOTV) return n;
    float3 t, b;
    GLINT_GGX_TangentFrame(v, t, b);
    float3 across = GLINT_GGX_SafeNormalize(n - NdotV * v, t);
    float c = GLINT_GGX_BENT_NDOTV;
    return GLINT_GGX_SafeNormalize(sqrt(1.0 - c * c) * across + c * v, v);
}

#endif // GLINT_GGX_HLSLI
