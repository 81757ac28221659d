// glint SSSR, pass 3: this frame's blue-noise sample (docs/sssr.md "Blue noise").
//
// Integration: define these callbacks before or after including this header.
//
//   float2 GLINT_SSSR_LoadBlueNoiseSource(int2 texel);
//       The 128x128 two-channel source (glint::sssrBlueNoise(): void-and-cluster, values
//       (rank + 0.5) / 16384), texel in [0, 128)^2.
//   void   GLINT_SSSR_StoreBlueNoise(int2 texel, float2 sample);
//       This frame's sample in [0, 1)^2 for texel in [0, 128)^2.
//
// Entry: from main, GLINT_SSSR_AnimateBlueNoise(c, SV_DispatchThreadID.xy), c the
// GLINT_SssrConstants in a cbuffer (glint_sssr_common.hlsli; only c.frameIndex is read).
// glint's entry also calls GLINT_SSSR_WriteIndirectArguments (glint_sssr_indirect_args.hlsli)
// from thread (0, 0) of the same dispatch. Integration guide: docs/integration.md.
// Dispatch: [numthreads(8, 8, 1)], 16 x 16 groups.
//
// Animation: each dimension d is shifted by frac(k a_d) with the R2 constants a = (0.7548776662,
// 0.5698402910) (Roberts 2018), so the two dimensions never move together
// (docs/conventions.md, defect SS13: one golden-ratio shift for both), plus a per-frame
// toroidal texel offset from a hash of k.
// frac(k a_d) is computed in 0.32 fixed point, exact for every 32-bit frame index, so the
// sequence has no period shorter than 2^32 frames.
#ifndef GLINT_SSSR_BLUE_NOISE_HLSLI
#define GLINT_SSSR_BLUE_NOISE_HLSLI

#include "glint/sssr/glint_sssr_constants.h"

float2 GLINT_SSSR_LoadBlueNoiseSource(int2 texel);
void GLINT_SSSR_StoreBlueNoise(int2 texel, float2 sample);

// A 32-bit integer hash (the "lowbias32" constants of Wellons' hash prospector).
uint GLINT_SSSR_Hash(uint x)
{
    x ^= x >> 16;
    x *= 0x7FEB352Du;
    x ^= x >> 15;
    x *= 0x846CA68Bu;
    x ^= x >> 16;
    return x;
}

float2 GLINT_SSSR_BlueNoiseShift(uint frameIndex)
{
    uint2 fixedPoint = uint2(frameIndex * 0xC13FA9A9u, frameIndex * 0x91E10DA6u);
    return float2(fixedPoint >> 8) * (1.0 / 16777216.0);
}

void GLINT_SSSR_AnimateBlueNoise(GLINT_SssrConstants c, uint2 texel)
{
    uint hash = GLINT_SSSR_Hash(c.frameIndex);
    uint2 offset = uint2(hash & 127u, (hash >> 7) & 127u);
    float2 source = GLINT_SSSR_LoadBlueNoiseSource(int2((texel + offset) & 127u));
    float2 value = frac(source + GLINT_SSSR_BlueNoiseShift(c.frameIndex));
    // frac can round up to exactly 1.0 for inputs just below an integer; keep [0, 1).
    GLINT_SSSR_StoreBlueNoise(int2(texel), min(value, 0.99999994));
}

#endif // GLINT_SSSR_BLUE_NOISE_HLSLI
