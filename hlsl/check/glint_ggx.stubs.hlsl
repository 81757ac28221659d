// Header check of glint_ggx.hlsli: it needs no callbacks, but calls each function so that
// every body is instantiated and validated by both compilers.
RWStructuredBuffer<float4> g_glint_check;

[numthreads(1, 1, 1)] void main()
{
    float4 x = g_glint_check[0];
    float3 t, b;
    GLINT_GGX_TangentFrame(normalize(x.xyz), t, b);
    float3 local = GLINT_GGX_ToLocal(x.xyz, t, b, normalize(x.xyz));
    float3 H = GLINT_GGX_SampleVndf(local, x.w, x.xy, x.z);
    float3 L = GLINT_GGX_SampleReflection(local, x.w, x.xy, x.z);
    g_glint_check[1] = float4(GLINT_GGX_ToWorld(L, t, b, x.xyz) + GLINT_GGX_BendNormalTowardView(x.xyz, H),
                              GLINT_GGX_D(H.z, x.w) + GLINT_GGX_SmithG1(x.z, x.w) +
                                  GLINT_GGX_ReflectionPdf(x.z, H.z, x.w));
}
