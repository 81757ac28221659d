// The shadow denoiser's final output image ("shadow_output") as the entry files declare it.
// Its format is the application's choice (ShadowDenoiserDesc::outputFormat) and a storage
// image's format is fixed in SPIR-V, so each format is a permutation:
//   GLINT_SHADOW_DENOISER_OUTPUT_FORMAT 0: rg32f (shadow, variance), the default here and the
//                                          format of the scratch images the filter also writes
//                                       1: r16f  (shadow)
//                                       2: r8    (shadow, unorm; the plan's default)
// The library's callbacks always pass (shadow, variance); one-channel formats keep .x.
// Only the passes that write the final output take the non-default permutations.
#ifndef GLINT_SHADOW_DENOISER_OUTPUT_HLSLI
#define GLINT_SHADOW_DENOISER_OUTPUT_HLSLI

#include "entry/common/glint_entry_common.hlsli"

#ifndef GLINT_SHADOW_DENOISER_OUTPUT_FORMAT
#define GLINT_SHADOW_DENOISER_OUTPUT_FORMAT 0
#endif

#if GLINT_SHADOW_DENOISER_OUTPUT_FORMAT == 0
#define GLINT_SHADOW_DENOISER_OUTPUT_IMAGE GLINT_IMAGE_FORMAT(rg32f) RWTexture2D<float2>
#define GLINT_SHADOW_DENOISER_OUTPUT_TEXEL(meanVariance) (meanVariance)
#elif GLINT_SHADOW_DENOISER_OUTPUT_FORMAT == 1
#define GLINT_SHADOW_DENOISER_OUTPUT_IMAGE GLINT_IMAGE_FORMAT(r16f) RWTexture2D<float>
#define GLINT_SHADOW_DENOISER_OUTPUT_TEXEL(meanVariance) ((meanVariance).x)
#elif GLINT_SHADOW_DENOISER_OUTPUT_FORMAT == 2
// unorm: the store clamps to [0, 1] and rounds to 8 bits (the shadow is in [0, 1] already).
#define GLINT_SHADOW_DENOISER_OUTPUT_IMAGE GLINT_IMAGE_FORMAT(r8) RWTexture2D<unorm float>
#define GLINT_SHADOW_DENOISER_OUTPUT_TEXEL(meanVariance) ((meanVariance).x)
#else
#error "GLINT_SHADOW_DENOISER_OUTPUT_FORMAT must be 0 (rg32f), 1 (r16f) or 2 (r8)"
#endif

#endif // GLINT_SHADOW_DENOISER_OUTPUT_HLSLI
