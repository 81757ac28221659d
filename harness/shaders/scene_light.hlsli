// Lights as cones seen from a point, cone sampling and visibility. The including entry
// declares StructuredBuffer<SceneLight> g_scene_lights.
#ifndef GLINT_SCENE_LIGHT_HLSLI
#define GLINT_SCENE_LIGHT_HLSLI

struct SceneLightCone {
    float3 axis;       // unit direction to the light's centre
    float cosHalf;     // cosine of the cone's half-angle
    float sinHalf;
    float3 irradiance; // at normal incidence, unshadowed
    float maxT;        // shadow rays stop before the light
};

SceneLightCone SceneLightConeAt(uint lightIndex, float3 position)
{
    SceneLight l = g_scene_lights[lightIndex];
    SceneLightCone c;
    if (l.kind == GLINT_SCENE_LIGHT_DIRECTIONAL) {
        c.axis = l.where;
        c.sinHalf = sin(l.size);
        c.cosHalf = cos(l.size);
        c.irradiance = l.radiance;
        c.maxT = 3.0e38;
    } else {
        float3 toLight = l.where - position;
        float d2 = max(dot(toLight, toLight), 1e-12);
        float d = sqrt(d2);
        c.axis = toLight / d;
        c.sinHalf = min(l.size / d, 1.0);
        c.cosHalf = sqrt(max(1.0 - c.sinHalf * c.sinHalf, 0.0));
        c.irradiance = l.radiance / d2;
        c.maxT = max(d - l.size, 0.0) * 0.999;
    }
    return c;
}

// Uniform direction inside the cone (solid-angle uniform).
float3 SceneSampleCone(SceneLightCone c, float u1, float u2)
{
    float cosTheta = lerp(1.0, c.cosHalf, u1);
    float sinTheta = sqrt(max(1.0 - cosTheta * cosTheta, 0.0));
    float phi = 2.0 * SCENE_PI * u2;
    float3 up = abs(c.axis.z) < 0.999 ? float3(0.0, 0.0, 1.0) : float3(1.0, 0.0, 0.0);
    float3 t = normalize(cross(up, c.axis));
    float3 b = cross(c.axis, t);
    return normalize(t * (sinTheta * cos(phi)) + b * (sinTheta * sin(phi)) + c.axis * cosTheta);
}

// 1 when the cone direction reaches the light. Directions below the surface are blocked by
// the surface itself.
float SceneVisibilityAlong(float3 position, float3 normal, float3 dir, float maxT)
{
    if (dot(normal, dir) <= 0.0) return 0.0;
    SceneHit h = SceneTrace(SceneOffsetOrigin(position, normal), dir, maxT, true);
    return h.t > 0.0 ? 0.0 : 1.0;
}

// The same test, also giving the distance to the blocker along `dir`: 0 when the direction
// reaches the light; -1 when it lies below the surface (no blocker: the caller knows the
// surface's curvature, which sets the terminator's penumbra).
float SceneVisibilityAndBlocker(float3 position, float3 normal, float3 dir, float maxT, out float blocker)
{
    blocker = 0.0;
    if (dot(normal, dir) <= 0.0) {
        blocker = -1.0;
        return 0.0;
    }
    SceneHit h = SceneTrace(SceneOffsetOrigin(position, normal), dir, maxT, false); // the closest blocker
    if (h.t > 0.0) {
        blocker = h.t;
        return 0.0;
    }
    return 1.0;
}

// Visible count of cone samples [start, start + count) of a `total`-sample stratification
// (stratified in cos(theta), golden-ratio in phi). The first two random numbers place the
// whole stratification, so every chunk of one pixel must start from the same rng state.
float SceneVisibilitySum(float3 position, float3 normal, SceneLightCone c, uint start, uint count, uint total,
                         inout uint rng)
{
    float visible = 0.0;
    float offset = SceneRandom(rng);
    float jitter = SceneRandom(rng);
    for (uint i = start; i < start + count; ++i) {
        float u1 = (float(i) + jitter) / float(max(total, 1u));
        float u2 = frac(offset + 0.618034 * float(i));
        visible += SceneVisibilityAlong(position, normal, SceneSampleCone(c, u1, u2), c.maxT);
    }
    return visible;
}

// One cone sample placed exactly as SceneVisibilitySum(.., 0, 1, 1, rng) places it, with the
// distance to its blocker (SceneVisibilityAndBlocker).
float SceneVisibilityOneSample(float3 position, float3 normal, SceneLightCone c, inout uint rng, out float blocker)
{
    float offset = SceneRandom(rng);
    float jitter = SceneRandom(rng);
    return SceneVisibilityAndBlocker(position, normal, SceneSampleCone(c, jitter, frac(offset)), c.maxT, blocker);
}

#endif // GLINT_SCENE_LIGHT_HLSLI
