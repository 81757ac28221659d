// Stub callbacks for the header check of glint_shadow_denoiser_classify.hlsli.
RWStructuredBuffer<float4> g_glint_check;
ConstantBuffer<GLINT_ShadowDenoiserClassifyConstants> g_glint_check_constants;

uint GLINT_SHADOW_DENOISER_LoadMask(int2 tile)
{
    return asuint(g_glint_check[tile.x + tile.y].x);
}

float GLINT_SHADOW_DENOISER_LoadDepth(int2 pixel)
{
    return g_glint_check[pixel.x].y;
}

float GLINT_SHADOW_DENOISER_LoadPreviousDepth(int2 pixel)
{
    return g_glint_check[pixel.y].z;
}

float3 GLINT_SHADOW_DENOISER_LoadNormal(int2 pixel)
{
    return g_glint_check[pixel.x + 1].xyz;
}

float2 GLINT_SHADOW_DENOISER_LoadMotion(int2 pixel)
{
    return g_glint_check[pixel.y + 2].xy;
}

float3 GLINT_SHADOW_DENOISER_LoadMomentsHistory(int2 pixel)
{
    return g_glint_check[pixel.x + 3].xyz;
}

float GLINT_SHADOW_DENOISER_LoadShadowHistory(int2 pixel)
{
    return g_glint_check[pixel.y + 4].w;
}

uint GLINT_SHADOW_DENOISER_LoadPreviousMetadata(uint tileIndex)
{
    return asuint(g_glint_check[tileIndex + 5].x);
}

void GLINT_SHADOW_DENOISER_StoreMetadata(uint tileIndex, uint metadata)
{
    g_glint_check[tileIndex] = asfloat(uint4(metadata, 0, 0, 0));
}

void GLINT_SHADOW_DENOISER_StoreShadowVariance(int2 pixel, float2 value)
{
    g_glint_check[pixel.x] = float4(value, 0.0, 0.0);
}

void GLINT_SHADOW_DENOISER_StoreMoments(int2 pixel, float4 moments)
{
    g_glint_check[pixel.y] = moments;
}

float GLINT_SHADOW_DENOISER_LoadBlockerDistance(int2 pixel)
{
    return g_glint_check[pixel.x + 6].w;
}

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
