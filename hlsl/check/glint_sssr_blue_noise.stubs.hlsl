// Stub callbacks for the header check of glint_sssr_blue_noise.hlsli.
cbuffer g_glint_check_constants { GLINT_SssrConstants g_glint_sssr; };
RWStructuredBuffer<float2> g_glint_check;

float2 GLINT_SSSR_LoadBlueNoiseSource(int2 texel) { return g_glint_check[texel.x * 128 + texel.y]; }
void GLINT_SSSR_StoreBlueNoise(int2 texel, float2 sample) { g_glint_check[texel.y * 128 + texel.x] = sample; }

[numthreads(8, 8, 1)] void main(uint3 dispatchId : SV_DispatchThreadID)
{
    GLINT_SSSR_AnimateBlueNoise(g_glint_sssr, dispatchId.xy);
}
