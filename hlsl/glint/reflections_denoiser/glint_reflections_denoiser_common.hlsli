// glint reflections denoiser: helpers shared by every pass (reproject, prefilter, resolve and
// the ratio path's reconstruct and cleanup; docs/reflections_denoiser.md). Defines no resources
// and no entry function; the callbacks below are declared here and defined by the entry files.
//
//   uint   GLINT_RD_LoadTile(uint index);          SSSR's tile list: the tile's top-left pixel, x | y << 16
//   float  GLINT_RD_LoadDepth(int2 pixel);         device depth of an in-image pixel
//   float3 GLINT_RD_LoadNormal(int2 pixel);        stored world-space normal (unpacked with normalUnpack)
//   float  GLINT_RD_LoadRoughness(int2 pixel);     GGX alpha (SSSR's "sssr_roughness")
//
// Every pass's entry function takes its constants struct by value: GLINT_ReflectionsDenoiserConstants
// (glint_reflections_denoiser_constants.h), or GLINT_ReflectionsDenoiserRatioConstants for the
// ratio path, both filled by host/src/core/reflections_denoiser_passes.cpp. Declare it as
//   cbuffer MyConstants : register(b0) { GLINT_ReflectionsDenoiserConstants g_rd; };
// (glslang cannot pass a ConstantBuffer<T> to a function taking T; DXC and glslang accept this).
// Every pass: [numthreads(8, 8, 1)] in every variant, dispatched indirectly with SSSR's
// arguments at byte 12, (listed tiles, 1, 1); SV_GroupID.x indexes SSSR's tile list.
// Integration guide: docs/integration.md.
#ifndef GLINT_REFLECTIONS_DENOISER_COMMON_HLSLI
#define GLINT_REFLECTIONS_DENOISER_COMMON_HLSLI

#include "glint/common/glint_math.hlsli"
#include "glint/common/glint_wire_formats.h"
#include "glint/reflections_denoiser/glint_reflections_denoiser_constants.h"

uint GLINT_RD_LoadTile(uint index);
float GLINT_RD_LoadDepth(int2 pixel);
float3 GLINT_RD_LoadNormal(int2 pixel);
float GLINT_RD_LoadRoughness(int2 pixel);

// The pixel's surface as the denoiser sees it: a glossy pixel has a finite depth inside the
// depth range, a usable normal and alpha below the threshold. Only glossy pixels are ever
// used as neighbours, so pixels of tiles nobody listed (which hold stale data) are never read
// as if they were valid (docs/conventions.md, defects RD6 and RD9).
struct GLINT_RD_Surface
{
    float3 normal;    // unit, world space
    float viewDepth;  // > 0
    float depth;      // the device depth it came from
    float alpha;
    bool glossy;
};

float GLINT_RD_Luma(float3 c)
{
    return dot(c, float3(0.2126, 0.7152, 0.0722));
}

float3 GLINT_RD_Finite3(float3 v)
{
    return float3(GLINT_FiniteOr(v.x, 0.0), GLINT_FiniteOr(v.y, 0.0), GLINT_FiniteOr(v.z, 0.0));
}

// Finite, non-negative and within the fp16 range: what every pass stores.
float3 GLINT_RD_SanitizeRadiance(float3 v)
{
    return clamp(GLINT_RD_Finite3(v), 0.0, 65504.0);
}

float GLINT_RD_ViewDepth(GLINT_ReflectionsDenoiserConstants c, float depth)
{
    return c.viewDepth.x / (c.viewDepth.y + c.viewDepth.z * depth);
}

// The stored normal unpacked and made unit; (0, 0, 1) when it has no usable length (ok false).
float3 GLINT_RD_UnpackNormal(GLINT_ReflectionsDenoiserConstants c, float3 stored, out bool ok)
{
    float3 n = stored * c.normalUnpack.x + c.normalUnpack.y;
    float lengthSquared = dot(n, n);
    ok = GLINT_IsFinite(lengthSquared) && lengthSquared > 1e-12;
    return ok ? n * rsqrt(lengthSquared) : float3(0.0, 0.0, 1.0);
}

GLINT_RD_Surface GLINT_RD_LoadSurface(GLINT_ReflectionsDenoiserConstants c, int2 pixel)
{
    GLINT_RD_Surface s;
    float depth = GLINT_RD_LoadDepth(pixel);
    s.depth = depth;
    bool normalOk;
    s.normal = GLINT_RD_UnpackNormal(c, GLINT_RD_LoadNormal(pixel), normalOk);
    s.alpha = GLINT_FiniteOr(GLINT_RD_LoadRoughness(pixel), 1.0);
    bool reversed = (c.flags & GLINT_RD_FLAG_REVERSED_DEPTH) != 0;
    bool background = !GLINT_IsFinite(depth) || (reversed ? (depth <= 1e-6 || depth > 1.0) : (depth >= 1.0 - 1e-6 || depth < 0.0));
    s.viewDepth = background ? 1.0 : GLINT_RD_ViewDepth(c, depth);
    s.glossy = !background && normalOk && s.alpha < c.roughnessThreshold && s.viewDepth > 0.0 &&
               GLINT_IsFinite(s.viewDepth);
    return s;
}

float4 GLINT_RD_Mul(float4 rows[4], float4 p)
{
    return float4(dot(rows[0], p), dot(rows[1], p), dot(rows[2], p), dot(rows[3], p));
}

// This frame's view-space position of pixel uv at device depth d.
float3 GLINT_RD_ViewPosition(GLINT_ReflectionsDenoiserConstants c, float2 uv, float depth)
{
    float4 q = GLINT_RD_Mul(c.viewFromClip, float4(2.0 * uv.x - 1.0, c.ndcYSign * (2.0 * uv.y - 1.0), depth, 1.0));
    return q.xyz / q.w;
}

// Last frame's uv of a view-space point of this frame, and its view depth there (clip w).
float2 GLINT_RD_PreviousUv(GLINT_ReflectionsDenoiserConstants c, float3 viewPosition, out float previousViewDepth)
{
    float4 clip = GLINT_RD_Mul(c.previousClipFromView, float4(viewPosition, 1.0));
    previousViewDepth = clip.w;
    float2 ndc = clip.xy / clip.w;
    return float2(0.5 * ndc.x + 0.5, 0.5 * c.ndcYSign * ndc.y + 0.5);
}

// The pixel of slot spanIndex of a span (the tile plus an apron, span = 8 + 2 apron texels a
// side, row-major); span texels outside the image are clamped to its edge. A pass whose taps
// reach less far than GLINT_RD_APRON passes its own, smaller span (prefilter: 14x14).
int2 GLINT_RD_SpanPixelOf(GLINT_ReflectionsDenoiserConstants c, uint2 tileOrigin, uint spanIndex, uint span, int apron)
{
    int2 offset = int2(spanIndex % span, spanIndex / span) - apron;
    return clamp(int2(tileOrigin) + offset, int2(0, 0), int2(c.inputSize) - 1);
}

// The tile's 16x16 span (tile plus a 4-pixel apron: the 9x9 statistics).
int2 GLINT_RD_SpanPixel(GLINT_ReflectionsDenoiserConstants c, uint2 tileOrigin, uint spanIndex)
{
    return GLINT_RD_SpanPixelOf(c, tileOrigin, spanIndex, GLINT_RD_SPAN, GLINT_RD_APRON);
}

// Gaussian weights of the 9x9 neighbourhood statistics, exp(-3 i^2 / 25) for i in [-4, 4].
float GLINT_RD_GaussianWeight(int i)
{
    return exp(-3.0 * float(i * i) / 25.0);
}

#ifdef GLINT_RD_USES_ROW_STATISTICS
// The 9x9 Gaussian statistics, separably: the weights are products w(x) w(y) times a 0/1
// glossy mask, so the sums factor into 9-tap row sums (per span row and tile column) and a
// 9-tap sum of those down the column.
//
// Row pass: the 16 span rows x 8 tile columns are 128 row sums, two a thread: thread i sums
// row i / 4 for the neighbouring columns 2 (i % 4) and 2 (i % 4) + 1, which share 8 of their 10
// span texels (10 groupshared reads for two sums instead of 18). Column pass: 9 row sums (two
// reads each: sums and squares) a pixel. About 30 taps of arithmetic a pixel instead of 81.
// Row r of the span, tile column x: slot r * 8 + x.
groupshared float4 g_glint_rd_row_sums[GLINT_RD_SPAN * GLINT_RD_TILE];    // (sum w rgb, sum w)
groupshared float4 g_glint_rd_row_squares[GLINT_RD_SPAN * GLINT_RD_TILE]; // (sum w rgb^2, sum w extra)

struct GLINT_RD_RowPair
{
    float4 sums[2];    // (sum w rgb, sum w) of the two columns
    float4 squares[2]; // (sum w rgb^2, sum w extra)
};

// The span row and first tile column of the thread's row pair (localIndex: 0..63).
uint GLINT_RD_RowPairRow(uint localIndex)
{
    return localIndex >> 2;
}

uint GLINT_RD_RowPairColumn(uint localIndex)
{
    return (localIndex & 3u) * 2u;
}

// Adds span texel `row, column + i` (i = 0..9, a constant: call it from an unrolled loop) to
// the pair: rgb (0 where not glossy, so that only the weight needs the mask), the glossy mask,
// 0 or 1, and one more value summed with the same weights (0 where not glossy; the resolve's
// anti-lag carries its history-minus-sample difference there, reproject passes 0).
void GLINT_RD_AccumulateRowPair(inout GLINT_RD_RowPair pair, int i, float3 rgb, float glossy, float extra)
{
    float4 value = float4(rgb, glossy);
    float4 square = float4(rgb * rgb, extra);
    if (i < 2 * GLINT_RD_APRON + 1)
    {
        float w = GLINT_RD_GaussianWeight(i - GLINT_RD_APRON);
        pair.sums[0] += w * value;
        pair.squares[0] += w * square;
    }
    if (i > 0)
    {
        float w = GLINT_RD_GaussianWeight(i - 1 - GLINT_RD_APRON);
        pair.sums[1] += w * value;
        pair.squares[1] += w * square;
    }
}

void GLINT_RD_StoreRowStatistics(uint row, uint column, float4 sums, float4 squares)
{
    g_glint_rd_row_sums[row * GLINT_RD_TILE + column] = sums;
    g_glint_rd_row_squares[row * GLINT_RD_TILE + column] = squares;
}

void GLINT_RD_StoreRowPair(uint localIndex, GLINT_RD_RowPair pair)
{
    uint row = GLINT_RD_RowPairRow(localIndex);
    uint column = GLINT_RD_RowPairColumn(localIndex);
    GLINT_RD_StoreRowStatistics(row, column, pair.sums[0], pair.squares[0]);
    GLINT_RD_StoreRowStatistics(row, column + 1u, pair.sums[1], pair.squares[1]);
}

// The 9x9 sums of tile pixel `local` from the row sums (after a barrier that follows their
// stores): rgb sum, rgb squares, weight and the extra value's weighted sum.
void GLINT_RD_ColumnStatistics(uint2 local, out float3 sum, out float3 sumSquares, out float weightSum,
                               out float extraSum)
{
    float4 sums = float4(0.0, 0.0, 0.0, 0.0);
    float4 squares = float4(0.0, 0.0, 0.0, 0.0);
    [unroll] for (int y = -GLINT_RD_APRON; y <= GLINT_RD_APRON; ++y)
    {
        uint slot = (local.y + uint(GLINT_RD_APRON + y)) * GLINT_RD_TILE + local.x;
        float w = GLINT_RD_GaussianWeight(y);
        sums += w * g_glint_rd_row_sums[slot];
        squares += w * g_glint_rd_row_squares[slot];
    }
    sum = sums.rgb;
    sumSquares = squares.rgb;
    weightSum = sums.a;
    extraSum = squares.a;
}
#endif

// The texels of the groupshared spans of radiance: reproject's noisy samples and the resolve's
// prefiltered radiance (which feed the 9x9 neighbourhood statistics), the prefilter's clamped
// samples: four values each.
//
// GLINT_RD_HALF_GROUPSHARED 1 (the 16-bit permutation's choice) carries them as four halves in
// two words (x | y << 16, z | w << 16): half the bytes a groupshared read. Groupshared reads
// bound the 9x9 statistics, so this is where the 16-bit permutation gains its speed
// (docs/performance.md, "Reflections denoiser: groupshared spans"). With fp16 images (SSSR's
// radiance, the clamped and prefiltered samples of the 16-bit permutation) that is lossless:
// the values were read from halves. Every value is finite and within the fp16 range before it
// is narrowed, and the sums stay 32-bit (docs/conventions.md, defect RD4). The default is
// 32-bit, as that defect's rule requires: narrowing 32-bit images' values would round them.
#ifndef GLINT_RD_HALF_GROUPSHARED
#define GLINT_RD_HALF_GROUPSHARED 0
#endif
#if GLINT_RD_HALF_GROUPSHARED
#define GLINT_RD_SpanTexel uint2
GLINT_RD_SpanTexel GLINT_RD_PackSpanTexel(float4 v)
{
    return uint2(f32tof16(v.x) | (f32tof16(v.y) << 16), f32tof16(v.z) | (f32tof16(v.w) << 16));
}

float4 GLINT_RD_UnpackSpanTexel(GLINT_RD_SpanTexel p)
{
    return float4(f16tof32(p.x), f16tof32(p.x >> 16), f16tof32(p.y), f16tof32(p.y >> 16));
}
#else
#define GLINT_RD_SpanTexel float4
GLINT_RD_SpanTexel GLINT_RD_PackSpanTexel(float4 v)
{
    return v;
}

float4 GLINT_RD_UnpackSpanTexel(GLINT_RD_SpanTexel p)
{
    return p;
}
#endif

// Clip x toward the box centre m with half-extent e (Playdead): the point where the segment
// from m to x leaves the box, or x inside it.
float3 GLINT_RD_ClipToBox(float3 x, float3 m, float3 e)
{
    float3 v = x - m;
    float3 a = abs(v / (e + 0.001));
    float u = max(a.x, max(a.y, a.z));
    return u > 1.0 ? m + v / u : x;
}

// Mirrors stay sharp (docs/reflections_denoiser.md, "Mirrors"). The scale s of every spatial
// operation, in [0, 1]: 0 at and below mirrorThreshold, where SSSR traces the exact mirror
// direction without noise, so that any spatial reuse could only blur the reflection; rising
// linearly in alpha to 1 at GLINT_RD_FOOTPRINT_RAMP above it, where the filters act in full. The
// prefilter's taps fall off as s^(d^2 / 2) with their distance d in pixels (a Gaussian whose
// width goes to 0 with s), the firefly clamp's bound is 3 sigma / s, and the resolve moves its
// sample toward the tile average by s times the full amount: at s = 0 each passes the input
// through unchanged.
#define GLINT_RD_FOOTPRINT_RAMP 0.01
float GLINT_RD_SpatialFootprint(GLINT_ReflectionsDenoiserConstants c, float alpha)
{
    return GLINT_Saturate((alpha - c.mirrorThreshold) * (1.0 / GLINT_RD_FOOTPRINT_RAMP));
}

// A mirror's sample is noise-free, so its history may differ from it only by resampling: the
// half-width, per channel, of the band around the sample within which a mirror's history counts
// as the same reflected point (relative, with a floor for dark pixels). A history outside the
// band is stale (the reflected point moved another way) and is rejected: the pixel's history
// length and temporal variance restart.
#define GLINT_RD_MIRROR_TOLERANCE 0.1
float3 GLINT_RD_MirrorBand(float3 radiance)
{
    return GLINT_RD_MIRROR_TOLERANCE * (radiance + 0.05);
}

// The history length a pixel can use: near-mirrors keep 8 frames, alpha >~ 0.03 keeps the cap.
float GLINT_RD_MaxHistoryLength(GLINT_ReflectionsDenoiserConstants c, float alpha)
{
    return max(8.0, float(c.maxHistoryLength) * (1.0 - exp(-100.0 * alpha)));
}

// Octahedral normal encoding for the guide history, signed form (docs/conventions.md §5).
float2 GLINT_RD_EncodeNormal(float3 n)
{
    float2 p = n.xy / (abs(n.x) + abs(n.y) + abs(n.z));
    if (n.z < 0.0)
        p = (1.0 - abs(p.yx)) * float2(p.x >= 0.0 ? 1.0 : -1.0, p.y >= 0.0 ? 1.0 : -1.0);
    return p;
}

float3 GLINT_RD_DecodeNormal(float2 p)
{
    float3 m = float3(p.x, p.y, 1.0 - abs(p.x) - abs(p.y));
    float t = max(-m.z, 0.0);
    m.x -= m.x >= 0.0 ? t : -t;
    m.y -= m.y >= 0.0 ? t : -t;
    return normalize(m);
}

#ifdef GLINT_RD_USES_AVERAGE
// This frame's tile averages (prefilter and resolve, after reproject wrote them):
//   float4 GLINT_RD_LoadAverage(uint2 tile);   rgb, a = weight sum
//   bool   GLINT_RD_TileListed(uint2 tile);    this frame's tile mask (the tile's own bit)
float4 GLINT_RD_LoadAverage(uint2 tile);
bool GLINT_RD_TileListed(uint2 tile);

// Whether an in-image pixel's own tile was listed this frame: only there do the images this
// frame's passes write (the clamped sample, the prefiltered radiance) hold this frame's values.
// Under SSSR's classification every glossy pixel lies in a listed tile, so a pixel elsewhere is
// not glossy, which is what the G-buffer says of it too.
bool GLINT_RD_PixelListed(int2 pixel)
{
    return GLINT_RD_TileListed(uint2(pixel) / GLINT_RD_TILE);
}

// The tile averages a group needs: bilinear lookups at its pixels reach the tiles around its
// own, 3x3 of them. Nine threads load one each (average and this frame's mask word) before the
// group's span barrier, and every pixel interpolates from groupshared memory after it: nine
// loads a group instead of eight a pixel (four mask words, four averages), which were a third
// of the prefilter's and the resolve's loads.
// Slot (dy + 1) * 3 + dx + 1 holds tile + (dx, dy): rgb, a = 1 when the tile is usable.
groupshared float4 g_glint_rd_tile_averages[9];

// Tiles outside the tile grid, tiles not listed this frame (they hold stale averages:
// docs/conventions.md, defect RD6) and tiles without a glossy pixel are not usable; a usable
// one's average is sanitised, so that any weight times it is finite.
void GLINT_RD_LoadTileAverages(GLINT_ReflectionsDenoiserConstants c, uint2 tile, uint localIndex)
{
    if (localIndex < 9u)
    {
        int2 neighbour = int2(tile) + int2(localIndex % 3u, localIndex / 3u) - 1;
        bool inside = all(neighbour >= 0) && all(neighbour < int2(c.tiles));
        uint2 clampedTile = uint2(clamp(neighbour, int2(0, 0), int2(c.tiles) - 1));
        bool listed = GLINT_RD_TileListed(clampedTile);
        float4 average = GLINT_RD_LoadAverage(clampedTile);
        bool used = inside && listed && average.a > 0.0;
        g_glint_rd_tile_averages[localIndex] =
            used ? float4(GLINT_RD_SanitizeRadiance(average.rgb), 1.0) : float4(0.0, 0.0, 0.0, 0.0);
    }
}

// Bilinear average at a pixel of the group's tile (after the barrier that follows
// GLINT_RD_LoadTileAverages) over the centres of the surrounding tiles, using only usable
// tiles, renormalised (a used tile weighs at least 1e-4). Tile centres are at 8 i + 4, so the
// lookup is aligned at every image size (docs/conventions.md, defect RD3).
float3 GLINT_RD_AverageAt(uint2 pixel, uint2 tile)
{
    float2 p = (float2(pixel) + 0.5) / float(GLINT_RD_TILE) - 0.5;
    float2 base = floor(p);
    float2 f = p - base;
    // The first of the 2x2 tiles is the group's own or the one before it: slot column/row 0 or 1.
    int2 first = int2(base) - int2(tile) + 1;
    float3 sum = float3(0.0, 0.0, 0.0);
    float total = 0.0;
    [unroll] for (uint tap = 0; tap < 4; ++tap)
    {
        int2 offset = int2(tap & 1u, tap >> 1);
        int2 slot = first + offset;
        float4 average = g_glint_rd_tile_averages[slot.y * 3 + slot.x];
        float w = average.a > 0.0 ? max((offset.x == 1 ? f.x : 1.0 - f.x) * (offset.y == 1 ? f.y : 1.0 - f.y), 1e-4) : 0.0;
        sum += w * average.rgb;
        total += w;
    }
    return total > 0.0 ? sum / total : float3(0.0, 0.0, 0.0);
}
#endif

#endif // GLINT_REFLECTIONS_DENOISER_COMMON_HLSLI
