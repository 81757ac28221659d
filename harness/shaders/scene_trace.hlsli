// The simulator's ray caster: random numbers, primary rays, BVH traversal over triangles and
// spheres. Harness-only (not part of the product). The including entry declares
//   ConstantBuffer<GLINT_SceneConstants> g_scene;
//   StructuredBuffer<SceneBvhNode> g_scene_nodes;
//   StructuredBuffer<ScenePrimitive> g_scene_primitives;
// The formulas match harness/scene/scene_trace.cpp, the CPU reference.
#ifndef GLINT_SCENE_TRACE_HLSLI
#define GLINT_SCENE_TRACE_HLSLI

static const float SCENE_PI = 3.14159265358979;

// PCG output hash: good avalanche for seeding and chaining.
uint SceneHash(uint x)
{
    uint state = x * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// Per-pixel stream, different for every frame, pass and scene seed (deterministic).
uint SceneSeed(uint2 pixel, uint frameIndex, uint salt)
{
    return SceneHash(SceneHash(SceneHash(pixel.x) ^ (pixel.y * 0x9E3779B9u)) ^ SceneHash(frameIndex ^ (g_scene.seed * 0x85EBCA6Bu)) ^ salt);
}

// Uniform in [0, 1) with 24 bits.
float SceneRandom(inout uint state)
{
    state = SceneHash(state);
    return float(state >> 8) * (1.0 / 16777216.0);
}

// 1 / d without infinities: a zero component becomes a tiny one of the same sign, so the slab
// test never computes 0 * inf.
float3 SceneSafeInverse(float3 d)
{
    float3 tiny = float3(d.x < 0.0 ? -1e-30 : 1e-30, d.y < 0.0 ? -1e-30 : 1e-30, d.z < 0.0 ? -1e-30 : 1e-30);
    return 1.0 / float3(abs(d.x) < 1e-30 ? tiny.x : d.x, abs(d.y) < 1e-30 ? tiny.y : d.y, abs(d.z) < 1e-30 ? tiny.z : d.z);
}

bool SceneHitsBox(SceneBvhNode node, float3 origin, float3 invDir, float tMax)
{
    float3 a = (node.boundsMin - origin) * invDir;
    float3 b = (node.boundsMax - origin) * invDir;
    float3 lo = min(a, b);
    float3 hi = max(a, b);
    float tNear = max(max(lo.x, lo.y), max(lo.z, 0.0));
    float tFar = min(min(hi.x, hi.y), min(hi.z, tMax));
    return tNear <= tFar;
}

// Nearest t in (0, tMax) or -1.
float SceneIntersect(ScenePrimitive p, float3 origin, float3 dir, float tMax)
{
    if (p.kind == GLINT_SCENE_PRIM_SPHERE) {
        float3 oc = origin - p.p0;
        float a = dot(dir, dir);
        float b = dot(oc, dir);
        float c = dot(oc, oc) - p.p1.x * p.p1.x;
        float disc = b * b - a * c;
        if (disc < 0.0) return -1.0;
        float s = sqrt(disc);
        float t = (-b - s) / a;
        if (!(t > 0.0)) t = (-b + s) / a;
        return (t > 0.0 && t < tMax) ? t : -1.0;
    }
    float3 e1 = p.p1 - p.p0;
    float3 e2 = p.p2 - p.p0;
    float3 pv = cross(dir, e2);
    float det = dot(e1, pv);
    if (abs(det) < 1e-20) return -1.0;
    float invDet = 1.0 / det;
    float3 tv = origin - p.p0;
    float u = dot(tv, pv) * invDet;
    if (u < 0.0 || u > 1.0) return -1.0;
    float3 qv = cross(tv, e1);
    float v = dot(dir, qv) * invDet;
    if (v < 0.0 || u + v > 1.0) return -1.0;
    float t = dot(e2, qv) * invDet;
    return (t > 0.0 && t < tMax) ? t : -1.0;
}

struct SceneHit {
    float t;   // < 0: miss
    uint prim;
};

// Closest hit (anyHit = false) or the first hit found (anyHit = true) with t in (0, tMax).
SceneHit SceneTrace(float3 origin, float3 dir, float tMax, bool anyHit)
{
    SceneHit best;
    best.t = -1.0;
    best.prim = 0;
    float3 invDir = SceneSafeInverse(dir);
    uint stack[GLINT_SCENE_STACK_SIZE];
    uint top = 0;
    stack[top++] = 0;
    while (top > 0) {
        SceneBvhNode node = g_scene_nodes[stack[--top]];
        if (!SceneHitsBox(node, origin, invDir, tMax)) continue;
        if (node.count > 0 || node.first == 0) {
            for (uint i = node.first; i < node.first + node.count; ++i) {
                float t = SceneIntersect(g_scene_primitives[i], origin, dir, tMax);
                if (t > 0.0 && t < tMax) {
                    tMax = t;
                    best.t = t;
                    best.prim = i;
                    if (anyHit) return best;
                }
            }
        } else if (top + 2 <= GLINT_SCENE_STACK_SIZE) {
            stack[top++] = node.first;
            stack[top++] = node.first + 1;
        }
    }
    return best;
}

// Unit geometric normal at a hit, facing against the ray (surfaces are two-sided).
float3 SceneHitNormal(SceneHit hit, float3 origin, float3 dir)
{
    ScenePrimitive p = g_scene_primitives[hit.prim];
    float3 n = p.kind == GLINT_SCENE_PRIM_SPHERE ? (origin + dir * hit.t - p.p0) : cross(p.p1 - p.p0, p.p2 - p.p0);
    float len = length(n);
    n = len > 1e-30 ? n / len : -dir;
    return dot(n, dir) > 0.0 ? -n : n;
}

// Offset for rays leaving a surface: scaled with the magnitude of the position, as float
// rounding of the hit point is.
float3 SceneOffsetOrigin(float3 position, float3 normal)
{
    float scale = max(max(abs(position.x), abs(position.y)), max(abs(position.z), 1.0));
    return position + normal * (2e-4 * scale);
}

float2 SceneUvOfPixel(uint2 pixel)
{
    return (float2(pixel) + 0.5) / float2(g_scene.size);
}

// Screen UV of a homogeneous clip position (docs/conventions.md §1); w is kept away from zero so
// that points behind the camera still give finite values.
float2 SceneUvOfClip(float4 clip)
{
    float w = abs(clip.w) < 1e-12 ? 1e-12 : clip.w;
    float2 ndc = clip.xy / w;
    return float2(0.5 * ndc.x + 0.5, g_scene.ndcYDown != 0 ? 0.5 * ndc.y + 0.5 : 0.5 - 0.5 * ndc.y);
}

// The primary ray through a pixel centre: from the eye through the unprojected point at
// device depth 0.5 (finite for every depth convention, including reversed infinite).
void ScenePrimaryRay(uint2 pixel, out float3 origin, out float3 dir)
{
    float2 uv = SceneUvOfPixel(pixel);
    float2 ndc = float2(2.0 * uv.x - 1.0, g_scene.ndcYDown != 0 ? 2.0 * uv.y - 1.0 : 1.0 - 2.0 * uv.y);
    float4 q = SCENE_MUL(g_scene.invViewProjection, float4(ndc, 0.5, 1.0));
    origin = g_scene.eye.xyz;
    dir = normalize(q.xyz / q.w - origin);
}

// Device depth of a world point, or the background depth when it lies outside [0, 1].
float SceneDeviceDepth(float3 position, out bool inside)
{
    float4 clip = SCENE_MUL(g_scene.viewProjection, float4(position, 1.0));
    float d = clip.z / clip.w;
    inside = clip.w > 0.0 && d >= 0.0 && d <= 1.0;
    return inside ? d : g_scene.backgroundDepth;
}

// The primary ray through a pixel centre and what it hits. Returns true when the hit lies
// between the near and far planes; otherwise the pixel shows the background.
bool ScenePrimaryHit(uint2 pixel, out float3 origin, out float3 dir, out SceneHit hit)
{
    ScenePrimaryRay(pixel, origin, dir);
    hit = SceneTrace(origin, dir, 3.0e38, false);
    bool inside = false;
    if (hit.t > 0.0) SceneDeviceDepth(origin + dir * hit.t, inside);
    return inside;
}

#endif // GLINT_SCENE_TRACE_HLSLI
