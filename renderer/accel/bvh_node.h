// BvhNode: one 32-byte node of a bounding volume hierarchy as the kernels read it (host and device).
#pragma once

#include <cstdint>

#include "core/vec3.h"

namespace trazo {

// Leaves sit at depth ≤ kMaxBvhDepth (root = depth 0); the builder guarantees it for any input.
constexpr uint32_t kMaxBvhDepth = 64;
// Traversal pushes at most one node per interior ancestor of the current node, so one entry per level.
constexpr int kBvhStackSize = (int)kMaxBvhDepth;

struct BvhNode {
    Vec3 boundsMin;
    uint32_t firstOrChild;  // interior: left child (right = left + 1), relative to the root; leaf: first primitive
    Vec3 boundsMax;
    uint32_t primCount;     // 0 = interior node
};
static_assert(sizeof(BvhNode) == 32, "two sibling nodes should share a 64-byte cache line");

}  // namespace trazo
