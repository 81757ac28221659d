// Stub callbacks for the header check of glint_depth_pyramid.hlsli.
RWStructuredBuffer<float2> g_glint_check;

float4 GLINT_DEPTH_PYRAMID_GatherDepth(int2 pixel)
{
    return float4(g_glint_check[pixel.x], g_glint_check[pixel.y]);
}

float2 GLINT_DEPTH_PYRAMID_Reduce(float2 a, float2 b)
{
    return float2(min(a.x, b.x), max(a.y, b.y));
}

void GLINT_DEPTH_PYRAMID_StoreLevel(int2 texel, uint level, float2 value)
{
    g_glint_check[texel.x + level] = value;
}

float2 GLINT_DEPTH_PYRAMID_LoadLevelCoherent(int2 texel, uint level)
{
    return g_glint_check[texel.y + level];
}

uint GLINT_DEPTH_PYRAMID_IncrementCounter()
{
    return 0;
}

void GLINT_DEPTH_PYRAMID_ResetCounter()
{
}

[numthreads(256, 1, 1)] void main(uint3 groupId : SV_GroupID, uint groupIndex : SV_GroupIndex)
{
    GLINT_DEPTH_PYRAMID_Build(groupId.xy, groupIndex, uint2(7, 3), uint2(64, 64), 7, 1, 1.0, true);
}
