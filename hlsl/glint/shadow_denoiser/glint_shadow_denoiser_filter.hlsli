// glint shadow denoiser, passes 4-6 (filter): one edge-avoiding a-trous iteration over
// (mean, variance) with depth and normal edge stops; run three times with step 1, 2 and 4
// (docs/shadow_denoiser.md).
//
// Integration: define these callbacks before or after including this header.
//
//   float2 GLINT_SHADOW_DENOISER_LoadMeanVariance(int2 pixel);
//       (mean, variance) of the previous iteration at an in-image pixel. Any value is
//       allowed: non-finite ones become 0, the mean is clamped to [0, 1], the variance to >= 0.
//   float  GLINT_SHADOW_DENOISER_LoadDepth(int2 pixel);
//       Device depth of an in-image pixel. Receivers have finite depth strictly inside
//       (1e-6, 1 - 1e-6); anything else (sky, NaN) is a non-receiver.
//   float3 GLINT_SHADOW_DENOISER_LoadNormal(int2 pixel);
//       Unpacked world-space normal (need not be unit length). Non-finite or zero normals
//       make the pixel accept no neighbour (only its own sample).
//   void   GLINT_SHADOW_DENOISER_StoreFiltered(int2 pixel, float2 meanVariance);
//       Writes the result; the final pass writes (remapped mean, variance).
//
// With GLINT_SHADOW_DENOISER_TILE_SKIP=1 (tile metadata from the classification pass):
//   uint   GLINT_SHADOW_DENOISER_LoadTileMetadata(uint tileIndex);   one word per 8x8 tile
//   void   GLINT_SHADOW_DENOISER_CountFilteredTile();                called once per filtered tile
// A CLEAR tile skips the filter: passes with step 1 and the final pass write the constant
// (1 for receivers of a LIGHT tile, else 0; variance 0), the step-2 pass writes nothing (its
// output image already holds the constant from classification).
//
// Weights, for a receiver c and a receiver neighbour q at step * (i, j), i, j in {-1, 0, 1}:
//   w = k(i) k(j) exp(-|s_c - s_q| / sigma) exp(-|z_c - z_q| / (depthSigma z_c)) max(0, N_c . N_q)^normalPower
// with k(0) = 1, k(1) = 2/3, sigma = sqrt(var_f + 1e-9), var_f the 3x3 Gaussian (1/4 centre,
// 1/8 edges, 1/16 corners) of the variance around c, z the view depth A / (B + C d). The
// centre weighs 1. mean = sum w s / sum w, variance = sum w^2 var_q / (sum w)^2.
// Final pass: mean^max(1.2 - variance, 1). Non-receivers write (0, 0).
//
// Dispatch: [numthreads(8, 8, 1)], ceil(W / 8) x ceil(H / 8) x 1 groups; groupshared tile of
// 16 x 16 pixels (the 8 x 8 tile plus a 4-pixel apron), coordinates clamped to the image.
#ifndef GLINT_SHADOW_DENOISER_FILTER_HLSLI
#define GLINT_SHADOW_DENOISER_FILTER_HLSLI

#include "glint/common/glint_math.hlsli"
#include "glint/shadow_denoiser/glint_shadow_denoiser_constants.h"

float2 GLINT_SHADOW_DENOISER_LoadMeanVariance(int2 pixel);
float GLINT_SHADOW_DENOISER_LoadDepth(int2 pixel);
float3 GLINT_SHADOW_DENOISER_LoadNormal(int2 pixel);
void GLINT_SHADOW_DENOISER_StoreFiltered(int2 pixel, float2 meanVariance);
#if GLINT_SHADOW_DENOISER_TILE_SKIP
uint GLINT_SHADOW_DENOISER_LoadTileMetadata(uint tileIndex);
void GLINT_SHADOW_DENOISER_CountFilteredTile();
#endif

#define GLINT_SHADOW_DENOISER_FILTER_SPAN 16

// (mean, variance) and (view depth or -1 for non-receivers, normal) of the 16 x 16 span.
groupshared float2 g_glint_shadow_denoiser_filter_values[GLINT_SHADOW_DENOISER_FILTER_SPAN * GLINT_SHADOW_DENOISER_FILTER_SPAN];
groupshared float4 g_glint_shadow_denoiser_filter_geometry[GLINT_SHADOW_DENOISER_FILTER_SPAN * GLINT_SHADOW_DENOISER_FILTER_SPAN];

float2 GLINT_SHADOW_DENOISER_SanitizeMeanVariance(float2 value)
{
    float mean = GLINT_IsFinite(value.x) ? clamp(value.x, 0.0, 1.0) : 0.0;
    float variance = GLINT_IsFinite(value.y) ? max(value.y, 0.0) : 0.0;
    return float2(mean, variance);
}

// View depth of a receiver, or -1.
float GLINT_SHADOW_DENOISER_ReceiverViewDepth(float depth, float4 viewDepth)
{
    if (!GLINT_IsFinite(depth) || !(depth > 1e-6 && depth < 1.0 - 1e-6))
        return -1.0;
    float z = viewDepth.x / (viewDepth.y + viewDepth.z * depth);
    return GLINT_IsFinite(z) && z > 0.0 ? z : -1.0;
}

float3 GLINT_SHADOW_DENOISER_SanitizeNormal(float3 n)
{
    if (!GLINT_IsFinite(n.x) || !GLINT_IsFinite(n.y) || !GLINT_IsFinite(n.z))
        return float3(0.0, 0.0, 0.0);
    float lengthSquared = dot(n, n);
    if (!(lengthSquared > 1e-12) || !GLINT_IsFinite(lengthSquared))
        return float3(0.0, 0.0, 0.0);
    return n * rsqrt(lengthSquared);
}

uint GLINT_SHADOW_DENOISER_FilterSlot(int2 local)
{
    return uint(local.y) * GLINT_SHADOW_DENOISER_FILTER_SPAN + uint(local.x);
}

float GLINT_SHADOW_DENOISER_KernelWeight(int offset)
{
    return offset == 0 ? 1.0 : 2.0 / 3.0;
}

void GLINT_SHADOW_DENOISER_Filter(uint2 groupId, uint2 groupThreadId, uint groupIndex, uint2 inputSize, uint step,
                                  bool finalPass, float4 viewDepth, float depthSigma, float normalPower)
{
#if GLINT_SHADOW_DENOISER_TILE_SKIP
    // Uniform across the group, so returning here keeps the barrier below legal.
    uint tilesX = (inputSize.x + GLINT_SHADOW_DENOISER_FILTER_TILE - 1) / GLINT_SHADOW_DENOISER_FILTER_TILE;
    uint metadata = GLINT_SHADOW_DENOISER_LoadTileMetadata(groupId.y * tilesX + groupId.x);
    if ((metadata & GLINT_SHADOW_DENOISER_TILE_CLEAR) != 0u)
    {
        int2 clearPixel = int2(groupId * GLINT_SHADOW_DENOISER_FILTER_TILE + groupThreadId);
        if (step == 2u || any(uint2(clearPixel) >= inputSize))
            return;
        bool lit = (metadata & GLINT_SHADOW_DENOISER_TILE_LIGHT) != 0u &&
                   GLINT_SHADOW_DENOISER_ReceiverViewDepth(GLINT_SHADOW_DENOISER_LoadDepth(clearPixel), viewDepth) > 0.0;
        GLINT_SHADOW_DENOISER_StoreFiltered(clearPixel, float2(lit ? 1.0 : 0.0, 0.0));
        return;
    }
    if (groupIndex == 0)
        GLINT_SHADOW_DENOISER_CountFilteredTile();
#endif
    int2 spanOrigin = int2(groupId * GLINT_SHADOW_DENOISER_FILTER_TILE) - GLINT_SHADOW_DENOISER_FILTER_APRON;
    [unroll] for (uint k = 0; k < 4; ++k)
    {
        uint slot = groupIndex + k * 64u;
        int2 local = int2(slot % GLINT_SHADOW_DENOISER_FILTER_SPAN, slot / GLINT_SHADOW_DENOISER_FILTER_SPAN);
        int2 pixel = clamp(spanOrigin + local, int2(0, 0), int2(inputSize) - 1);
        g_glint_shadow_denoiser_filter_values[slot] =
            GLINT_SHADOW_DENOISER_SanitizeMeanVariance(GLINT_SHADOW_DENOISER_LoadMeanVariance(pixel));
        float z = GLINT_SHADOW_DENOISER_ReceiverViewDepth(GLINT_SHADOW_DENOISER_LoadDepth(pixel), viewDepth);
        float3 n = z > 0.0 ? GLINT_SHADOW_DENOISER_SanitizeNormal(GLINT_SHADOW_DENOISER_LoadNormal(pixel))
                           : float3(0.0, 0.0, 0.0);
        g_glint_shadow_denoiser_filter_geometry[slot] = float4(z, n);
    }
    GroupMemoryBarrierWithGroupSync();

    int2 pixel = int2(groupId * GLINT_SHADOW_DENOISER_FILTER_TILE + groupThreadId);
    if (any(uint2(pixel) >= inputSize))
        return;
    int2 centre = int2(groupThreadId) + GLINT_SHADOW_DENOISER_FILTER_APRON;
    float4 geometry = g_glint_shadow_denoiser_filter_geometry[GLINT_SHADOW_DENOISER_FilterSlot(centre)];
    if (geometry.x <= 0.0)
    {
        GLINT_SHADOW_DENOISER_StoreFiltered(pixel, float2(0.0, 0.0));
        return;
    }
    float2 value = g_glint_shadow_denoiser_filter_values[GLINT_SHADOW_DENOISER_FilterSlot(centre)];

    float filteredVariance = 0.0;
    [unroll] for (int y = -1; y <= 1; ++y)
        [unroll] for (int x = -1; x <= 1; ++x)
        {
            float weight = (x == 0 ? 0.5 : 0.25) * (y == 0 ? 0.5 : 0.25);
            filteredVariance += weight * g_glint_shadow_denoiser_filter_values[GLINT_SHADOW_DENOISER_FilterSlot(centre + int2(x, y))].y;
        }
    float sigma = sqrt(filteredVariance + 1e-9);
    float depthScale = max(depthSigma * geometry.x, 1e-20);

    // The mean accumulates offsets from the centre (mean = s_c + sum w (s_q - s_c) / sum w):
    // a uniform neighbourhood then returns s_c exactly on every GPU, whatever the precision of
    // its division, so a skipped tile's constant and a filtered tile's result agree bit for bit.
    float weightSum = 1.0;
    float meanOffsetSum = 0.0;
    float varianceSum = value.y;
    [unroll] for (int j = -1; j <= 1; ++j)
        [unroll] for (int i = -1; i <= 1; ++i)
        {
            if (i == 0 && j == 0)
                continue;
            uint slot = GLINT_SHADOW_DENOISER_FilterSlot(centre + int(step) * int2(i, j));
            float4 other = g_glint_shadow_denoiser_filter_geometry[slot];
            if (other.x <= 0.0)
                continue;
            float2 tap = g_glint_shadow_denoiser_filter_values[slot];
            float normalWeight = pow(max(dot(geometry.yzw, other.yzw), 0.0), normalPower);
            float weight = GLINT_SHADOW_DENOISER_KernelWeight(i) * GLINT_SHADOW_DENOISER_KernelWeight(j) *
                           exp(-abs(value.x - tap.x) / sigma) * exp(-abs(geometry.x - other.x) / depthScale) *
                           normalWeight;
            weightSum += weight;
            meanOffsetSum += weight * (tap.x - value.x);
            varianceSum += weight * weight * tap.y;
        }
    float mean = clamp(value.x + meanOffsetSum / weightSum, 0.0, 1.0);
    float variance = max(varianceSum / (weightSum * weightSum), 0.0);
    if (finalPass)
        mean = pow(mean, max(1.2 - variance, 1.0));
    GLINT_SHADOW_DENOISER_StoreFiltered(pixel, float2(GLINT_FiniteOr(mean, 0.0), GLINT_FiniteOr(variance, 0.0)));
}

#endif // GLINT_SHADOW_DENOISER_FILTER_HLSLI
