// Shared math for every glint pass: finite-value guards and roughness conversions.
// Integration: include from any glint header; defines no resources and needs no callbacks.
// No entry function, constants or dispatch of its own.
#ifndef GLINT_MATH_HLSLI
#define GLINT_MATH_HLSLI

// True for a finite float. Written with bit tests rather than isnan/isinf because fast-math
// compilers may fold those away, and a NaN must never slip past the guard.
bool GLINT_IsFinite(float x)
{
    return (asuint(x) & 0x7F800000u) != 0x7F800000u;
}

// x when finite, otherwise fallback: the one way a pass turns non-finite input into a
// defined value.
float GLINT_FiniteOr(float x, float fallback)
{
    return GLINT_IsFinite(x) ? x : fallback;
}

float GLINT_Saturate(float x)
{
    return clamp(x, 0.0, 1.0);
}

// GGX alpha from perceptual (artist) roughness: alpha = r^2 (docs/conventions.md §4).
float GLINT_AlphaFromPerceptualRoughness(float perceptualRoughness)
{
    return perceptualRoughness * perceptualRoughness;
}

float GLINT_PerceptualRoughnessFromAlpha(float alpha)
{
    return sqrt(max(alpha, 0.0));
}

#endif // GLINT_MATH_HLSLI
