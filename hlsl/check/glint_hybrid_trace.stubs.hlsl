// Stub callbacks for the header check of glint_hybrid_trace.hlsli.
cbuffer g_glint_check_constants { GLINT_SssrConstants g_glint_sssr; GLINT_HybridConstants g_glint_hybrid; };
RWStructuredBuffer<float4> g_glint_check;
RWStructuredBuffer<uint> g_glint_check_words;

float GLINT_SSSR_LoadDepth(int2 texel, int mip) { return g_glint_check[texel.x + mip].x; }
float3 GLINT_SSSR_LoadNormal(int2 pixel) { return g_glint_check[pixel.y].xyz; }
float GLINT_SSSR_LoadRoughness(int2 pixel) { return g_glint_check[pixel.x].y; }
float2 GLINT_SSSR_LoadBlueNoise(int2 pixel) { return g_glint_check[pixel.x & 127].zw; }
uint GLINT_HYBRID_LoadRayTracedCount() { return g_glint_check_words[5]; }
uint GLINT_HYBRID_LoadRayTracedRay(uint index) { return g_glint_check_words[index + 8]; }
GLINT_HYBRID_Hit GLINT_HYBRID_TraceRay(float3 origin, float3 direction, float tMin, float tMax)
{
    GLINT_HYBRID_Hit hit;
    hit.t = dot(origin, direction) > tMin ? tMax : -1.0;
    hit.primitive = 1;
    hit.barycentrics = origin.xy;
    hit.instance = 2;
    return hit;
}
void GLINT_HYBRID_StoreHit(uint index, uint4 record) { g_glint_check_words[index + 64] = record.x ^ record.y ^ record.z ^ record.w; }

[numthreads(64, 1, 1)] void main(uint3 groupId : SV_GroupID, uint groupIndex : SV_GroupIndex)
{
    GLINT_HYBRID_TraceRays(g_glint_sssr, g_glint_hybrid, groupId.x * 64 + groupIndex);
}
