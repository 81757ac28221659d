// An engine entry file that numbers each register class from 0 in one space, as D3D12 allows:
// b0 and s0 land on Vulkan binding 0, t1 and u1 on binding 1. It compiles and passes spirv-val;
// the consumer (main.cpp) must find both collisions by reflection, which Vulkan forbids.
#include "entry/common/glint_entry_common.hlsli"
#include "glint/shadow_denoiser/glint_shadow_denoiser_constants.h"

ConstantBuffer<GLINT_ShadowDenoiserFilterConstants> EngineConstants : register(b0, space1);
SamplerState EngineLinearClamp : register(s0, space1);
Texture2D<float2> EngineMoments : register(t1, space1);
GLINT_IMAGE_FORMAT(rg32f) RWTexture2D<float2> EngineFiltered : register(u1, space1);

[numthreads(8, 8, 1)] void main(uint3 pixel : SV_DispatchThreadID)
{
    const float2 uv = (float2(pixel.xy) + 0.5) / float2(EngineConstants.inputSize);
    EngineFiltered[pixel.xy] = EngineMoments.SampleLevel(EngineLinearClamp, uv, 0.0);
}
