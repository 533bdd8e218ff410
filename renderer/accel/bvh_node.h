// BvhNode: one 32-byte node of the binary BVH the builder makes (host); collapse_bvh.h turns it into the
// four-wide nodes the kernels traverse.
#pragma once

#include <cstdint>

#include "core/vec3.h"

namespace trazo {

// Leaves sit at depth ≤ kMaxBvhDepth (root = depth 0); the builder guarantees it for any input.
constexpr uint32_t kMaxBvhDepth = 64;

struct BvhNode {
    Vec3 boundsMin;
    uint32_t firstOrChild;  // interior: left child (right = left + 1), relative to the root; leaf: first primitive
    Vec3 boundsMax;
    uint32_t primCount;     // 0 = interior node
};

}  // namespace trazo
