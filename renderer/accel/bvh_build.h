// BVH builder (host): binned surface-area-heuristic splits over primitive bounds, parallel on the CPU.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "core/aabb.h"
#include "accel/bvh_node.h"

namespace trazo {

class ThreadPool;

struct BvhBuildOptions {
    uint32_t maxLeafSize = 4;  // a hard cap: a larger node is always split
    uint32_t binCount = 16;    // centroid bins per axis, 2..kMaxBvhBins
    unsigned threads = 0;      // at most this many threads at once; 0 = all of the pool's
    ThreadPool* pool = nullptr;  // the threads to build on; null = sharedThreadPool() (core/thread_pool.h)
    // SAH: cost(node) = traversalCost + intersectionCost · Σ A(child)/A(node) · count(child); leaf = intersectionCost · count.
    float traversalCost = 1.0f;
    float intersectionCost = 1.0f;
};

constexpr uint32_t kMaxBvhBins = 64;

// For triangles, which intersectTriangleLeaf tests a whole leaf (≤ 4) at a time for about the cost of one:
// a triangle is priced at a fraction of a node visit, so the SAH fills leaves: fewer nodes, and rays visit
// fewer of them (build/bench/bvh/bvh_bench prints both).
inline BvhBuildOptions triangleBvhOptions() {
    BvhBuildOptions options;
    options.intersectionCost = 0.3f;
    return options;
}

struct Bvh {
    std::vector<BvhNode> nodes;               // nodes[0] is the root; empty for zero primitives
    std::vector<uint32_t> primitiveOrder;     // reordered position i holds original primitive primitiveOrder[i]
};

// Leaves hold ≤ maxLeafSize primitives and sit at depth ≤ kMaxBvhDepth: where SAH would go deeper, or no
// SAH split exists (all centroids equal), the node is split at the median instead. Deterministic: the
// same input and options give the same nodes whatever the thread count.
Bvh buildBvh(const std::vector<Aabb>& primitiveBounds, const BvhBuildOptions& options = {});

// The same over `count` primitives whose bounds boundsOf(i) gives (called once per primitive, from
// several threads at once: it must be safe to call concurrently), without an array of boxes.
Bvh buildBvh(uint32_t count, const std::function<Aabb(uint32_t)>& boundsOf, const BvhBuildOptions& options = {});

// The SAH cost of a built tree relative to its root's area (the figure the builder minimises greedily).
float bvhSahCost(const Bvh& bvh, const BvhBuildOptions& options = {});

// Depth of the deepest leaf (root = 0); 0 for an empty BVH.
uint32_t bvhDepth(const Bvh& bvh);

}  // namespace trazo
