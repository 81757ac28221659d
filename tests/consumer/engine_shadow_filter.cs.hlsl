// An engine's own entry file for glint's shadow filter (one a-trous iteration): its own
// register bindings in its own space (numbered so that they map to distinct Vulkan bindings), its own names, and helpers whose plain names (PI,
// Luminance, LoadDepth) an engine already has; glint's prefixed symbols cannot collide with them.
#include "entry/common/glint_entry_common.hlsli"
#include "glint/shadow_denoiser/glint_shadow_denoiser_constants.h"
#include "glint/shadow_denoiser/glint_shadow_denoiser_filter.hlsli"

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

static const float PI = 3.14159265;
float Luminance(float3 c) { return dot(c, float3(0.2126, 0.7152, 0.0722)); }

ConstantBuffer<GLINT_ShadowDenoiserFilterConstants> EngineShadowConstants : register(b0, space3);
Texture2D<float2> EngineShadowMoments : register(t1, space3);
Texture2D<float> EngineSceneDepth : register(t2, space3);
Texture2D<float4> EngineSceneNormals : register(t3, space3);
GLINT_IMAGE_FORMAT(rg32f) RWTexture2D<float2> EngineShadowFiltered : register(u4, space3);

float LoadDepth(int2 pixel) { return EngineSceneDepth.Load(int3(pixel, 0)); }

float2 GLINT_SHADOW_DENOISER_LoadMeanVariance(int2 pixel) { return EngineShadowMoments.Load(int3(pixel, 0)); }
float GLINT_SHADOW_DENOISER_LoadDepth(int2 pixel) { return LoadDepth(pixel); }
float3 GLINT_SHADOW_DENOISER_LoadNormal(int2 pixel)
{
    return EngineSceneNormals.Load(int3(pixel, 0)).xyz * 2.0 - 1.0; // the engine's UNORM normals
}
// This engine has no blocker distances: unknown everywhere (and it passes penumbraScale -1: no estimate).
float GLINT_SHADOW_DENOISER_LoadBlockerDistance(int2 pixel) { return -1.0; }
void GLINT_SHADOW_DENOISER_StoreFiltered(int2 pixel, float2 meanVariance)
{
    EngineShadowFiltered[pixel] = meanVariance;
}

[numthreads(8, 8, 1)] void main(uint3 groupId : SV_GroupID, uint3 groupThreadId : SV_GroupThreadID,
                                uint groupIndex : SV_GroupIndex)
{
    GLINT_SHADOW_DENOISER_Filter(groupId.xy, groupThreadId.xy, groupIndex, EngineShadowConstants.inputSize,
                                 EngineShadowConstants.step, EngineShadowConstants.finalPass != 0,
                                 EngineShadowConstants.viewDepth, EngineShadowConstants.depthSigma,
                                 EngineShadowConstants.normalPower, -1.0);
}
