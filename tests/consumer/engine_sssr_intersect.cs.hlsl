// An engine's own entry file for glint's SSSR intersection: register bindings in its own space,
// its own resource names, its own environment lookup (a cube map, where glint's harness uses a
// lat-long map), and the constants in a cbuffer (the form both DXC and glslang accept when the
// struct is passed to GLINT_SSSR_Intersect).
#include "entry/common/glint_entry_common.hlsli"
#include "glint/sssr/glint_sssr_constants.h"
#include "glint/sssr/glint_sssr_intersect.hlsli"

// Written against glint 0.9: a release that may change the callback API stops the build here
// (docs/integration.md, "Versions" and "Migration").
#if GLINT_VERSION_MAJOR != 0 || GLINT_VERSION_MINOR != 9
#error "engine entry written against glint 0.9.x"
#endif
// The headers' version is the installed package's (tests/consumer/CMakeLists.txt passes it).
#if GLINT_VERSION_MAJOR != GLINT_CONSUMER_PACKAGE_MAJOR || GLINT_VERSION_MINOR != GLINT_CONSUMER_PACKAGE_MINOR || \
    GLINT_VERSION_PATCH != GLINT_CONSUMER_PACKAGE_PATCH
#error "glint_version.h and the CMake package disagree on glint's version"
#endif

cbuffer EngineReflectionConstants : register(b0, space5) { GLINT_SssrConstants EngineSssr; };
Texture2D<float> EngineDepth : register(t1, space5);
Texture2D<float> EngineHiZ : register(t2, space5);
Texture2D<float4> EngineNormals : register(t3, space5);
Texture2D<float> EngineAlpha : register(t4, space5);
Texture2D<float2> EngineBlueNoise : register(t5, space5);
Texture2D<float4> EngineSceneColor : register(t6, space5);
Texture2D<float2> EngineVelocity : register(t7, space5);
TextureCube<float4> EngineSkyCube : register(t8, space5);
SamplerState EngineLinearClamp : register(s9, space5);
StructuredBuffer<uint> EngineRayCounters : register(t10, space5);
StructuredBuffer<uint> EngineRayList : register(t11, space5);
GLINT_IMAGE_FORMAT(rgba16f) RWTexture2D<float4> EngineReflection : register(u12, space5);
GLINT_IMAGE_FORMAT(r16f) RWTexture2D<float> EngineReflectionConfidence : register(u13, space5);

float GLINT_SSSR_LoadDepth(int2 texel, int mip)
{
    // Level 0 is the depth itself; the engine's Hi-Z holds levels 1 and up.
    return mip == 0 ? EngineDepth.Load(int3(texel, 0)) : EngineHiZ.Load(int3(texel, mip));
}
float3 GLINT_SSSR_LoadNormal(int2 pixel) { return EngineNormals.Load(int3(pixel, 0)).xyz; } // world space
float GLINT_SSSR_LoadRoughness(int2 pixel) { return EngineAlpha.Load(int3(pixel, 0)); }      // GGX alpha
float2 GLINT_SSSR_LoadBlueNoise(int2 pixel) { return EngineBlueNoise.Load(int3(pixel & 127, 0)); }
float3 GLINT_SSSR_LoadColor(int2 pixel) { return EngineSceneColor.Load(int3(pixel, 0)).rgb; }
float3 GLINT_SSSR_SampleColor(float2 uv) { return EngineSceneColor.SampleLevel(EngineLinearClamp, uv, 0).rgb; }
float2 GLINT_SSSR_LoadMotion(int2 pixel) { return EngineVelocity.Load(int3(pixel, 0)); }
float3 GLINT_SSSR_SampleEnvironment(float3 direction, float lod)
{
    return EngineSkyCube.SampleLevel(EngineLinearClamp, direction, lod).rgb;
}
uint GLINT_SSSR_LoadRayCount() { return EngineRayCounters[1]; }
uint GLINT_SSSR_LoadRay(uint index) { return EngineRayList[index]; }
void GLINT_SSSR_StoreRadiance(int2 pixel, float4 value) { EngineReflection[pixel] = float4(value.rgb, min(value.a, 65504.0)); }
void GLINT_SSSR_StoreConfidence(int2 pixel, float confidence) { EngineReflectionConfidence[pixel] = confidence; }

[numthreads(64, 1, 1)] void main(uint3 groupId : SV_GroupID, uint groupIndex : SV_GroupIndex)
{
    GLINT_SSSR_Intersect(EngineSssr, groupIndex,
                         (groupId.y * GLINT_SSSR_GROUPS_PER_ROW + groupId.x) * GLINT_SSSR_RAYS_PER_GROUP + groupIndex);
}
