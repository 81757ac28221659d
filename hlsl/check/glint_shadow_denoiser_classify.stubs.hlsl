// Header check of glint_shadow_denoiser_classify.hlsli: its callbacks are the shared stubs in
// check/stubs/shadow_denoiser.stubs.hlsli (each defined once for every check).
#include "check/stubs/shadow_denoiser.stubs.hlsli"

ConstantBuffer<GLINT_ShadowDenoiserClassifyConstants> g_glint_check_constants;

[numthreads(8, 8, GLINT_SHADOW_DENOISER_CLASSIFY_BLOCKS)] void main(uint3 groupId : SV_GroupID,
                                                                   uint3 groupThreadId : SV_GroupThreadID)
{
    // glslang passes no ConstantBuffer to a function: copy it into the plain struct.
    GLINT_ShadowDenoiserClassifyParams c;
    c.inputSize = g_glint_check_constants.inputSize;
    c.maskTiles = g_glint_check_constants.maskTiles;
    c.reproject = float4x4(g_glint_check_constants.reproject[0], g_glint_check_constants.reproject[1], g_glint_check_constants.reproject[2], g_glint_check_constants.reproject[3]);
    c.inverseViewProj = float4x4(g_glint_check_constants.inverseViewProj[0], g_glint_check_constants.inverseViewProj[1], g_glint_check_constants.inverseViewProj[2],
                                 g_glint_check_constants.inverseViewProj[3]);
    c.eyePosition = g_glint_check_constants.eyePosition;
    c.viewDepth = g_glint_check_constants.viewDepth;
    c.ndcYSign = g_glint_check_constants.ndcYSign;
    c.flags = g_glint_check_constants.flags;
    c.storedVarianceScale = g_glint_check_constants.storedVarianceScale;
    c.penumbraScale = g_glint_check_constants.penumbraScale;
    GLINT_SHADOW_DENOISER_Classify(groupId.xy, groupThreadId, c);
}
