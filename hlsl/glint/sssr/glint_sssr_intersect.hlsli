// glint SSSR, pass 5: intersection (docs/sssr.md). One ray per ray-list entry: GGX VNDF
// direction from blue noise, near-plane-clipped screen-space segment, hierarchical traversal of
// the closest-depth pyramid, hit validation and confidence, environment fallback, and the
// result written to the pixel and to the quad neighbours that copy it.
//
// Integration: define these callbacks before or after including this header.
//
//   float  GLINT_SSSR_LoadDepth(int2 texel, int mip);
//       mip 0: the device depth of an in-image pixel. mip 1..6: the depth pyramid's closest
//       value (glint_depth_pyramid.hlsli layout: texel (i, j) of mip k covers pixels
//       [i 2^k, (i+1) 2^k) x [j 2^k, (j+1) 2^k)). Texels are clamped to the level by the header.
//   float  GLINT_SSSR_LoadFarthestDepth(int2 texel, int mip);   (GLINT_SSSR_THICKNESS_AWARE=1 only)
//       The pyramid's farthest value, mip 1..6.
//   float3 GLINT_SSSR_LoadNormal(int2 pixel);        stored world-space normal (unpacked by the header)
//   float  GLINT_SSSR_LoadRoughness(int2 pixel);     GGX alpha written by the classification
//   float2 GLINT_SSSR_LoadBlueNoise(int2 pixel);     this frame's sample in [0,1)^2, any pixel (wrap)
//   float3 GLINT_SSSR_LoadColor(int2 pixel);         lit colour of this frame (point load)
//   float3 GLINT_SSSR_SampleColor(float2 uv);        previous frame's colour, bilinear (PREVIOUS_FRAME_COLOR)
//   float2 GLINT_SSSR_LoadMotion(int2 pixel);        application motion vector (scaled by motionScale)
//   float3 GLINT_SSSR_SampleEnvironment(float3 worldDirection, float lod);
//   uint   GLINT_SSSR_LoadRayCount();                counter 1 (copied by the indirect-arguments pass)
//   uint   GLINT_SSSR_LoadRay(uint index);
//   void   GLINT_SSSR_StoreRadiance(int2 pixel, float4 radianceAndHitDistance);
//   void   GLINT_SSSR_StoreConfidence(int2 pixel, float confidence);
//   void   GLINT_SSSR_StoreRayInfo(int2 pixel, float4 info);   (GLINT_SSSR_DEBUG_OUTPUT=1 only)
//       (hit x, hit y in pixels, GLINT_SSSR_RAY_* class, iterations)
//   void   GLINT_SSSR_StoreRay(int2 pixel, float4 directionAndPdf);   (GLINT_SSSR_STORE_RAY=1 only)
//       the sampled direction (world, unit) and its density per steradian (bias-free VNDF pdf,
//       finite, > 0), written to the pixel and to its copies like the radiance; read by the
//       reflections denoiser's ratio-estimator path
//
// Entry: from main, GLINT_SSSR_Intersect(c, SV_GroupIndex, rayIndex), with
//   rayIndex = (SV_GroupID.y * GLINT_SSSR_GROUPS_PER_ROW + SV_GroupID.x) * GLINT_SSSR_RAYS_PER_GROUP
//              + SV_GroupIndex
// and c the GLINT_SssrConstants (glint_sssr_constants.h; filled by host/src/core/sssr_passes.cpp)
// declared as  cbuffer MyConstants : register(b0) { GLINT_SssrConstants c; };  : glslang
// rejects a ConstantBuffer<GLINT_SssrConstants> passed here ("no matching overloaded function");
// the cbuffer form compiles with DXC (DXIL and SPIR-V) and glslang. Guide: docs/integration.md.
//
// Dispatch: [numthreads(64, 1, 1)] in every variant (thickness-aware, debug, stored rays, 16-bit
// storage), indirect from the arguments buffer at byte 0: (min(g, 1024), ceil(g / 1024), 1)
// groups for g = ceil(rays / 64); ray index = (group.y * 1024 + group.x) * 64 + thread.
// The low-occupancy exit counts the group's live rays in groupshared memory every
// GLINT_SSSR_OCCUPANCY_INTERVAL iterations, so it means the same on 8-, 32- and 64-wide
// hardware (docs/conventions.md, defect SS2); every barrier is in group-uniform control flow.
#ifndef GLINT_SSSR_INTERSECT_HLSLI
#define GLINT_SSSR_INTERSECT_HLSLI

#include "glint/sssr/glint_sssr_common.hlsli"
#include "glint/common/glint_ggx.hlsli"

#ifndef GLINT_SSSR_THICKNESS_AWARE
#define GLINT_SSSR_THICKNESS_AWARE 0
#endif
#ifndef GLINT_SSSR_DEBUG_OUTPUT
#define GLINT_SSSR_DEBUG_OUTPUT 0
#endif
#ifndef GLINT_SSSR_STORE_RAY
#define GLINT_SSSR_STORE_RAY 0
#endif
#define GLINT_SSSR_OCCUPANCY_INTERVAL 8u
#define GLINT_SSSR_BIG 3.0e38

float GLINT_SSSR_LoadDepth(int2 texel, int mip);
#if GLINT_SSSR_THICKNESS_AWARE
float GLINT_SSSR_LoadFarthestDepth(int2 texel, int mip);
#endif
float3 GLINT_SSSR_LoadNormal(int2 pixel);
float GLINT_SSSR_LoadRoughness(int2 pixel);
float2 GLINT_SSSR_LoadBlueNoise(int2 pixel);
float3 GLINT_SSSR_LoadColor(int2 pixel);
float3 GLINT_SSSR_SampleColor(float2 uv);
float2 GLINT_SSSR_LoadMotion(int2 pixel);
float3 GLINT_SSSR_SampleEnvironment(float3 worldDirection, float lod);
uint GLINT_SSSR_LoadRayCount();
uint GLINT_SSSR_LoadRay(uint index);
void GLINT_SSSR_StoreRadiance(int2 pixel, float4 radianceAndHitDistance);
void GLINT_SSSR_StoreConfidence(int2 pixel, float confidence);
#if GLINT_SSSR_DEBUG_OUTPUT
void GLINT_SSSR_StoreRayInfo(int2 pixel, float4 info);
#endif
#if GLINT_SSSR_STORE_RAY
void GLINT_SSSR_StoreRay(int2 pixel, float4 directionAndPdf);
#endif

// Live-ray counters, three so that one barrier per interval suffices: slot i is counted in
// interval i, read after its barrier, and reset in interval i + 2 (before that interval's
// barrier, after every reader of interval i - 1 has passed the previous one).
groupshared uint g_glint_sssr_live[3];

// A ray in trace space: xy in pixels, z device depth; points are origin + t direction.
struct GLINT_SSSR_Ray
{
    float3 origin;
    float3 direction;
    float3 inverseDirection; // per-component; BIG where the component is 0 (never used there)
    float tEnd;              // the segment is clipped to the screen and to [0, 1]
    bool movingAway;         // depth increases away from the camera along the ray
};

struct GLINT_SSSR_TraversalState
{
    float t;
    int level;
    uint iterations;
    uint rayClass; // GLINT_SSSR_RAY_* once finished
    bool live;
};

// Depth used by the traversal: sanitized exactly as the pyramid sanitizes its inputs
// (docs/depth_pyramid.md), so that level 0 and the coarse levels stay conservative together.
float GLINT_SSSR_TraversalDepth(GLINT_SssrConstants c, int2 texel, int mip)
{
    // The last texel of level k is (size - 1) >> k (levels are ceil-halved).
    int2 lastTexel = int2((c.inputSize - 1u) >> uint(mip));
    float depth = GLINT_SSSR_LoadDepth(clamp(texel, int2(0, 0), lastTexel), mip);
    if (!GLINT_IsFinite(depth))
        return GLINT_SSSR_FarDepth(GLINT_SSSR_Reversed(c));
    return depth < 1.17549435e-38 ? 0.0 : min(depth, 1.0);
}

float GLINT_SSSR_FarthestDepth(GLINT_SssrConstants c, int2 texel, int mip)
{
#if GLINT_SSSR_THICKNESS_AWARE
    if (mip > 0)
        return GLINT_SSSR_LoadFarthestDepth(clamp(texel, int2(0, 0), int2((c.inputSize - 1u) >> uint(mip))), mip);
#endif
    return GLINT_SSSR_TraversalDepth(c, texel, mip);
}

float GLINT_SSSR_Thickness(GLINT_SssrConstants c, float surfaceViewDepth)
{
    return max(c.thickness * surfaceViewDepth, c.thicknessFloor);
}

// t of the exit through the current cell's far x and y planes (with a small overshoot so the
// next cell is entered for certain).
float GLINT_SSSR_CellExit(GLINT_SSSR_Ray ray, float2 cell, float cellSize, float2 overshoot)
{
    float2 stepOut = float2(ray.direction.x > 0.0 ? 1.0 : 0.0, ray.direction.y > 0.0 ? 1.0 : 0.0);
    float2 boundary = (cell + stepOut) * cellSize + overshoot;
    float tx = ray.direction.x != 0.0 ? (boundary.x - ray.origin.x) * ray.inverseDirection.x : GLINT_SSSR_BIG;
    float ty = ray.direction.y != 0.0 ? (boundary.y - ray.origin.y) * ray.inverseDirection.y : GLINT_SSSR_BIG;
    return min(tx, ty);
}

// One traversal step (docs/sssr.md, "Intersection": Traversal).
void GLINT_SSSR_Step(GLINT_SssrConstants c, GLINT_SSSR_Ray ray, int finestLevel, float2 overshoot,
                     inout GLINT_SSSR_TraversalState state)
{
    bool reversed = GLINT_SSSR_Reversed(c);
    float3 position = ray.origin + state.t * ray.direction;
    // Cells are powers of two: scaling by the exact reciprocal avoids a division per step.
    float cellSize = asfloat(uint(127 + state.level) << 23);
    float2 cellFloat = floor(position.xy * asfloat(uint(127 - state.level) << 23));
    int2 cell = int2(cellFloat);
    float surface = GLINT_SSSR_TraversalDepth(c, cell, state.level);
    float tSide = GLINT_SSSR_CellExit(ray, cellFloat, cellSize, overshoot);
    state.iterations += 1;
    if (GLINT_SSSR_Closer(position.z, surface, reversed))
    {
        float tPlane = ray.movingAway ? (surface - ray.origin.z) * ray.inverseDirection.z : GLINT_SSSR_BIG;
        if (tPlane < tSide)
        {
            state.t = max(state.t, tPlane); // reaches the cell's closest plane inside the cell
            state.level -= 1;
        }
        else
        {
            state.t = tSide;
            state.level = min(state.level + 1, GLINT_SSSR_PYRAMID_LEVELS - 1);
        }
    }
    else
    {
#if GLINT_SSSR_THICKNESS_AWARE
        if ((c.flags & GLINT_SSSR_FLAG_THICKNESS_AWARE) != 0)
        {
            // Behind the cell's closest depth: pass behind the whole cell when even the
            // segment's closest point is farther than the cell's farthest depth plus thickness.
            float tExit = min(tSide, ray.tEnd);
            float zExit = ray.origin.z + tExit * ray.direction.z;
            float closestOfSegment = GLINT_SSSR_Closer(zExit, position.z, reversed) ? zExit : position.z;
            float farthest = GLINT_SSSR_ViewDepth(c, GLINT_SSSR_FarthestDepth(c, cell, state.level));
            float segmentViewDepth = GLINT_SSSR_ViewDepth(c, closestOfSegment);
            if (segmentViewDepth > farthest + GLINT_SSSR_Thickness(c, farthest))
            {
                state.t = tSide;
                return;
            }
        }
#endif
        state.level -= 1;
    }
    if (state.level < finestLevel)
    {
        state.live = false;
        state.rayClass = GLINT_SSSR_RAY_HIT;
    }
    else if (state.t > ray.tEnd)
    {
        state.live = false;
        state.rayClass = GLINT_SSSR_RAY_ESCAPED;
    }
}

// The screen-space segment of a view-space ray (docs/sssr.md, "Intersection": Ray setup;
// docs/conventions.md §1.2 and defect SS3): the end stays in front of the near plane for rays
// toward the camera, lies on the far plane (or the vanishing point for an infinite one)
// otherwise, and the parameter range is clipped to the screen.
GLINT_SSSR_Ray GLINT_SSSR_SetupRay(GLINT_SssrConstants c, uint2 pixel, float depth, float3 viewPosition,
                                   float3 viewDirection)
{
    float4 clipPosition = GLINT_SSSR_Mul(c.clipFromView, float4(viewPosition, 1.0));
    float4 clipDirection = GLINT_SSSR_Mul(c.clipFromView, float4(viewDirection, 0.0));
    float4 clipEnd;
    if (clipDirection.w < 0.0)
    {
        float length = max(clipPosition.w - c.nearPlane, 0.0) / -clipDirection.w * (1.0 - 1e-3);
        clipEnd = clipPosition + length * clipDirection;
    }
    else if (c.farPlane <= 0.0 && clipDirection.w > 1e-6)
    {
        clipEnd = clipDirection; // the vanishing point
    }
    else
    {
        float length = clipDirection.w > 1e-6 ? max(c.farPlane - clipPosition.w, 0.0) / clipDirection.w
                                              : 1e4 * max(clipPosition.w, c.nearPlane);
        clipEnd = clipPosition + length * clipDirection;
    }
    float3 ndcEnd = clipEnd.xyz / clipEnd.w;
    float2 size = float2(c.inputSize);
    GLINT_SSSR_Ray ray;
    ray.origin = float3(float2(pixel) + 0.5, depth);
    ray.direction = float3(GLINT_SSSR_UvFromNdc(c, ndcEnd.xy) * size, ndcEnd.z) - ray.origin;
    ray.inverseDirection = float3(ray.direction.x != 0.0 ? 1.0 / ray.direction.x : GLINT_SSSR_BIG,
                                  ray.direction.y != 0.0 ? 1.0 / ray.direction.y : GLINT_SSSR_BIG,
                                  ray.direction.z != 0.0 ? 1.0 / ray.direction.z : GLINT_SSSR_BIG);
    float tEnd = 1.0;
    if (ray.direction.x > 0.0)
        tEnd = min(tEnd, (size.x - ray.origin.x) * ray.inverseDirection.x);
    if (ray.direction.x < 0.0)
        tEnd = min(tEnd, -ray.origin.x * ray.inverseDirection.x);
    if (ray.direction.y > 0.0)
        tEnd = min(tEnd, (size.y - ray.origin.y) * ray.inverseDirection.y);
    if (ray.direction.y < 0.0)
        tEnd = min(tEnd, -ray.origin.y * ray.inverseDirection.y);
    ray.tEnd = GLINT_FiniteOr(tEnd, 0.0);
    ray.movingAway = GLINT_SSSR_Reversed(c) ? ray.direction.z < 0.0 : ray.direction.z > 0.0;
    return ray;
}

// The depth slope per pixel along `axis` when the texel lies on a plane along it: device depth
// is affine in screen space on a plane, so both one-sided differences agree (within 5 %). 0 at
// depth edges, curvature, the image border and next to the background. The smaller one-sided
// difference taken everywhere would accept wrong hits at silhouettes (docs/sssr.md, "Accuracy
// on simulated scenes").
float GLINT_SSSR_ConsistentSlope(GLINT_SssrConstants c, int2 texel, int2 axis, float centre)
{
    int2 last = int2(c.inputSize) - 1;
    if (any(texel + axis > last) || any(texel - axis < 0))
        return 0.0;
    float after = GLINT_SSSR_LoadDepth(texel + axis, 0);
    float before = GLINT_SSSR_LoadDepth(texel - axis, 0);
    bool reversed = GLINT_SSSR_Reversed(c);
    if (GLINT_SSSR_IsBackground(after, reversed) || GLINT_SSSR_IsBackground(before, reversed))
        return 0.0;
    float forward = after - centre;
    float backward = centre - before;
    return abs(forward - backward) <= 0.05 * max(abs(forward), abs(backward)) ? 0.5 * (forward + backward) : 0.0;
}

float GLINT_SSSR_Vignette(GLINT_SssrConstants c, float2 uv)
{
    float2 fade = 0.05 * float2(float(c.inputSize.y) * c.inverseInputSize.x, 1.0);
    float2 border = smoothstep(float2(0.0, 0.0), fade, uv) * (1.0 - smoothstep(1.0 - fade, float2(1.0, 1.0), uv));
    return border.x * border.y;
}

// A GGX sample around n for view v; below-horizon directions are resampled once with a
// toroidally shifted blue-noise pair, then replaced by the mirror direction (docs/conventions.md,
// defect SS10).
float3 GLINT_SSSR_SampleDirection(GLINT_SssrConstants c, int2 pixel, float3 n, float3 v, float alpha,
                                  out float NdotH)
{
    NdotH = 1.0;
    if (alpha < c.mirrorThreshold)
        return 2.0 * dot(n, v) * n - v; // mirrors need no noise
    float3 t, b;
    GLINT_GGX_TangentFrame(n, t, b);
    float3 localView = float3(dot(v, t), dot(v, b), dot(v, n));
    for (uint attempt = 0; attempt < 2; ++attempt)
    {
        float2 u = GLINT_SSSR_LoadBlueNoise(pixel + int2(attempt * 64u, attempt * 37u));
        float3 h = GLINT_GGX_SampleVndf(localView, alpha, u, c.importanceSampleBias);
        float3 l = 2.0 * dot(localView, h) * h - localView;
        if (l.z > 1e-4)
        {
            NdotH = h.z;
            return l.x * t + l.y * b + l.z * n;
        }
    }
    return 2.0 * dot(n, v) * n - v;
}

// The reflection sample of a listed pixel: its surface and the GGX direction drawn from this
// frame's blue noise (the same for the screen-space march and, in the hybrid, the ray tracer).
struct GLINT_SSSR_PixelSample
{
    float depth;
    float alpha;
    float3 viewPosition;
    float3 normal;    // world, bent toward the view
    float3 view;      // world, unit, from the surface toward the eye
    float NdotV;
    float NdotH;
    float3 direction; // world, unit
};

GLINT_SSSR_PixelSample GLINT_SSSR_SamplePixel(GLINT_SssrConstants c, uint2 pixel)
{
    GLINT_SSSR_PixelSample s;
    int2 ipixel = int2(pixel);
    float2 uv = (float2(pixel) + 0.5) * c.inverseInputSize;
    s.depth = GLINT_SSSR_LoadDepth(ipixel, 0);
    float3 normal = GLINT_SSSR_UnpackNormal(c, GLINT_SSSR_LoadNormal(ipixel));
    s.alpha = clamp(GLINT_FiniteOr(GLINT_SSSR_LoadRoughness(ipixel), 1.0), 0.0, 1.0);
    s.viewPosition = GLINT_SSSR_ViewPosition(c, uv, s.depth);
    s.view = -normalize(GLINT_SSSR_MulDirection(c.worldFromView, s.viewPosition));
    s.normal = GLINT_GGX_BendNormalTowardView(normal, s.view);
    s.NdotV = dot(s.normal, s.view);
    s.NdotH = 1.0;
    s.direction = GLINT_SSSR_SampleDirection(c, ipixel, s.normal, s.view, s.alpha, s.NdotH);
    return s;
}

// One traced ray's result, stored by GLINT_SSSR_StoreResult at its pixel and its quad copies.
struct GLINT_SSSR_RayResult
{
    bool valid;
    uint entry;        // the ray-list entry (pixel and copy flags)
    float4 result;     // radiance, world hit distance (GLINT_SSSR_MISS_DISTANCE: none)
    float confidence;  // of the screen-space hit, 0 when there is none
    float alpha;
    float4 sampledRay; // direction and bias-free pdf (stored with GLINT_SSSR_STORE_RAY)
    float4 info;       // hit x, hit y, class, iterations (stored with GLINT_SSSR_DEBUG_OUTPUT)
};

// Traces the ray of list entry `entry` (when `valid`). Every thread of the group calls it: it
// synchronizes the group (all its barriers are before any thread returns). The hit's
// thickness is SSSR's times (1 + thicknessGrowth.x alpha) plus thicknessGrowth.y times the ray's
// view-space length to the hit; SSSR passes (0, 0), the hybrid its growth settings.
GLINT_SSSR_RayResult GLINT_SSSR_TraceEntry(GLINT_SssrConstants c, uint groupIndex, bool valid, uint entry,
                                           float2 thicknessGrowth)
{
    GLINT_SSSR_RayResult r = (GLINT_SSSR_RayResult)0;
    r.valid = false;
    r.entry = entry;
    if (groupIndex == 0)
    {
        g_glint_sssr_live[0] = 0;
        g_glint_sssr_live[1] = 0;
        g_glint_sssr_live[2] = 0;
    }
    bool reversed = GLINT_SSSR_Reversed(c);
    uint2 pixel = GLINT_SSSR_UnpackRayPixel(entry);
    int2 ipixel = int2(pixel);
    float2 uv = (float2(pixel) + 0.5) * c.inverseInputSize;

    GLINT_SSSR_TraversalState state;
    state.t = 0.0;
    state.level = 0;
    state.iterations = 0;
    state.rayClass = GLINT_SSSR_RAY_DEGENERATE;
    state.live = false;
    GLINT_SSSR_Ray ray = (GLINT_SSSR_Ray)0;
    float3 viewPosition = float3(0.0, 0.0, 1.0);
    float3 worldDirection = float3(0.0, 0.0, 1.0);
    float3 view = float3(0.0, 0.0, 1.0);
    float NdotV = 1.0;
    float NdotH = 1.0;
    float alpha = 0.0;
    bool mirror = true;
    int finestLevel = 0;
    float2 overshoot = float2(0.0, 0.0);
    if (valid)
    {
        GLINT_SSSR_PixelSample sample = GLINT_SSSR_SamplePixel(c, pixel);
        float depth = sample.depth;
        alpha = sample.alpha;
        mirror = alpha < c.mirrorThreshold;
        viewPosition = sample.viewPosition;
        view = sample.view;
        NdotV = sample.NdotV;
        NdotH = sample.NdotH;
        worldDirection = sample.direction;
        ray = GLINT_SSSR_SetupRay(c, pixel, depth, viewPosition, GLINT_SSSR_MulDirection(c.viewFromWorld, worldDirection));
        finestLevel = mirror ? 0 : int(min(c.mostDetailedMip, uint(GLINT_SSSR_PYRAMID_LEVELS - 1)));
        float epsilon = 0.005 * float(1u << uint(finestLevel));
        overshoot = float2(ray.direction.x >= 0.0 ? epsilon : -epsilon, ray.direction.y >= 0.0 ? epsilon : -epsilon);
        // A ray that moves less than 1/100 pixel over its whole segment makes no screen progress.
        bool degenerate = !(dot(ray.direction.xy, ray.direction.xy) >= 1e-4) || GLINT_SSSR_IsBackground(depth, reversed);
        if (!degenerate)
        {
            // Initial advance out of the origin's own cell, with no depth test.
            float finestCell = float(1u << uint(finestLevel));
            state.t = GLINT_SSSR_CellExit(ray, floor(ray.origin.xy / finestCell), finestCell, overshoot);
            state.level = finestLevel;
            state.live = state.t <= ray.tEnd;
            state.rayClass = state.live ? GLINT_SSSR_RAY_BUDGET : GLINT_SSSR_RAY_ESCAPED;
        }
    }
    GroupMemoryBarrierWithGroupSync();

    if (c.minActiveRays == 0)
    {
        // No occupancy exit: every ray marches on its own, with no group synchronization.
        for (uint i = 0; i < c.maxIterations && state.live; ++i)
            GLINT_SSSR_Step(c, ray, finestLevel, overshoot, state);
    }
    else
    {
        // minActiveRays is uniform, so this branch and every barrier in it are group-uniform.
        uint interval = 0;
        for (uint start = 0; start < c.maxIterations; start += GLINT_SSSR_OCCUPANCY_INTERVAL)
        {
            uint stop = min(start + GLINT_SSSR_OCCUPANCY_INTERVAL, c.maxIterations);
            for (uint i = start; i < stop && state.live; ++i)
                GLINT_SSSR_Step(c, ray, finestLevel, overshoot, state);
            uint slot = interval % 3u;
            if (groupIndex == 0)
                g_glint_sssr_live[(interval + 1u) % 3u] = 0;
            if (state.live)
                InterlockedAdd(g_glint_sssr_live[slot], 1u);
            GroupMemoryBarrierWithGroupSync();
            uint live = g_glint_sssr_live[slot];
            interval += 1;
            if (live == 0)
                break;
            // Stragglers: non-mirror rays stop when few of the group are still marching.
            if (live <= c.minActiveRays && state.live && !mirror)
            {
                state.live = false;
                state.rayClass = GLINT_SSSR_RAY_OCCUPANCY;
            }
        }
    }
    if (!valid)
        return r;
    // A ray still marching here ran out of budget; only a completed descent is a hit
    // (docs/conventions.md, defect SS1).

    float3 hit = ray.origin + state.t * ray.direction;
    float2 hitUv = hit.xy * c.inverseInputSize;
    int2 hitPixel = clamp(int2(floor(hit.xy)), int2(0, 0), int2(c.inputSize) - 1);
    float confidence = 0.0;
    float3 hitColor = float3(0.0, 0.0, 0.0);
    if (state.rayClass == GLINT_SSSR_RAY_HIT)
    {
        float hitDepth = GLINT_SSSR_LoadDepth(hitPixel, 0);
        float3 hitNormal = GLINT_SSSR_UnpackNormal(c, GLINT_SSSR_LoadNormal(hitPixel));
        bool advanced = any(abs(hit.xy - ray.origin.xy) >= 2.0);
        if (any(hitUv < 0.0) || any(hitUv > 1.0) || !advanced || GLINT_SSSR_IsBackground(hitDepth, reversed) ||
            dot(hitNormal, hitNormal) == 0.0)
            state.rayClass = GLINT_SSSR_RAY_REJECTED;
        else if (dot(hitNormal, worldDirection) > 0.0)
            state.rayClass = GLINT_SSSR_RAY_BEHIND;
        else
        {
            // The gap between the ray and the surface, under two models of the depth texel,
            // keeping the smaller: a flat box at the texel's depth (the traversal's own model,
            // exact for hits on a cell's closest plane), and the texel's plane where the depth is
            // planar across it. With the box alone, a correct hit that enters a texel of a wall
            // seen at a grazing angle through its side is half a texel of depth slope away and
            // loses confidence (stripes on the mirror corridor's walls).
            float surface = GLINT_SSSR_ViewDepth(c, hitDepth);
            float rayDepth = GLINT_SSSR_ViewDepth(c, hit.z);
            float gap = abs(rayDepth - surface);
            float2 slope = float2(GLINT_SSSR_ConsistentSlope(c, hitPixel, int2(1, 0), hitDepth),
                                  GLINT_SSSR_ConsistentSlope(c, hitPixel, int2(0, 1), hitDepth));
            float planeDepth = hitDepth + dot(slope, hit.xy - (float2(hitPixel) + 0.5));
            gap = min(gap, abs(rayDepth - GLINT_SSSR_ViewDepth(c, planeDepth)));
            gap = GLINT_FiniteOr(gap, 3.0e38);
            float thickness = GLINT_SSSR_Thickness(c, surface);
            if (any(thicknessGrowth != 0.0))
            {
                float rayLength = length(GLINT_SSSR_ViewPosition(c, hitUv, hit.z) - viewPosition);
                thickness = thickness * (1.0 + thicknessGrowth.x * alpha) +
                            thicknessGrowth.y * GLINT_FiniteOr(rayLength, 0.0);
            }
            float fit = 1.0 - smoothstep(0.0, thickness, gap);
            float vignette = GLINT_SSSR_Vignette(c, hitUv);
            if ((c.flags & GLINT_SSSR_FLAG_PREVIOUS_FRAME_COLOR) != 0)
            {
                float2 motion = GLINT_SSSR_LoadMotion(hitPixel) * c.motionScale;
                float2 previousUv = hitUv + float2(GLINT_FiniteOr(motion.x, 1e9), GLINT_FiniteOr(motion.y, 1e9));
                bool onScreen = all(previousUv >= 0.0) && all(previousUv <= 1.0);
                vignette = onScreen ? min(vignette, GLINT_SSSR_Vignette(c, previousUv)) : 0.0;
                hitColor = onScreen ? GLINT_SSSR_SampleColor(previousUv) : float3(0.0, 0.0, 0.0);
            }
            else
            {
                hitColor = GLINT_SSSR_LoadColor(hitPixel);
            }
            confidence = vignette * fit * fit;
            // Non-finite hit colour is not evidence: fall back to the environment.
            if (!GLINT_IsFinite(hitColor.x + hitColor.y + hitColor.z))
                confidence = 0.0;
        }
    }
    // Fade to the environment over the band below the roughness threshold, so that shading
    // does not jump where classification stops tracing (docs/conventions.md, defect SS8).
    if (!mirror && c.roughnessFadeBand > 0.0)
        confidence *= GLINT_Saturate((c.roughnessThreshold - alpha) / c.roughnessFadeBand);

    float3 environment = float3(0.0, 0.0, 0.0);
    if (confidence < 1.0)
    {
        float lod = GLINT_SSSR_EnvironmentLod(c, GLINT_GGX_ReflectionPdf(NdotV, NdotH, alpha));
        environment = GLINT_SSSR_SanitizeRadiance(GLINT_SSSR_SampleEnvironment(worldDirection, lod) * c.iblFactor);
    }
    float3 radiance = GLINT_SSSR_SanitizeRadiance(lerp(environment, hitColor, confidence));
    float distance = GLINT_SSSR_MISS_DISTANCE;
    if (confidence > 0.0)
        distance = min(length(GLINT_SSSR_ViewPosition(c, hitUv, hit.z) - viewPosition), GLINT_SSSR_MISS_DISTANCE);
    float4 result = float4(radiance, GLINT_FiniteOr(distance, GLINT_SSSR_MISS_DISTANCE));
    confidence = GLINT_FiniteOr(confidence, 0.0);

    r.valid = true;
    r.result = result;
    r.confidence = confidence;
    r.alpha = alpha;
    // The sample's own density (the one the environment LOD uses), bias-free even with the
    // importance-sample bias (reference: the ratio estimator stays deliberately biased). A copy
    // carries its donor's ray: the copied radiance is that ray's sample.
    float pdf = GLINT_GGX_ReflectionPdf(NdotV, NdotH, alpha);
    r.sampledRay = float4(worldDirection, clamp(GLINT_FiniteOr(pdf, 3.0e38), 1e-30, 3.0e38));
    r.info = float4(hit.xy, float(state.rayClass), float(state.iterations));
    return r;
}

// Writes `result` and `confidence` (and the stored ray and debug info of the permutations) to
// the entry's pixel and to the quad neighbours its copy flags name.
void GLINT_SSSR_StoreAt(uint2 pixel, float4 result, float confidence, GLINT_SSSR_RayResult r)
{
    GLINT_SSSR_StoreRadiance(int2(pixel), result);
    GLINT_SSSR_StoreConfidence(int2(pixel), confidence);
#if GLINT_SSSR_STORE_RAY
    GLINT_SSSR_StoreRay(int2(pixel), r.sampledRay);
#endif
}

void GLINT_SSSR_StoreResult(uint entry, float4 result, float confidence, GLINT_SSSR_RayResult r)
{
    uint2 pixel = GLINT_SSSR_UnpackRayPixel(entry);
    GLINT_SSSR_StoreAt(pixel, result, confidence, r);
    if ((entry & GLINT_SSSR_RAY_COPY_H) != 0)
        GLINT_SSSR_StoreAt(pixel ^ uint2(1, 0), result, confidence, r);
    if ((entry & GLINT_SSSR_RAY_COPY_V) != 0)
        GLINT_SSSR_StoreAt(pixel ^ uint2(0, 1), result, confidence, r);
    if ((entry & GLINT_SSSR_RAY_COPY_D) != 0)
        GLINT_SSSR_StoreAt(pixel ^ uint2(1, 1), result, confidence, r);
#if GLINT_SSSR_DEBUG_OUTPUT
    GLINT_SSSR_StoreRayInfo(int2(pixel), r.info);
#endif
}

void GLINT_SSSR_Intersect(GLINT_SssrConstants c, uint groupIndex, uint rayIndex)
{
    bool valid = rayIndex < GLINT_SSSR_LoadRayCount();
    // Not ?:, which evaluates both operands in HLSL: the load must not run past the ray count.
    uint entry = 0u;
    if (valid)
        entry = GLINT_SSSR_LoadRay(rayIndex);
    GLINT_SSSR_RayResult r = GLINT_SSSR_TraceEntry(c, groupIndex, valid, entry, float2(0.0, 0.0));
    if (r.valid)
        GLINT_SSSR_StoreResult(r.entry, r.result, r.confidence, r);
}

#endif // GLINT_SSSR_INTERSECT_HLSLI
