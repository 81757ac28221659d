// Test harness for glint/common/glint_ggx.hlsli (tests/sssr/vndf_test.cpp): one thread per
// input record evaluates the library's GGX functions and writes every result, so that the CPU
// can check them against independent double-precision references (chi-square of the sampled
// directions, finiteness in hard cases, the tangent frame and the bent normal).
#include "entry/common/glint_entry_common.hlsli"
#include "glint/common/glint_ggx.hlsli"

struct TestGgxConstants {
    uint sampleCount;
    uint3 padding;
};

struct TestGgxInput {
    float4 viewAlpha; // V (local frame, or world for the bend), alpha
    float4 uBias;     // u.x, u.y, bias, unused
    float4 normal;    // n for GLINT_GGX_BendNormalTowardView and GLINT_GGX_TangentFrame
};

struct TestGgxOutput {
    float4 reflection; // L (local) from GLINT_GGX_SampleReflection, ReflectionPdf(V.z, H.z)
    float4 microfacet; // H (local) from GLINT_GGX_SampleVndf, SmithG1(V.z)
    float4 bent;       // BendNormalTowardView(n, V), D(H.z)
    float4 tangent;    // TangentFrame(n): t, then ToWorld(ToLocal(V)).x
    float4 bitangent;  // TangentFrame(n): b, then ToLocal(V).z (= dot(V, n))
};

GLINT_BINDING(0, 0) ConstantBuffer<TestGgxConstants> g_glint_constants;
GLINT_BINDING(1, 0) StructuredBuffer<TestGgxInput> g_glint_ggx_inputs;
GLINT_BINDING(2, 0) RWStructuredBuffer<TestGgxOutput> g_glint_ggx_outputs;

[numthreads(64, 1, 1)] void main(uint3 id : SV_DispatchThreadID)
{
    if (id.x >= g_glint_constants.sampleCount) return;
    TestGgxInput input = g_glint_ggx_inputs[id.x];
    float3 V = input.viewAlpha.xyz;
    float alpha = input.viewAlpha.w;
    float2 u = input.uBias.xy;
    float bias = input.uBias.z;
    float3 n = input.normal.xyz;

    float3 H = GLINT_GGX_SampleVndf(V, alpha, u, bias);
    float3 L = GLINT_GGX_SampleReflection(V, alpha, u, bias);
    float3 t, b;
    GLINT_GGX_TangentFrame(n, t, b);
    float3 local = GLINT_GGX_ToLocal(V, t, b, n);

    TestGgxOutput output;
    output.reflection = float4(L, GLINT_GGX_ReflectionPdf(V.z, H.z, alpha));
    output.microfacet = float4(H, GLINT_GGX_SmithG1(V.z, alpha));
    output.bent = float4(GLINT_GGX_BendNormalTowardView(n, V), GLINT_GGX_D(H.z, alpha));
    output.tangent = float4(t, GLINT_GGX_ToWorld(local, t, b, n).x);
    output.bitangent = float4(b, local.z);
    g_glint_ggx_outputs[id.x] = output;
}
