// Directions drawn in proportion to the environment map as SceneEnvironment reads it, and the
// density of any direction under that draw. The including entry declares Texture2D<float4>
// g_scene_environment and StructuredBuffer<SceneEnvironmentSample> g_scene_environment_sampling
// (harness/scene/scene_environment.cpp, environmentSamplingTable), and includes scene_trace
// first.
// The lookup filters bilinearly, and a bilinear image is a sum of tents (one per texel, height
// the texel's value, one texel wide on each side). So the draw picks a texel with its table
// probability and places the direction by that texel's tent: the density in the map's texel
// coordinates is then the bilinear interpolation of the probabilities, times W * H. Over solid
// angle it is divided by 2 pi^2 cos(latitude). Tents past a pole are folded back into the map,
// which matches the lookup's clamping there; longitude wraps.
#ifndef GLINT_SCENE_ENVIRONMENT_SAMPLING_HLSLI
#define GLINT_SCENE_ENVIRONMENT_SAMPLING_HLSLI

float SceneEnvironmentProbability(int2 texel, int2 size)
{
    texel.x = (texel.x % size.x + size.x) % size.x;
    texel.y = clamp(texel.y, 0, size.y - 1);
    return g_scene_environment_sampling[texel.y * size.x + texel.x].probability;
}

// Density (per steradian) with which SceneSampleEnvironment draws `dir` (unit).
float SceneEnvironmentPdf(float3 dir)
{
    uint width, height;
    g_scene_environment.GetDimensions(width, height);
    int2 size = int2(width, height);
    float2 uv = float2(0.5 - atan2(dir.x, dir.z) / (2.0 * SCENE_PI), 0.5 - asin(clamp(dir.y, -1.0, 1.0)) / SCENE_PI);
    float2 texel = uv * float2(size) - 0.5;
    float2 base = floor(texel);
    float2 f = texel - base;
    int2 i = int2(base);
    float a = lerp(SceneEnvironmentProbability(i, size), SceneEnvironmentProbability(i + int2(1, 0), size), f.x);
    float b = lerp(SceneEnvironmentProbability(i + int2(0, 1), size), SceneEnvironmentProbability(i + int2(1, 1), size), f.x);
    float cosLatitude = sqrt(saturate(1.0 - dir.y * dir.y));
    return lerp(a, b, f.y) * float(width * height) / (2.0 * SCENE_PI * SCENE_PI * max(cosLatitude, 1e-6));
}

// Offset in (-1, 1) with the tent density 1 - |t|.
float SceneTentOffset(float u)
{
    return u < 0.5 ? sqrt(2.0 * u) - 1.0 : 1.0 - sqrt(2.0 - 2.0 * u);
}

// A direction drawn from the table with four uniform numbers in [0, 1); its density is
// SceneEnvironmentPdf of it.
float3 SceneSampleEnvironment(float4 u)
{
    uint width, height;
    g_scene_environment.GetDimensions(width, height);
    uint count = width * height;
    uint slot = min(uint(u.x * float(count)), count - 1u);
    SceneEnvironmentSample entry = g_scene_environment_sampling[slot];
    uint texel = u.y < entry.keep ? slot : entry.alias;
    float2 t = float2(texel % width, texel / width) + float2(SceneTentOffset(u.z), SceneTentOffset(u.w));
    float h = float(height);
    t.y = t.y < -0.5 ? -1.0 - t.y : (t.y > h - 0.5 ? 2.0 * h - 1.0 - t.y : t.y);
    float2 uv = (t + 0.5) / float2(width, height);
    float longitude = 2.0 * SCENE_PI * (0.5 - uv.x);
    float latitude = SCENE_PI * (0.5 - uv.y);
    float cosLatitude = cos(latitude);
    return float3(cosLatitude * sin(longitude), sin(latitude), cosLatitude * cos(longitude));
}

#endif // GLINT_SCENE_ENVIRONMENT_SAMPLING_HLSLI
