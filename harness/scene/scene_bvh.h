// Bounding volume hierarchy over world-space primitives (triangles and spheres), built on the
// CPU with binned SAH and traversed identically by the HLSL ray caster
// (harness/shaders/scene_trace.hlsli) and by the CPU reference (scene_trace.h).
#pragma once

#include "scene_constants.h"

#include <vector>

namespace glint::scene {

// The GPU layout: nodes[0] is the root; primitives are reordered so that every leaf's
// primitives are contiguous.
struct Bvh {
    std::vector<shaders::SceneBvhNode> nodes;
    std::vector<shaders::ScenePrimitive> primitives;
};

inline constexpr unsigned kMaxBvhDepth = GLINT_SCENE_STACK_SIZE - 2;
inline constexpr unsigned kMaxLeafSize = 4;

// An empty input gives one empty leaf (every ray misses).
Bvh buildBvh(std::vector<shaders::ScenePrimitive> primitives);

} // namespace glint::scene
