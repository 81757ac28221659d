// reference.reflection: the GGX-VNDF-weighted mean of the radiance arriving along reflected
// rays (docs/scenes.md). Each sample: a microfacet normal from the visible-normal distribution
// (Heitz 2018) for alpha = r^2, the view direction reflected about it; directions below the
// surface are discarded; a hit is shaded as the colour buffer shades it, except that each light's
// visibility is one of the colour buffer's g_scene.shadowSamples cone samples, picked by the
// sample (one shadow ray per light, the same mean); a miss returns the environment. When every
// sample is discarded, the mirror direction is used. Background pixels are 0.
// With g_scene.environmentSampling, each sample is paired with a direction drawn from the
// environment map's brightness, and the environment seen through misses is combined from both
// draws by the balance heuristic (multiple importance sampling): a small, very bright sun disc
// that a wide lobe rarely finds is then found by the second draw, weighted by the lobe's
// density. Hits are counted from the GGX draw alone. The estimate's mean is unchanged.
// The samples' numbers are consecutive points of randomly shifted Kronecker sequences (below),
// so a run of samples covers the lobe evenly. g_reflection_sum holds (sum, used) and
// g_reflection_moments (sum of squared luminance, iterations) over every sample so far of the
// run of unchanged frames (scene_constants.h, sampleBase); the last chunk of a frame writes
// sum / used to g_reflection. Every pixel takes g_scene.referenceFrameSamples samples a frame;
// the chunks past them (up to sampleTotal) sample only the pixels whose estimate's relative
// standard error is not yet below g_scene.referenceNoiseTarget and whose GGX alpha is below
// g_scene.referenceNoiseAlphaBelow, so that the samples go where the variance is, on the pixels
// that are scored.
#include "entry/common/glint_entry_common.hlsli"
#include "../harness/shaders/scene_constants.h"

GLINT_BINDING(0, 0) ConstantBuffer<GLINT_SceneConstants> g_scene;
GLINT_BINDING(1, 0) StructuredBuffer<SceneBvhNode> g_scene_nodes;
GLINT_BINDING(2, 0) StructuredBuffer<ScenePrimitive> g_scene_primitives;
GLINT_BINDING(3, 0) StructuredBuffer<SceneMaterial> g_scene_materials;
GLINT_BINDING(4, 0) StructuredBuffer<SceneLight> g_scene_lights;
GLINT_BINDING(5, 0) Texture2D<float4> g_scene_environment;
GLINT_BINDING(6, 0) GLINT_IMAGE_FORMAT(rgba32f) RWTexture2D<float4> g_reflection;
GLINT_BINDING(7, 0) StructuredBuffer<SceneEnvironmentSample> g_scene_environment_sampling;
GLINT_BINDING(8, 0) GLINT_IMAGE_FORMAT(rgba32f) RWTexture2D<float4> g_reflection_sum;
GLINT_BINDING(9, 0) GLINT_IMAGE_FORMAT(rg32f) RWTexture2D<float2> g_reflection_moments;
GLINT_BINDING(10, 0) GLINT_IMAGE_FORMAT(r32f) RWTexture2D<float> g_roughness; // the G-buffer's perceptual roughness (read)

#include "../harness/shaders/scene_trace.hlsli"
#include "../harness/shaders/scene_surface.hlsli"
#include "../harness/shaders/scene_light.hlsli"
#include "../harness/shaders/scene_shading.hlsli"
#include "../harness/shaders/scene_environment_sampling.hlsli"

// Visible normal in tangent space (z = surface normal) for view ve (ve.z > 0).
float3 SceneSampleVndf(float3 ve, float alpha, float u1, float u2)
{
    float3 vh = normalize(float3(alpha * ve.x, alpha * ve.y, ve.z));
    float lensq = vh.x * vh.x + vh.y * vh.y;
    float3 t1 = lensq > 0.0 ? float3(-vh.y, vh.x, 0.0) * rsqrt(lensq) : float3(1.0, 0.0, 0.0);
    float3 t2 = cross(vh, t1);
    float r = sqrt(u1);
    float phi = 2.0 * SCENE_PI * u2;
    float p1 = r * cos(phi);
    float p2 = r * sin(phi);
    float s = 0.5 * (1.0 + vh.z);
    p2 = (1.0 - s) * sqrt(max(1.0 - p1 * p1, 0.0)) + s * p2;
    float3 nh = p1 * t1 + p2 * t2 + sqrt(max(1.0 - p1 * p1 - p2 * p2, 0.0)) * vh;
    return normalize(float3(alpha * nh.x, alpha * nh.y, max(nh.z, 1e-6)));
}

// Density over reflected directions of the draw above, for a microfacet normal m (tangent
// space, m.z > 0) and the view ve: D_v(m) / (4 ve.m) = G1(ve) D(m) / (4 ve.z); 0 when ve.m <= 0.
float SceneVndfPdfOfNormal(float3 ve, float alpha, float3 m)
{
    if (dot(ve, m) <= 0.0 || m.z <= 0.0) return 0.0;
    float a2 = alpha * alpha;
    // (m.z^2 (a2 - 1) + 1) written without the cancellation that makes it 0 for tiny alpha.
    float denom = m.x * m.x + m.y * m.y + m.z * m.z * a2;
    float d = a2 / (SCENE_PI * denom * denom);
    float g1 = 2.0 * ve.z / (ve.z + sqrt(a2 * (1.0 - ve.z * ve.z) + ve.z * ve.z));
    return g1 * d / (4.0 * ve.z);
}

// The same density for a reflected direction le (tangent space, unit).
float SceneVndfReflectionPdf(float3 ve, float alpha, float3 le)
{
    float3 m = ve + le;
    float lengthSquared = dot(m, m);
    return lengthSquared > 1e-12 ? SceneVndfPdfOfNormal(ve, alpha, m * rsqrt(lengthSquared)) : 0.0;
}

// Point `index` of the three-dimensional Kronecker sequence with the generalized golden ratio
// (Roberts 2018), shifted by `shift` modulo 1 (a Cranley-Patterson rotation, so every pixel's
// points are uniform and independent of other pixels' and seeds'): the lobe is covered evenly
// by any run of consecutive points, and the estimate's error falls faster than 1 / sqrt(n)
// where the radiance is smooth. Kept in 32-bit fixed point, so the index never loses bits.
float3 SceneLatticePoint(uint index, uint3 shift)
{
    uint3 fraction = shift + index * uint3(0xD1B54A33u, 0xABC98389u, 0x8CB92BA7u);
    return float3(fraction >> 8u) * (1.0 / 16777216.0);
}

// Point `index` of the four-dimensional sequence of the same kind, for the environment draws.
float4 SceneLatticePoint4(uint index, uint4 shift)
{
    uint4 fraction = shift + index * uint4(0xDB4F0B91u, 0xBBE05633u, 0xA0F2EC76u, 0x89E18285u);
    return float4(fraction >> 8u) * (1.0 / 16777216.0);
}

// Balance-heuristic weight of the draw with density `own` against the other draw's `other`.
float SceneMisWeight(float own, float other)
{
    float total = own + other;
    return total > 0.0 ? own / total : 0.0;
}

// Relative standard error of the run's estimate at a pixel from its accumulators: the
// iterations' luminance spread over sqrt(iterations), scaled to the estimate (sum / used), over
// max(its luminance, 0.05) as the error metric divides (replay_error.h). Samples of a Kronecker
// sequence are not independent, so this overstates the error where the sequence helps.
float SceneRelativeStandardError(float4 sum, float2 moments)
{
    float iterations = moments.y;
    if (iterations < 2.0 || sum.a <= 0.0) return 3.0e38;
    float meanLuminance = SceneLuminance(sum.rgb) / iterations;
    float variance = max(moments.x / iterations - meanLuminance * meanLuminance, 0.0) * iterations / (iterations - 1.0);
    float estimate = SceneLuminance(sum.rgb) / sum.a;
    return sqrt(variance / iterations) * (iterations / sum.a) / max(estimate, 0.05);
}

[numthreads(8, 8, 1)] void main(uint3 id : SV_DispatchThreadID)
{
    if (any(id.xy >= g_scene.size)) return;
    bool lastChunk = g_scene.sampleStart + g_scene.samples >= g_scene.sampleTotal;
    // (sum, used) and (sum of squared luminance, iterations) of the run's earlier samples; none
    // on its first chunk.
    bool runStart = g_scene.sampleBase + g_scene.sampleStart == 0u;
    float4 earlier = runStart ? float4(0.0, 0.0, 0.0, 0.0) : g_reflection_sum[id.xy];
    float2 moments = runStart ? float2(0.0, 0.0) : g_reflection_moments[id.xy];
    // Past the frame's baseline samples, a pixel with an estimate rests when it meets the noise
    // target or its lobe is too rough for the target to apply (a pixel without one, whose every
    // sample was discarded, goes on to the mirror direction below).
    float roughness = g_roughness[id.xy];
    bool resting = g_scene.sampleStart >= g_scene.referenceFrameSamples && earlier.a > 0.0 &&
                   (roughness * roughness >= g_scene.referenceNoiseAlphaBelow ||
                    SceneRelativeStandardError(earlier, moments) < g_scene.referenceNoiseTarget);
    if (resting) {
        if (!lastChunk) return;
        g_reflection[id.xy] = float4(SceneFinite(earlier.rgb / earlier.a), 1.0);
        return;
    }
    float3 origin, dir;
    SceneHit hit;
    bool inside = ScenePrimaryHit(id.xy, origin, dir, hit);
    float3 result = 0.0;
    if (inside) {
        SceneSurface s = SceneSurfaceAt(hit, origin, dir);
        float3 n = s.normal;
        float3 up = abs(n.z) < 0.999 ? float3(0.0, 0.0, 1.0) : float3(1.0, 0.0, 0.0);
        float3 tx = normalize(cross(up, n));
        float3 ty = cross(n, tx);
        // docs/conventions.md §5: never a lower-hemisphere view; clamp its z. Rays reflect the
        // clamped view, so that the density below describes the draw exactly.
        float3 ve = normalize(float3(dot(-dir, tx), dot(-dir, ty), max(dot(-dir, n), 1e-4)));
        float3 v = tx * ve.x + ty * ve.y + n * ve.z;
        bool environmentSampling = g_scene.environmentSampling != 0u;
        float alpha = max(s.perceptualRoughness * s.perceptualRoughness, 1e-4);
        float3 start = SceneOffsetOrigin(s.position, n);
        float3 sum = earlier.rgb;
        uint used = uint(earlier.a);
        float squares = moments.x;
        uint index = uint(moments.y); // the pixel's next point of the run's sequences
        // One shift per pixel for the whole run: its chunks and frames continue one sequence.
        uint pixelRng = SceneSeed(id.xy, g_scene.sequenceFrame, g_scene.passSalt);
        uint3 shift = uint3(SceneHash(pixelRng), SceneHash(pixelRng ^ 0x68E31DA4u), SceneHash(pixelRng ^ 0xB5297A4Du));
        uint4 environmentShift = uint4(SceneHash(pixelRng ^ 0x1B873593u), SceneHash(pixelRng ^ 0xCC9E2D51u),
                                       SceneHash(pixelRng ^ 0x27D4EB2Fu), SceneHash(pixelRng ^ 0x165667B1u));
        for (uint i = 0; i < g_scene.samples; ++i, ++index) {
            float3 contribution = 0.0;
            float3 u = SceneLatticePoint(index, shift);
            float3 m = SceneSampleVndf(ve, alpha, u.x, u.y);
            float3 h = normalize(tx * m.x + ty * m.y + n * m.z);
            float3 l = reflect(-v, h);
            if (dot(n, l) > 0.0) {
                ++used;
                SceneHit hit = SceneTrace(start, l, 3.0e38, false);
                if (hit.t >= 0.0) {
                    contribution += SceneFinite(SceneShadeStrata(SceneSurfaceAt(hit, start, l), -l, true, u.z));
                } else {
                    float weight = environmentSampling
                                       ? SceneMisWeight(SceneVndfPdfOfNormal(ve, alpha, m), SceneEnvironmentPdf(l))
                                       : 1.0;
                    contribution += SceneFinite(SceneEnvironment(l) * weight);
                }
            }
            if (environmentSampling) {
                float3 le = SceneSampleEnvironment(SceneLatticePoint4(index, environmentShift));
                float3 leTangent = float3(dot(le, tx), dot(le, ty), dot(le, n));
                float lobePdf = leTangent.z > 0.0 ? SceneVndfReflectionPdf(ve, alpha, leTangent) : 0.0;
                if (lobePdf > 0.0 && SceneTrace(start, le, 3.0e38, true).t < 0.0) {
                    float environmentPdf = SceneEnvironmentPdf(le);
                    // Weighted GGX density over the environment draw's density:
                    // SceneMisWeight(lobePdf, environmentPdf) * lobePdf / environmentPdf, kept finite.
                    contribution += SceneFinite(SceneEnvironment(le) * (lobePdf / (lobePdf + environmentPdf)));
                }
            }
            sum += contribution;
            squares += SceneLuminance(contribution) * SceneLuminance(contribution);
        }
        g_reflection_sum[id.xy] = float4(sum, float(used));
        g_reflection_moments[id.xy] = float2(squares, float(index));
        if (!lastChunk) return;
        result = used > 0 ? sum / float(used) : SceneFinite(SceneRadianceAlong(start, reflect(-v, n)));
    } else if (!lastChunk) {
        return;
    }
    g_reflection[id.xy] = float4(SceneFinite(result), 1.0);
}
