#include "scene/scene_bvh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace glint::scene {
namespace {

using shaders::float3;
using shaders::ScenePrimitive;

struct Box {
    float lo[3] = {std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
                   std::numeric_limits<float>::max()};
    float hi[3] = {-std::numeric_limits<float>::max(), -std::numeric_limits<float>::max(),
                   -std::numeric_limits<float>::max()};
    void grow(const float p[3]) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], p[k]);
            hi[k] = std::max(hi[k], p[k]);
        }
    }
    void grow(const Box& b) {
        grow(b.lo);
        grow(b.hi);
    }
    float area() const {
        const float dx = hi[0] - lo[0], dy = hi[1] - lo[1], dz = hi[2] - lo[2];
        return dx < 0.0f ? 0.0f : 2.0f * (dx * dy + dy * dz + dz * dx);
    }
};

Box boundsOf(const ScenePrimitive& p) {
    Box b;
    if (p.kind == GLINT_SCENE_PRIM_SPHERE) {
        const float r = p.p1.x;
        const float lo[3] = {p.p0.x - r, p.p0.y - r, p.p0.z - r};
        const float hi[3] = {p.p0.x + r, p.p0.y + r, p.p0.z + r};
        b.grow(lo);
        b.grow(hi);
    } else {
        for (const float3& v : {p.p0, p.p1, p.p2}) {
            const float q[3] = {v.x, v.y, v.z};
            b.grow(q);
        }
    }
    return b;
}

struct Item {
    Box box;
    float centre[3];
    std::uint32_t index;
};

struct Builder {
    std::vector<Item> items;
    std::vector<shaders::SceneBvhNode> nodes;

    void setBounds(std::size_t node, const Box& b) {
        nodes[node].boundsMin = {b.lo[0], b.lo[1], b.lo[2]};
        nodes[node].boundsMax = {b.hi[0], b.hi[1], b.hi[2]};
    }

    void makeLeaf(std::size_t node, std::size_t begin, std::size_t end) {
        nodes[node].first = static_cast<std::uint32_t>(begin);
        nodes[node].count = static_cast<std::uint32_t>(end - begin);
    }

    // Binned SAH (16 bins on the centroid bounds of each axis): the split minimising
    // area(left)·count(left) + area(right)·count(right), or a leaf when no split beats the
    // leaf's own cost.
    void build(std::size_t node, std::size_t begin, std::size_t end, unsigned depth) {
        Box bounds, centroids;
        for (std::size_t i = begin; i < end; ++i) {
            bounds.grow(items[i].box);
            centroids.grow(items[i].centre);
        }
        setBounds(node, bounds);
        const std::size_t n = end - begin;
        if (n <= 1 || depth >= kMaxBvhDepth) return makeLeaf(node, begin, end);

        constexpr int kBins = 16;
        float bestCost = std::numeric_limits<float>::max();
        int bestAxis = -1, bestSplit = 0;
        for (int axis = 0; axis < 3; ++axis) {
            const float lo = centroids.lo[axis], extent = centroids.hi[axis] - lo;
            if (!(extent > 0.0f)) continue;
            std::array<Box, kBins> binBox{};
            std::array<std::size_t, kBins> binCount{};
            for (std::size_t i = begin; i < end; ++i) {
                const int b =
                    std::min(kBins - 1, static_cast<int>(kBins * (items[i].centre[axis] - lo) / extent));
                binBox[static_cast<std::size_t>(b)].grow(items[i].box);
                ++binCount[static_cast<std::size_t>(b)];
            }
            std::array<float, kBins> rightCost{};
            Box right;
            std::size_t rightCount = 0;
            for (int b = kBins - 1; b > 0; --b) {
                right.grow(binBox[static_cast<std::size_t>(b)]);
                rightCount += binCount[static_cast<std::size_t>(b)];
                rightCost[static_cast<std::size_t>(b)] = right.area() * static_cast<float>(rightCount);
            }
            Box left;
            std::size_t leftCount = 0;
            for (int b = 0; b < kBins - 1; ++b) {
                left.grow(binBox[static_cast<std::size_t>(b)]);
                leftCount += binCount[static_cast<std::size_t>(b)];
                if (leftCount == 0 || leftCount == n) continue;
                const float cost =
                    left.area() * static_cast<float>(leftCount) + rightCost[static_cast<std::size_t>(b + 1)];
                if (cost < bestCost) {
                    bestCost = cost;
                    bestAxis = axis;
                    bestSplit = b;
                }
            }
        }
        const float leafCost = bounds.area() * static_cast<float>(n);
        std::size_t mid = begin;
        if (bestAxis >= 0 && (bestCost < leafCost || n > kMaxLeafSize)) {
            const float lo = centroids.lo[bestAxis], extent = centroids.hi[bestAxis] - lo;
            const auto it = std::partition(
                items.begin() + static_cast<std::ptrdiff_t>(begin),
                items.begin() + static_cast<std::ptrdiff_t>(end), [&](const Item& item) {
                    return std::min(kBins - 1, static_cast<int>(kBins * (item.centre[bestAxis] - lo) /
                                                                extent)) <= bestSplit;
                });
            mid = static_cast<std::size_t>(it - items.begin());
        } else if (n > kMaxLeafSize) {
            // All centroids coincide: split by count so that leaves stay small.
            mid = begin + n / 2;
        } else {
            return makeLeaf(node, begin, end);
        }
        const std::size_t left = nodes.size();
        nodes.emplace_back();
        nodes.emplace_back();
        nodes[node].first = static_cast<std::uint32_t>(left);
        nodes[node].count = 0;
        build(left, begin, mid, depth + 1);
        build(left + 1, mid, end, depth + 1);
    }
};

} // namespace

Bvh buildBvh(std::vector<ScenePrimitive> primitives) {
    Builder builder;
    builder.items.reserve(primitives.size());
    for (std::size_t i = 0; i < primitives.size(); ++i) {
        Item item;
        item.box = boundsOf(primitives[i]);
        for (int k = 0; k < 3; ++k) item.centre[k] = 0.5f * (item.box.lo[k] + item.box.hi[k]);
        item.index = static_cast<std::uint32_t>(i);
        builder.items.push_back(item);
    }
    builder.nodes.emplace_back();
    builder.build(0, 0, builder.items.size(), 0);
    Bvh bvh;
    bvh.nodes = std::move(builder.nodes);
    bvh.primitives.reserve(primitives.size());
    for (const Item& item : builder.items) bvh.primitives.push_back(primitives[item.index]);
    return bvh;
}

} // namespace glint::scene
