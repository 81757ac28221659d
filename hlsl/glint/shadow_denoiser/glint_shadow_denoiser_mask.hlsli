// glint shadow denoiser: the visibility mask's bits, shared by prepare (which stores the mask)
// and classification (which, with GLINT_SHADOW_DENOISER_CLASSIFY_FROM_VISIBILITY=1, packs the
// words it needs itself). Layout in glint_shadow_denoiser_prepare.hlsli.
//
//   float GLINT_SHADOW_DENOISER_LoadVisibility(int2 pixel);
//       Visibility of an in-image pixel, 1 = lit. Only called with 0 <= pixel < inputSize.
//       A pixel is lit when the value is >= 0.5; NaN counts as shadowed.
#ifndef GLINT_SHADOW_DENOISER_MASK_HLSLI
#define GLINT_SHADOW_DENOISER_MASK_HLSLI

#include "glint/shadow_denoiser/glint_shadow_denoiser_constants.h"

float GLINT_SHADOW_DENOISER_LoadVisibility(int2 pixel);

uint GLINT_SHADOW_DENOISER_VisibilityBit(int2 pixel, uint2 inputSize)
{
    int2 clamped = clamp(pixel, int2(0, 0), int2(inputSize) - 1);
    float visibility = GLINT_SHADOW_DENOISER_LoadVisibility(clamped);
    // NaN compares false: shadowed.
    return visibility >= 0.5 ? 1u : 0u;
}

// Bits of pixel row `row` (0..3) of mask tile `tile`, shifted into their byte of the word.
uint GLINT_SHADOW_DENOISER_MaskRow(int2 tile, uint row, uint2 inputSize)
{
    int2 origin = tile * int2(GLINT_SHADOW_DENOISER_MASK_TILE_WIDTH, GLINT_SHADOW_DENOISER_MASK_TILE_HEIGHT) +
                  int2(0, int(row));
    uint bits = 0u;
    [unroll] for (uint column = 0; column < GLINT_SHADOW_DENOISER_MASK_TILE_WIDTH; ++column)
        bits |= GLINT_SHADOW_DENOISER_VisibilityBit(origin + int2(column, 0), inputSize) << column;
    return bits << (row * GLINT_SHADOW_DENOISER_MASK_TILE_WIDTH);
}

#endif // GLINT_SHADOW_DENOISER_MASK_HLSLI
