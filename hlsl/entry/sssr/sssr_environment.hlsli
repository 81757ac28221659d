// The harness's environment callback, shared by the SSSR entries: a lat-long map
// (docs/capture-format.md, "Environment maps") with a box-filtered mip chain, sampled with
// the roughness-aware LOD the header computes. Engines with a GGX-prefiltered cube map
// define GLINT_SSSR_SampleEnvironment as a cube lookup instead.
#ifndef SSSR_ENTRY_ENVIRONMENT_HLSLI
#define SSSR_ENTRY_ENVIRONMENT_HLSLI

float3 SSSR_EntrySampleLatLong(Texture2D<float4> map, SamplerState linearClamp, float3 direction, float lod)
{
    const float pi = 3.14159265358979;
    float3 d = normalize(direction);
    float longitude = atan2(d.x, d.z);
    float latitude = asin(clamp(d.y, -1.0, 1.0));
    float2 uv = float2(0.5 - longitude / (2.0 * pi), 0.5 - latitude / pi);
    return map.SampleLevel(linearClamp, uv, lod).rgb;
}

#endif // SSSR_ENTRY_ENVIRONMENT_HLSLI
