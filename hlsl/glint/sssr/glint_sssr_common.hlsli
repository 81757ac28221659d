// glint SSSR: helpers shared by the classification, intersection and composite passes:
// depth conventions, (un)projection, the quad rules and the ray-list packing
// (docs/conventions.md §1, §2 and §8; docs/sssr.md).
// Integration: included by the pass headers; needs no callbacks and declares no resources.
// No entry function of its own. Every SSSR entry function takes the constants struct
// GLINT_SssrConstants (glint_sssr_constants.h; filled by host/src/core/sssr_passes.cpp) by
// value; declare it in the form DXC (DXIL and SPIR-V) and glslang all accept,
//   cbuffer MyConstants : register(b0) { GLINT_SssrConstants g_sssr; };   ... (g_sssr, ...)
// (glslang rejects a ConstantBuffer<GLINT_SssrConstants> passed to them: "no matching
// overloaded function"). Normals are world space everywhere. Guide: docs/integration.md.
#ifndef GLINT_SSSR_COMMON_HLSLI
#define GLINT_SSSR_COMMON_HLSLI

#include "glint/common/glint_math.hlsli"
#include "glint/common/glint_wire_formats.h"
#include "glint/sssr/glint_sssr_constants.h"

#define GLINT_SSSR_BACKGROUND_EPSILON 1e-6

bool GLINT_SSSR_Reversed(GLINT_SssrConstants c)
{
    return (c.flags & GLINT_SSSR_FLAG_REVERSED_DEPTH) != 0;
}

// Sky, far plane, NaN and out-of-range depths are all background: a non-finite depth must
// never become a ray origin or an occluder.
bool GLINT_SSSR_IsBackground(float depth, bool reversed)
{
    if (!GLINT_IsFinite(depth))
        return true;
    return reversed ? (depth <= GLINT_SSSR_BACKGROUND_EPSILON || depth > 1.0)
                    : (depth >= 1.0 - GLINT_SSSR_BACKGROUND_EPSILON || depth < 0.0);
}

// The depth every background texel stands for in the traversal.
float GLINT_SSSR_FarDepth(bool reversed)
{
    return reversed ? 0.0 : 1.0;
}

// True when device depth a is strictly closer to the camera than b.
bool GLINT_SSSR_Closer(float a, float b, bool reversed)
{
    return reversed ? a > b : a < b;
}

float GLINT_SSSR_ViewDepth(GLINT_SssrConstants c, float depth)
{
    return c.viewDepth.x / (c.viewDepth.y + c.viewDepth.z * depth);
}

float4 GLINT_SSSR_Mul(float4 rows[4], float4 p)
{
    return float4(dot(rows[0], p), dot(rows[1], p), dot(rows[2], p), dot(rows[3], p));
}

float3 GLINT_SSSR_MulDirection(float4 rows[4], float3 d)
{
    return float3(dot(rows[0].xyz, d), dot(rows[1].xyz, d), dot(rows[2].xyz, d));
}

// Screen uv (origin top-left, +v down) and device depth -> NDC; the y sign is explicit.
float3 GLINT_SSSR_NdcFromUv(GLINT_SssrConstants c, float2 uv, float depth)
{
    return float3(2.0 * uv.x - 1.0, c.ndcYSign * (2.0 * uv.y - 1.0), depth);
}

float2 GLINT_SSSR_UvFromNdc(GLINT_SssrConstants c, float2 ndc)
{
    return float2(0.5 * ndc.x + 0.5, 0.5 * c.ndcYSign * ndc.y + 0.5);
}

float3 GLINT_SSSR_ViewPosition(GLINT_SssrConstants c, float2 uv, float depth)
{
    float4 q = GLINT_SSSR_Mul(c.viewFromClip, float4(GLINT_SSSR_NdcFromUv(c, uv, depth), 1.0));
    return q.xyz / q.w;
}

// n = normalize(raw * mul + add); zero when the result is not a usable direction.
float3 GLINT_SSSR_UnpackNormal(GLINT_SssrConstants c, float3 raw)
{
    float3 n = raw * c.normalUnpack.x + c.normalUnpack.y;
    float lengthSquared = dot(n, n);
    if (!GLINT_IsFinite(lengthSquared) || !(lengthSquared > 1e-12))
        return float3(0.0, 0.0, 0.0);
    return n * rsqrt(lengthSquared);
}

// GGX alpha from the material channel's raw value, converted exactly once
// (docs/conventions.md §4). Non-finite roughness counts as fully rough.
float GLINT_SSSR_AlphaFromMaterial(GLINT_SssrConstants c, float raw)
{
    float value = GLINT_IsFinite(raw) ? GLINT_Saturate(raw) : 1.0;
    return (c.flags & GLINT_SSSR_FLAG_ROUGHNESS_PERCEPTUAL) != 0 ? GLINT_AlphaFromPerceptualRoughness(value)
                                                                 : value;
}

// Which pixel of its 2x2 quad traces in half-resolution mode: a fixed 4x4 pattern of quads
// (each offset once per row and column) rotated by the frame index so that every pixel of a
// quad traces once in four frames.
uint2 GLINT_SSSR_HalfResolutionOffset(uint2 pixel, uint frameIndex)
{
    uint2 quad = (pixel >> 1) & 3u;
    // Rows of the pattern 0 1 2 3 / 3 2 1 0 / 1 0 3 2 / 2 3 0 1, two bits per entry.
    const uint rows = 0xE4u | (0x1Bu << 8) | (0xB1u << 16) | (0x4Eu << 24);
    uint index = ((rows >> (quad.y * 8u + quad.x * 2u)) + frameIndex) & 3u;
    return uint2(index & 1u, index >> 1);
}

// The quad's base-ray rule (docs/sssr.md, "Classification"): which pixels trace before copies.
bool GLINT_SSSR_IsBasePixel(GLINT_SssrConstants c, uint2 pixel)
{
    if ((c.flags & GLINT_SSSR_FLAG_HALF_RESOLUTION) != 0)
        return all((pixel & 1u) == GLINT_SSSR_HalfResolutionOffset(pixel, c.frameIndex));
    if (c.samplesPerQuad >= 4)
        return true;
    if (c.samplesPerQuad == 2)
        return (pixel.x & 1u) == (pixel.y & 1u);
    return ((pixel.x | pixel.y) & 1u) == 0;
}

// The 8x8 tile grid: columns, and tiles in all (row-major: tile = y * columns + x).
uint GLINT_SSSR_TileColumns(GLINT_SssrConstants c)
{
    return (c.inputSize.x + GLINT_SSSR_TILE - 1) / GLINT_SSSR_TILE;
}

uint GLINT_SSSR_TileCount(GLINT_SssrConstants c)
{
    return GLINT_SSSR_TileColumns(c) * ((c.inputSize.y + GLINT_SSSR_TILE - 1) / GLINT_SSSR_TILE);
}

// Ray-list and tile-list entries: the wire formats of glint/common/glint_wire_formats.h.
uint GLINT_SSSR_PackRay(uint2 pixel, uint copyFlags)
{
    return GLINT_WIRE_PackRayEntry(pixel.x, pixel.y, copyFlags);
}

// Tile-list entry: the tile's top-left pixel.
uint GLINT_SSSR_PackTile(uint2 topLeft)
{
    return GLINT_WIRE_PackTileEntry(topLeft.x, topLeft.y);
}

uint2 GLINT_SSSR_UnpackRayPixel(uint entry)
{
    return uint2(GLINT_WIRE_RayEntryX(entry), GLINT_WIRE_RayEntryY(entry));
}

// Filtered-importance-sampling LOD (Colbert & Krivanek 2007): the environment level whose
// texel solid angle matches the sample's, 0.5 log2(omega_s / omega_p) with omega_s = 1/pdf.
float GLINT_SSSR_EnvironmentLod(GLINT_SssrConstants c, float pdf)
{
    float omegaS = 1.0 / max(pdf, 1e-20);
    float lod = 0.5 * log2(omegaS / max(c.environmentTexelSolidAngle, 1e-20));
    return clamp(GLINT_FiniteOr(lod, 0.0), 0.0, c.environmentMaxLod);
}

// Replaces non-finite or negative radiance by 0 and clamps to the fp16 maximum, so that
// nothing non-finite leaves a pass and the 16-bit storage permutation cannot overflow to Inf.
float3 GLINT_SSSR_SanitizeRadiance(float3 value)
{
    return float3(clamp(GLINT_FiniteOr(value.x, 0.0), 0.0, 65504.0), clamp(GLINT_FiniteOr(value.y, 0.0), 0.0, 65504.0),
                  clamp(GLINT_FiniteOr(value.z, 0.0), 0.0, 65504.0));
}

#endif // GLINT_SSSR_COMMON_HLSLI
