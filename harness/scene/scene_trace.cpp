#include "scene/scene_trace.h"

#include <algorithm>
#include <cmath>

namespace glint::scene {
namespace {

float dot3(const float a[3], const float b[3]) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
void cross3(const float a[3], const float b[3], float out[3]) {
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

// Slab test; the entry distance or a negative value when the box is missed within tMax.
float intersectBox(const shaders::SceneBvhNode& node, const Ray& ray, const float inv[3]) {
    const float lo[3] = {node.boundsMin.x, node.boundsMin.y, node.boundsMin.z};
    const float hi[3] = {node.boundsMax.x, node.boundsMax.y, node.boundsMax.z};
    float tNear = 0.0f, tFar = ray.tMax;
    for (int k = 0; k < 3; ++k) {
        const float a = (lo[k] - ray.origin[k]) * inv[k];
        const float b = (hi[k] - ray.origin[k]) * inv[k];
        // fmin/fmax drop a NaN (0 * inf for a ray inside a flat slab), keeping the other bound.
        tNear = std::fmax(tNear, std::fmin(a, b));
        tFar = std::fmin(tFar, std::fmax(a, b));
    }
    return tNear <= tFar ? tNear : -1.0f;
}

template <bool kAny> Hit traverse(const Bvh& bvh, const Ray& ray) {
    Hit best;
    float tMax = ray.tMax;
    const float inv[3] = {1.0f / ray.direction[0], 1.0f / ray.direction[1], 1.0f / ray.direction[2]};
    std::uint32_t stack[GLINT_SCENE_STACK_SIZE];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const shaders::SceneBvhNode& node = bvh.nodes[stack[--top]];
        Ray bounded = ray;
        bounded.tMax = tMax;
        if (intersectBox(node, bounded, inv) < 0.0f) continue;
        if (node.count > 0 || node.first == 0) {
            for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
                const float t = intersectPrimitive(bvh.primitives[i], bounded);
                if (t > 0.0f && t < tMax) {
                    tMax = t;
                    best = {t, i};
                    if (kAny) return best;
                }
            }
        } else {
            stack[top++] = node.first;
            stack[top++] = node.first + 1;
        }
    }
    return best;
}

} // namespace

float intersectPrimitive(const shaders::ScenePrimitive& p, const Ray& ray) {
    if (p.kind == GLINT_SCENE_PRIM_SPHERE) {
        const float oc[3] = {ray.origin[0] - p.p0.x, ray.origin[1] - p.p0.y, ray.origin[2] - p.p0.z};
        const float a = dot3(ray.direction, ray.direction);
        const float b = dot3(oc, ray.direction);
        const float c = dot3(oc, oc) - p.p1.x * p.p1.x;
        const float disc = b * b - a * c;
        if (disc < 0.0f) return -1.0f;
        const float s = std::sqrt(disc);
        float t = (-b - s) / a;
        if (!(t > 0.0f)) t = (-b + s) / a; // origin inside the sphere
        return (t > 0.0f && t < ray.tMax) ? t : -1.0f;
    }
    // Möller–Trumbore, two-sided.
    const float e1[3] = {p.p1.x - p.p0.x, p.p1.y - p.p0.y, p.p1.z - p.p0.z};
    const float e2[3] = {p.p2.x - p.p0.x, p.p2.y - p.p0.y, p.p2.z - p.p0.z};
    float pv[3];
    cross3(ray.direction, e2, pv);
    const float det = dot3(e1, pv);
    if (std::fabs(det) < 1e-20f) return -1.0f;
    const float invDet = 1.0f / det;
    const float tv[3] = {ray.origin[0] - p.p0.x, ray.origin[1] - p.p0.y, ray.origin[2] - p.p0.z};
    const float u = dot3(tv, pv) * invDet;
    if (u < 0.0f || u > 1.0f) return -1.0f;
    float qv[3];
    cross3(tv, e1, qv);
    const float v = dot3(ray.direction, qv) * invDet;
    if (v < 0.0f || u + v > 1.0f) return -1.0f;
    const float t = dot3(e2, qv) * invDet;
    return (t > 0.0f && t < ray.tMax) ? t : -1.0f;
}

Hit traceClosest(const Bvh& bvh, const Ray& ray) {
    return traverse<false>(bvh, ray);
}

bool traceAny(const Bvh& bvh, const Ray& ray) {
    return traverse<true>(bvh, ray).t > 0.0f;
}

Hit traceBruteForce(const std::vector<shaders::ScenePrimitive>& primitives, const Ray& ray) {
    Hit best;
    Ray bounded = ray;
    for (std::size_t i = 0; i < primitives.size(); ++i) {
        const float t = intersectPrimitive(primitives[i], bounded);
        if (t > 0.0f && t < bounded.tMax) {
            bounded.tMax = t;
            best = {t, static_cast<std::uint32_t>(i)};
        }
    }
    return best;
}

} // namespace glint::scene
