// reference.reflection: the GGX-VNDF-weighted mean of the radiance arriving along reflected
// rays (docs/scenes.md). For each of g_scene.samples samples: a microfacet normal from the
// visible-normal distribution (Heitz 2018) for alpha = r^2, the view direction reflected about
// it; directions below the surface are discarded; a hit is shaded as the colour buffer shades
// it, a miss returns the environment. When every sample is discarded, the mirror direction is
// used. Background pixels are 0.
// With g_scene.environmentSampling, each sample is paired with a direction drawn from the
// environment map's brightness, and the environment seen through misses is combined from both
// draws by the balance heuristic (multiple importance sampling): a small, very bright sun disc
// that a wide lobe rarely finds is then found by the second draw, weighted by the lobe's
// density. Hits are counted from the GGX draw alone. The estimate's mean is unchanged.
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

// Balance-heuristic weight of the draw with density `own` against the other draw's `other`.
float SceneMisWeight(float own, float other)
{
    float total = own + other;
    return total > 0.0 ? own / total : 0.0;
}

[numthreads(8, 8, 1)] void main(uint3 id : SV_DispatchThreadID)
{
    if (any(id.xy >= g_scene.size)) return;
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
        // Each chunk of samples (sampleStart) draws its own random numbers.
        uint rng = SceneSeed(id.xy, g_scene.frameIndex, g_scene.passSalt + g_scene.sampleStart * 0x9E3779B9u);
        // The image holds (sum, used) of the earlier chunks until the last one normalizes.
        float4 earlier = g_scene.sampleStart == 0 ? float4(0.0, 0.0, 0.0, 0.0) : g_reflection[id.xy];
        float3 sum = earlier.rgb;
        uint used = uint(earlier.a);
        for (uint i = 0; i < g_scene.samples; ++i) {
            float u1 = SceneRandom(rng);
            float u2 = SceneRandom(rng);
            float3 m = SceneSampleVndf(ve, alpha, u1, u2);
            float3 h = normalize(tx * m.x + ty * m.y + n * m.z);
            float3 l = reflect(-v, h);
            if (dot(n, l) > 0.0) {
                ++used;
                SceneHit hit = SceneTrace(start, l, 3.0e38, false);
                if (hit.t >= 0.0) {
                    sum += SceneFinite(SceneShade(SceneSurfaceAt(hit, start, l), -l));
                } else {
                    float weight = environmentSampling
                                       ? SceneMisWeight(SceneVndfPdfOfNormal(ve, alpha, m), SceneEnvironmentPdf(l))
                                       : 1.0;
                    sum += SceneFinite(SceneEnvironment(l) * weight);
                }
            }
            if (!environmentSampling) continue;
            float4 ue = float4(SceneRandom(rng), SceneRandom(rng), SceneRandom(rng), SceneRandom(rng));
            float3 le = SceneSampleEnvironment(ue);
            float3 leTangent = float3(dot(le, tx), dot(le, ty), dot(le, n));
            if (leTangent.z <= 0.0) continue;
            float lobePdf = SceneVndfReflectionPdf(ve, alpha, leTangent);
            if (lobePdf <= 0.0 || SceneTrace(start, le, 3.0e38, true).t >= 0.0) continue;
            float environmentPdf = SceneEnvironmentPdf(le);
            // Weighted GGX density over the environment draw's density: SceneMisWeight(lobePdf,
            // environmentPdf) * lobePdf / environmentPdf, written to stay finite.
            sum += SceneFinite(SceneEnvironment(le) * (lobePdf / (lobePdf + environmentPdf)));
        }
        if (g_scene.sampleStart + g_scene.samples < g_scene.sampleTotal) {
            g_reflection[id.xy] = float4(sum, float(used));
            return;
        }
        result = used > 0 ? sum / float(used) : SceneFinite(SceneRadianceAlong(start, reflect(-v, n)));
    }
    g_reflection[id.xy] = float4(SceneFinite(result), 1.0);
}
