// Shading exactly as the colour buffer does it, used for primary hits and for hits of
// reflection rays alike (docs/scenes.md): emission plus every light's direct contribution,
// Lambert + GGX specular, times converged visibility; misses see the environment map. The
// including entry declares Texture2D<float4> g_scene_environment (lat-long, rgba32f) and
// includes scene_trace, scene_surface and scene_light first.
#ifndef GLINT_SCENE_SHADING_HLSLI
#define GLINT_SCENE_SHADING_HLSLI

float4 SceneEnvironmentTexel(int2 texel, int2 size)
{
    texel.x = (texel.x % size.x + size.x) % size.x; // longitude wraps
    texel.y = clamp(texel.y, 0, size.y - 1);        // latitude clamps at the poles
    return g_scene_environment.Load(int3(texel, 0));
}

// Lat-long lookup with bilinear filtering: u = 0.5 - longitude / 2pi with longitude =
// atan2(x, z), v = 0.5 - latitude / pi, texel centres at (i + 0.5) / size.
float3 SceneEnvironment(float3 dir)
{
    uint width, height;
    g_scene_environment.GetDimensions(width, height);
    float2 uv = float2(0.5 - atan2(dir.x, dir.z) / (2.0 * SCENE_PI), 0.5 - asin(clamp(dir.y, -1.0, 1.0)) / SCENE_PI);
    float2 texel = uv * float2(width, height) - 0.5;
    float2 base = floor(texel);
    float2 f = texel - base;
    int2 i = int2(base);
    int2 size = int2(width, height);
    float4 a = lerp(SceneEnvironmentTexel(i, size), SceneEnvironmentTexel(i + int2(1, 0), size), f.x);
    float4 b = lerp(SceneEnvironmentTexel(i + int2(0, 1), size), SceneEnvironmentTexel(i + int2(1, 1), size), f.x);
    return lerp(a, b, f.y).rgb;
}

// Lambert + GGX (height-correlated Smith, Schlick Fresnel) for a light from direction l.
float3 SceneBrdfCos(SceneSurface s, float3 v, float3 l, float alphaFloor)
{
    float nl = dot(s.normal, l);
    if (nl <= 0.0) return 0.0;
    float nv = max(dot(s.normal, v), 1e-4);
    float3 h = normalize(v + l);
    float nh = saturate(dot(s.normal, h));
    float vh = saturate(dot(v, h));
    // Small lights widen the highlight (and keep mirrors finite): alpha >= the light's size.
    float alpha = max(s.perceptualRoughness * s.perceptualRoughness, alphaFloor);
    float a2 = alpha * alpha;
    float denom = nh * nh * (a2 - 1.0) + 1.0;
    float d = a2 / (SCENE_PI * denom * denom);
    float vis = 0.5 / (nl * sqrt(nv * nv * (1.0 - a2) + a2) + nv * sqrt(nl * nl * (1.0 - a2) + a2));
    float3 f0 = lerp(float3(0.04, 0.04, 0.04), s.baseColor, s.metallic);
    float3 fresnel = f0 + (1.0 - f0) * pow(1.0 - vh, 5.0);
    float3 diffuse = s.baseColor * ((1.0 - s.metallic) / SCENE_PI);
    return (diffuse + d * vis * fresnel) * nl;
}

// Radiance leaving surface s toward v (unit, pointing away from the surface), with the
// visibility of every light from `strata` of its g_scene.shadowSamples cone samples: all of
// them, or one picked by `pick` (uniform in [0, 1); light i turns it by i golden-ratio steps),
// whose mean over the pick is the all-strata value.
// The stratification's random numbers depend only on the point, so the same point shades the
// same way whether a camera ray or a reflection ray found it.
float3 SceneShadeStrata(SceneSurface s, float3 v, bool oneStratum, float pick)
{
    float3 radiance = s.emissive;
    uint rng = SceneHash(asuint(s.position.x) ^ SceneHash(asuint(s.position.y) ^ SceneHash(asuint(s.position.z))));
    uint total = max(g_scene.shadowSamples, 1u);
    for (uint i = 0; i < g_scene.lightCount; ++i) {
        SceneLightCone c = SceneLightConeAt(i, s.position);
        float3 f = SceneBrdfCos(s, v, c.axis, max(0.5 * c.sinHalf, 1e-3));
        if (all(f <= 0.0)) continue;
        uint first = oneStratum ? min(uint(frac(pick + 0.618034 * float(i)) * float(total)), total - 1u) : 0u;
        uint count = oneStratum ? 1u : total;
        float visible = SceneVisibilitySum(s.position, s.normal, c, first, count, total, rng);
        radiance += f * c.irradiance * (visible / float(count));
    }
    return radiance;
}

// The colour buffer's shading: every stratum of every light.
float3 SceneShade(SceneSurface s, float3 v)
{
    return SceneShadeStrata(s, v, false, 0.0);
}

// Radiance arriving at `origin` from direction `dir`.
float3 SceneRadianceAlong(float3 origin, float3 dir)
{
    SceneHit hit = SceneTrace(origin, dir, 3.0e38, false);
    if (hit.t < 0.0) return SceneEnvironment(dir);
    SceneSurface s = SceneSurfaceAt(hit, origin, dir);
    return SceneShade(s, -dir);
}

// Rec. 709 luminance, as the error metrics weigh colour (replay_error.h).
float SceneLuminance(float3 c)
{
    return dot(c, float3(0.2126, 0.7152, 0.0722));
}

// Replaces non-finite values so that nothing non-finite leaves a pass.
float3 SceneFinite(float3 v)
{
    return float3(isfinite(v.x) ? v.x : 0.0, isfinite(v.y) ? v.y : 0.0, isfinite(v.z) ? v.z : 0.0);
}

#endif // GLINT_SCENE_SHADING_HLSLI
