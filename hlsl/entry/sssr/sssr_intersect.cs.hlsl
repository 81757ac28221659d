// Permutation GLINT_SSSR_HALF_STORAGE=1: roughness, radiance and confidence stored in 16-bit
// float (the header clamps radiance to the fp16 range first).
// Entry for the SSSR intersection: main here, bindings and callbacks in
// sssr_intersect_bindings.hlsli. Engines read the two as the integration example for
// glint/sssr/glint_sssr_intersect.hlsli.
//
// Permutations: GLINT_SSSR_THICKNESS_AWARE=1 (RG32F closest+farthest pyramid),
// GLINT_SSSR_DEBUG_OUTPUT=1 (per-ray class and iteration count), GLINT_SSSR_STORE_RAY=1 (the
// sampled direction and pdf, for the denoiser's ratio-estimator path).
#include "entry/common/glint_entry_common.hlsli"
#include "glint/sssr/glint_sssr_constants.h"
#include "glint/sssr/glint_sssr_intersect.hlsli"
#include "entry/sssr/sssr_environment.hlsli"
#include "entry/sssr/sssr_intersect_bindings.hlsli"

[numthreads(64, 1, 1)] void main(uint3 groupId : SV_GroupID, uint groupIndex : SV_GroupIndex)
{
    GLINT_SSSR_Intersect(g_glint_sssr, groupIndex,
                         (groupId.y * GLINT_SSSR_GROUPS_PER_ROW + groupId.x) * GLINT_SSSR_RAYS_PER_GROUP + groupIndex);
}
