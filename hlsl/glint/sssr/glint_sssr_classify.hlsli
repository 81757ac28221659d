// glint SSSR, pass 2: tile classification (docs/sssr.md). Decides per pixel whether a ray is
// traced, copied from a quad neighbour or replaced by the environment; writes each tile's rays
// in its pixels' order to the tile's slots of the ray scratch buffer, with the counts the
// compaction (glint_sssr_compact.hlsli) turns into the ray list; appends the tiles with glossy
// pixels to the denoiser's tile list; extracts GGX alpha once; writes every pixel's initial
// radiance.
//
// Integration: define these callbacks before or after including this header.
//
//   float  GLINT_SSSR_LoadDepth(int2 pixel, int mip);
//       Device depth; this pass reads mip 0 only. Pixels outside the image are never asked.
//   float3 GLINT_SSSR_LoadNormal(int2 pixel);
//       The stored world-space normal before unpacking (the header applies normalUnpack and
//       normalizes).
//   float4 GLINT_SSSR_LoadMaterial(int2 pixel);
//       The material texture; constants.materialChannel selects roughness (r or alpha per flags).
//   float2 GLINT_SSSR_LoadMotion(int2 pixel);
//       The application's motion vector; uv_prev = uv + motionScale * mv (convention A).
//   float  GLINT_SSSR_SampleVarianceHistory(float2 uv);
//       Last frame's reflection variance, bilinear, uv in [0,1]^2 (only with VARIANCE_GUIDED).
//   float3 GLINT_SSSR_SampleEnvironment(float3 worldDirection, float lod);
//       The prefiltered environment, lod in the environment's own levels (0 = sharpest).
//   void   GLINT_SSSR_StoreRoughness(int2 pixel, float alpha);
//   void   GLINT_SSSR_StoreRadiance(int2 pixel, float4 radianceAndHitDistance);
//   void   GLINT_SSSR_StoreConfidence(int2 pixel, float confidence);
//   uint   GLINT_SSSR_AddRays(uint count);   atomic add to counter 0, returns the previous value
//   void   GLINT_SSSR_StoreRayScratch(uint word, uint value);   the ray scratch buffer
//   uint   GLINT_SSSR_AddRayScratch(uint word, uint value);     atomic add there, returns the previous value
//       (layout: glint/common/glint_wire_formats.h; GLINT_WIRE_RayScratchWords(tiles) words,
//       zeroed once at creation)
//   uint   GLINT_SSSR_AddTile();             atomic add of 1 to counter 2, returns the previous value
//   void   GLINT_SSSR_StoreTile(uint index, uint entry);
//
// Entry: from main, GLINT_SSSR_Classify(c, SV_GroupID.xy, SV_GroupThreadID.xy), c the
// GLINT_SssrConstants in a cbuffer (see glint_sssr_common.hlsli; filled by
// host/src/core/sssr_passes.cpp). Integration guide: docs/integration.md.
// Dispatch: [numthreads(8, 8, 1)] (also in the 16-bit storage permutation, which only changes
// the entry file's formats), ceil(W / 8) x ceil(H / 8) groups, one 8x8 tile per group.
// Quads never straddle tiles, so every quad decision is made in groupshared memory and holds
// for any subgroup size.
#ifndef GLINT_SSSR_CLASSIFY_HLSLI
#define GLINT_SSSR_CLASSIFY_HLSLI

#include "glint/sssr/glint_sssr_common.hlsli"
#include "glint/common/glint_ggx.hlsli"

float GLINT_SSSR_LoadDepth(int2 pixel, int mip);
float3 GLINT_SSSR_LoadNormal(int2 pixel);
float4 GLINT_SSSR_LoadMaterial(int2 pixel);
float2 GLINT_SSSR_LoadMotion(int2 pixel);
float GLINT_SSSR_SampleVarianceHistory(float2 uv);
float3 GLINT_SSSR_SampleEnvironment(float3 worldDirection, float lod);
void GLINT_SSSR_StoreRoughness(int2 pixel, float alpha);
void GLINT_SSSR_StoreRadiance(int2 pixel, float4 radianceAndHitDistance);
void GLINT_SSSR_StoreConfidence(int2 pixel, float confidence);
uint GLINT_SSSR_AddRays(uint count);
void GLINT_SSSR_StoreRayScratch(uint word, uint value);
uint GLINT_SSSR_AddRayScratch(uint word, uint value);
uint GLINT_SSSR_AddTile();
void GLINT_SSSR_StoreTile(uint index, uint entry);

#define GLINT_SSSR_STATE_TRACES 1u
#define GLINT_SSSR_STATE_REQUIRES_COPY 2u

groupshared uint g_glint_sssr_state[GLINT_SSSR_TILE * GLINT_SSSR_TILE];
groupshared uint g_glint_sssr_trace_bits[2]; // bit i of word i / 32: pixel i of the tile traces
groupshared uint g_glint_sssr_any_glossy;

uint GLINT_SSSR_StateAt(uint2 local)
{
    return g_glint_sssr_state[local.y * GLINT_SSSR_TILE + local.x];
}

// The quad neighbour a pixel that needs a copy takes its ray from: the first of x^1, y^1 and
// both that traces (1, 2, 3), or 0 when none does and the pixel must trace itself (the
// reference leaves such pixels black: docs/conventions.md, defect SS11). Out-of-image
// neighbours never trace.
uint GLINT_SSSR_DonorOf(uint2 local)
{
    if ((GLINT_SSSR_StateAt(local ^ uint2(1, 0)) & GLINT_SSSR_STATE_TRACES) != 0)
        return 1u;
    if ((GLINT_SSSR_StateAt(local ^ uint2(0, 1)) & GLINT_SSSR_STATE_TRACES) != 0)
        return 2u;
    if ((GLINT_SSSR_StateAt(local ^ uint2(1, 1)) & GLINT_SSSR_STATE_TRACES) != 0)
        return 3u;
    return 0u;
}

// True when the neighbour at local ^ offset needs a copy and chose this pixel (code = offset).
bool GLINT_SSSR_ChoseMe(uint2 local, uint2 offset, uint code)
{
    uint2 neighbour = local ^ offset;
    return (GLINT_SSSR_StateAt(neighbour) & GLINT_SSSR_STATE_REQUIRES_COPY) != 0 &&
           GLINT_SSSR_DonorOf(neighbour) == code;
}

// Variance of last frame at the reprojected position; off-screen history counts as high so
// that the pixel traces (docs/conventions.md, defect SS12: the reference reads it unreprojected).
bool GLINT_SSSR_HighVariance(GLINT_SssrConstants c, int2 pixel, float2 uv)
{
    float2 motion = GLINT_SSSR_LoadMotion(pixel) * c.motionScale;
    float2 previousUv = uv + float2(GLINT_FiniteOr(motion.x, 1e9), GLINT_FiniteOr(motion.y, 1e9));
    if (any(previousUv < 0.0) || any(previousUv > 1.0))
        return true;
    return !(GLINT_SSSR_SampleVarianceHistory(previousUv) <= c.varianceThreshold);
}

// What classification decided for one pixel of the tile.
struct GLINT_SSSR_PixelDecision
{
    int2 pixel;
    float2 uv;
    bool inImage;
    bool reflective; // not background, usable normal
    bool glossy;     // reflective and below the roughness threshold: the denoiser's tile list
    bool traces;     // owns a ray (its quad's copies are in copyFlags)
    uint copyFlags;  // GLINT_SSSR_RAY_COPY_*
    float alpha;
    float depth;
    float3 normal;
};

// The per-pixel decision: which pixels trace, which copy a quad neighbour's ray, and the
// GGX alpha (stored). Every thread of the 8x8 group calls it: it synchronizes the group once.
GLINT_SSSR_PixelDecision GLINT_SSSR_ClassifyPixel(GLINT_SssrConstants c, uint2 groupId, uint2 local)
{
    uint localIndex = local.y * GLINT_SSSR_TILE + local.x;
    GLINT_SSSR_PixelDecision d;
    uint2 pixel = groupId * GLINT_SSSR_TILE + local;
    d.pixel = int2(pixel);
    d.inImage = all(pixel < c.inputSize);
    d.uv = (float2(pixel) + 0.5) * c.inverseInputSize;
    d.reflective = false;
    d.glossy = false;
    d.alpha = 1.0;
    d.normal = float3(0.0, 0.0, 0.0);
    d.depth = 0.0;
    bool mirror = false;
    if (d.inImage)
    {
        d.depth = GLINT_SSSR_LoadDepth(d.pixel, 0);
        // Background pixels read nothing else (sky-heavy frames cost little) and store alpha 1.
        if (!GLINT_SSSR_IsBackground(d.depth, GLINT_SSSR_Reversed(c)))
        {
            d.normal = GLINT_SSSR_UnpackNormal(c, GLINT_SSSR_LoadNormal(d.pixel));
            float4 material = GLINT_SSSR_LoadMaterial(d.pixel);
            uint channel = min(c.materialChannel, 3u);
            float raw = channel == 0 ? material.x : channel == 1 ? material.y : channel == 2 ? material.z : material.w;
            d.alpha = GLINT_SSSR_AlphaFromMaterial(c, raw);
            d.reflective = dot(d.normal, d.normal) > 0.0;
        }
        GLINT_SSSR_StoreRoughness(d.pixel, d.alpha);
        d.glossy = d.reflective && d.alpha < c.roughnessThreshold;
        mirror = d.glossy && d.alpha < c.mirrorThreshold;
    }
    bool halfResolution = (c.flags & GLINT_SSSR_FLAG_HALF_RESOLUTION) != 0;
    bool needsDenoiser = d.glossy && !mirror;
    bool base = GLINT_SSSR_IsBasePixel(c, pixel);
    // Mirrors always trace, except in half-resolution mode where every pixel shares its quad's ray.
    bool traces = d.glossy && (base || (mirror && !halfResolution));
    bool copies = (needsDenoiser || (mirror && halfResolution)) && !traces;
    if (copies && (c.flags & GLINT_SSSR_FLAG_VARIANCE_GUIDED) != 0 && GLINT_SSSR_HighVariance(c, d.pixel, d.uv))
    {
        traces = true;
        copies = false;
    }
    g_glint_sssr_state[localIndex] = (traces ? GLINT_SSSR_STATE_TRACES : 0u) | (copies ? GLINT_SSSR_STATE_REQUIRES_COPY : 0u);
    GroupMemoryBarrierWithGroupSync();

    if (copies && GLINT_SSSR_DonorOf(local) == 0)
        traces = true; // promoted: no neighbour traces for it
    uint copyFlags = 0;
    if (traces && !copies)
    {
        copyFlags |= GLINT_SSSR_ChoseMe(local, uint2(1, 0), 1u) ? GLINT_SSSR_RAY_COPY_H : 0u;
        copyFlags |= GLINT_SSSR_ChoseMe(local, uint2(0, 1), 2u) ? GLINT_SSSR_RAY_COPY_V : 0u;
        copyFlags |= GLINT_SSSR_ChoseMe(local, uint2(1, 1), 3u) ? GLINT_SSSR_RAY_COPY_D : 0u;
    }
    d.traces = traces;
    d.copyFlags = copyFlags;
    return d;
}

// Initial radiance: the environment for reflective pixels that get no ray, 0 elsewhere;
// traced pixels and their copies are overwritten by the intersection.
void GLINT_SSSR_StoreInitialRadiance(GLINT_SssrConstants c, GLINT_SSSR_PixelDecision d)
{
    if (!d.inImage)
        return;
    float3 radiance = float3(0.0, 0.0, 0.0);
    if (d.reflective && !d.glossy)
    {
        float3 viewPosition = GLINT_SSSR_ViewPosition(c, d.uv, d.depth);
        float3 view = -normalize(GLINT_SSSR_MulDirection(c.worldFromView, viewPosition));
        float3 n = GLINT_GGX_BendNormalTowardView(d.normal, view);
        float NdotV = dot(n, view);
        float3 mirrorDirection = 2.0 * NdotV * n - view;
        // The lobe's LOD at its centre (H = N), the same estimate the traced misses use.
        float lod = GLINT_SSSR_EnvironmentLod(c, GLINT_GGX_ReflectionPdf(NdotV, 1.0, d.alpha));
        radiance = GLINT_SSSR_SampleEnvironment(mirrorDirection, lod) * c.iblFactor;
    }
    GLINT_SSSR_StoreRadiance(d.pixel, float4(GLINT_SSSR_SanitizeRadiance(radiance), GLINT_SSSR_MISS_DISTANCE));
    GLINT_SSSR_StoreConfidence(d.pixel, 0.0);
}

// The tile's rays in its pixels' row-major order: pixel localIndex's slot counts the tracing
// pixels before it, so the order does not depend on scheduling or wave size.
uint GLINT_SSSR_TraceSlot(uint localIndex)
{
    uint low = g_glint_sssr_trace_bits[0];
    if (localIndex < 32u)
        return countbits(low & ((1u << localIndex) - 1u));
    return countbits(low) + countbits(g_glint_sssr_trace_bits[1] & ((1u << (localIndex - 32u)) - 1u));
}

void GLINT_SSSR_Classify(GLINT_SssrConstants c, uint2 groupId, uint2 local)
{
    uint localIndex = local.y * GLINT_SSSR_TILE + local.x;
    if (localIndex == 0)
    {
        g_glint_sssr_trace_bits[0] = 0;
        g_glint_sssr_trace_bits[1] = 0;
        g_glint_sssr_any_glossy = 0;
    }
    // Its barrier also orders the initialization above before the atomics below.
    GLINT_SSSR_PixelDecision d = GLINT_SSSR_ClassifyPixel(c, groupId, local);
    bool traces = d.traces;

    // A groupshared OR per tracing pixel: the bit is the pixel's place in the tile, which no
    // wave layout changes.
    if (traces)
        InterlockedOr(g_glint_sssr_trace_bits[localIndex / 32u], 1u << (localIndex % 32u));
    bool waveGlossy = WaveActiveAnyTrue(d.glossy); // outside the condition: wave ops need every lane
    if (WaveIsFirstLane() && waveGlossy)
        InterlockedOr(g_glint_sssr_any_glossy, 1u);
    GroupMemoryBarrierWithGroupSync();
    uint tiles = GLINT_SSSR_TileCount(c);
    uint tile = groupId.y * GLINT_SSSR_TileColumns(c) + groupId.x;
    if (localIndex == 0)
    {
        uint count = countbits(g_glint_sssr_trace_bits[0]) + countbits(g_glint_sssr_trace_bits[1]);
        GLINT_SSSR_StoreRayScratch(GLINT_WIRE_RayScratchTileCount(tiles, tile), count);
        if (count > 0)
        {
            // Sums, so their values do not depend on the order of the groups.
            GLINT_SSSR_AddRays(count);
            uint block = tile / GLINT_WIRE_RAY_BLOCK_TILES;
            GLINT_SSSR_AddRayScratch(GLINT_WIRE_RayScratchBlockCount(tiles, block), count);
            GLINT_SSSR_AddRayScratch(GLINT_WIRE_RayScratchSuperblockCount(tiles, block / GLINT_WIRE_RAY_SUPERBLOCK_BLOCKS), count);
        }
        if (g_glint_sssr_any_glossy != 0)
            GLINT_SSSR_StoreTile(GLINT_SSSR_AddTile(), GLINT_SSSR_PackTile(groupId * GLINT_SSSR_TILE));
    }
    if (traces)
        GLINT_SSSR_StoreRayScratch(GLINT_WIRE_RayScratchSlot(tile, GLINT_SSSR_TraceSlot(localIndex)),
                                   GLINT_SSSR_PackRay(uint2(d.pixel), d.copyFlags));

    GLINT_SSSR_StoreInitialRadiance(c, d);
}

#endif // GLINT_SSSR_CLASSIFY_HLSLI
