// CPU ray casting over the BVH: the reference the GPU ray caster is tested against, plus a
// brute-force loop over every primitive that the BVH itself is tested against. The
// intersection routines are the same formulas as harness/shaders/scene_trace.hlsli.
#pragma once

#include "scene/scene_bvh.h"

#include <cstdint>

namespace glint::scene {

struct Ray {
    float origin[3];
    float direction[3]; // need not be normalized; t is in units of |direction|
    float tMax = 3.0e38f;
};

struct Hit {
    float t = -1.0f;             // < 0: miss
    std::uint32_t primitive = 0; // index into the (reordered) primitive array
};

// Nearest hit with t in (0, ray.tMax).
Hit traceClosest(const Bvh& bvh, const Ray& ray);
// Any hit with t in (0, ray.tMax).
bool traceAny(const Bvh& bvh, const Ray& ray);
Hit traceBruteForce(const std::vector<shaders::ScenePrimitive>& primitives, const Ray& ray);
// Ray parameter of the nearest intersection in (0, tMax), or a negative value.
float intersectPrimitive(const shaders::ScenePrimitive& primitive, const Ray& ray);

} // namespace glint::scene
