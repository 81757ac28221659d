// Header check of glint_reflections_denoiser_common.hlsli: its callbacks are the shared stubs in
// check/stubs/reflections_denoiser.stubs.hlsli (each defined once for every check).
#include "check/stubs/reflections_denoiser.stubs.hlsli"

// An entry point, so the check compiles the header's functions (a module without one is an
// error for DXC and a warning glslang's check treats as one).
[numthreads(8, 8, 1)] void main(uint3 id : SV_DispatchThreadID)
{
    int2 pixel = int2(id.xy);
    float3 n = GLINT_RD_DecodeNormal(GLINT_RD_EncodeNormal(normalize(GLINT_RD_LoadNormal(pixel) + 1e-3)));
    float weight = GLINT_RD_Luma(n) + GLINT_RD_LoadRoughness(pixel) + float(GLINT_RD_LoadTile(id.y));
    g_glint_check[id.x] = float4(GLINT_RD_SanitizeRadiance(n * GLINT_RD_LoadDepth(pixel)), weight);
}
