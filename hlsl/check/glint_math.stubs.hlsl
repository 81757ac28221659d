// Header check of glint_math.hlsli: calls each helper so that every body is instantiated.
RWStructuredBuffer<float> g_glint_check;

[numthreads(1, 1, 1)] void main()
{
    float x = g_glint_check[0];
    g_glint_check[1] = GLINT_FiniteOr(x, 0.0) + GLINT_Saturate(x) + GLINT_AlphaFromPerceptualRoughness(x) +
                       GLINT_PerceptualRoughnessFromAlpha(x);
}
