// glint shadow denoiser: the penumbra width estimate that classification and the filter share
// (docs/shadow_denoiser.md, "Penumbra-aware filtering" and "Hard shadows pass through").
//
// penumbraScale = 2 tan(light angular radius) / (pixel angular size), from the host plan:
//   < 0  unknown light or pixel size: no estimate (every pixel as wide as
//        GLINT_SHADOW_DENOISER_FULL_PENUMBRA: the full filter, the full temporal stage);
//   = 0  a light of angular radius 0: every shadow is hard (width 0), the blocker distance is
//        not read;
//   > 0  the width of a receiver's penumbra is W = penumbraScale * b / z pixels, b the blocker
//        distance along the pixel's shadow ray, z its view depth.
// No callbacks: the passes load the blocker distance and pass it in.
#ifndef GLINT_SHADOW_DENOISER_PENUMBRA_HLSLI
#define GLINT_SHADOW_DENOISER_PENUMBRA_HLSLI

#include "glint/common/glint_math.hlsli"
#include "glint/shadow_denoiser/glint_shadow_denoiser_constants.h"

// Whether the plan passes a penumbra estimate (penumbraScale >= 0; NaN is not one).
bool GLINT_SHADOW_DENOISER_PenumbraKnown(float penumbraScale)
{
    return penumbraScale >= 0.0;
}

// Whether the pass must load blocker distances (a light of positive size).
bool GLINT_SHADOW_DENOISER_PenumbraReadsBlockers(float penumbraScale)
{
    return penumbraScale > 0.0;
}

// Penumbra width in pixels a sample implies (only with a known estimate): 0 for a
// non-receiver (z <= 0), a lit sample (blocker 0) or a light of size 0; unknown blockers
// (negative, non-finite) count as wide enough for the full filter.
float GLINT_SHADOW_DENOISER_PenumbraWidth(float blocker, float z, float penumbraScale)
{
    if (!(z > 0.0) || !(penumbraScale > 0.0))
        return 0.0;
    if (!GLINT_IsFinite(blocker) || blocker < 0.0)
        return GLINT_SHADOW_DENOISER_FULL_PENUMBRA;
    float width = penumbraScale * blocker / z;
    return GLINT_IsFinite(width) ? min(width, GLINT_SHADOW_DENOISER_FULL_PENUMBRA) : GLINT_SHADOW_DENOISER_FULL_PENUMBRA;
}

#endif // GLINT_SHADOW_DENOISER_PENUMBRA_HLSLI
