// WideBvhNode: the node the kernels traverse (host and device). Four children per node, their boxes stored
// structure-of-arrays so one node's four slab tests are four-lane arithmetic (SSE on the host).
#pragma once

#include <cstdint>

#include "accel/bvh_node.h"
#include "core/aabb.h"
#include "core/hd.h"

namespace trazo {

constexpr int kBvhWidth = 4;

// A child reference: an interior node's index (relative to the root), or a leaf's primitive range packed as
// bit 31 = leaf, bits 29–30 = count − 1, bits 0–28 = first primitive (< kBvhMaxFirstPrimitive, so that no
// leaf reads as kBvhEmptyLane).
constexpr uint32_t kBvhLeafBit = 0x80000000u;
constexpr uint32_t kBvhMaxLeafSize = 4;
constexpr uint32_t kBvhMaxFirstPrimitive = (1u << 29) - 1;
// An unused lane: its box is empty (+inf, −inf), and traversal also checks the reference, because a NaN ray
// passes every slab test.
constexpr uint32_t kBvhEmptyLane = 0xffffffffu;

TRAZO_HD constexpr uint32_t bvhLeafRef(uint32_t first, uint32_t count) {
    return kBvhLeafBit | ((count - 1u) << 29) | first;
}
TRAZO_HD constexpr bool bvhIsLeaf(uint32_t ref) { return (ref & kBvhLeafBit) != 0; }
TRAZO_HD constexpr uint32_t bvhLeafFirst(uint32_t ref) { return ref & kBvhMaxFirstPrimitive; }
TRAZO_HD constexpr uint32_t bvhLeafCount(uint32_t ref) { return ((ref >> 29) & 3u) + 1u; }

// A wide node is at least one binary level, so it sits at depth ≤ kMaxBvhDepth − 1 (its leaves at ≤ 64), and
// each interior node on the way down pushes at most kBvhWidth − 1 siblings.
constexpr int kBvhStackSize = (kBvhWidth - 1) * (int)kMaxBvhDepth;

struct alignas(128) WideBvhNode {
    float bounds[3][2][kBvhWidth];  // [axis][0 = min, 1 = max][child]
    uint32_t child[kBvhWidth];      // child references (see above)
    // The binary nodes the lanes were opened from (collapseBvh), so widenBvh can regroup them as the binary tree
    // did: bits 0–1 how many lanes were opened after the first two, then two bits each for the lane opened at
    // each step (its left child stayed in it, its right child took the next lane). Traversal never reads it.
    uint32_t opened;
    uint32_t padding[kBvhWidth - 1];  // to 128 bytes: a node is two whole cache lines
};
static_assert(sizeof(WideBvhNode) == 128, "a node should fill exactly two 64-byte cache lines");

// The node the host's AVX2 and AVX-512 kernels traverse meshes over: the same layout with eight lanes (one
// 256-bit slab test per axis and plane), made from the four-wide nodes where those kernels run (widenBvh,
// accel/collapse_bvh.h); never on the device. Each is a node of the binary tree both are made from, so its tree
// is no deeper than that one (≤ kMaxBvhDepth).
constexpr int kBvh8Width = 8;
constexpr int kBvh8StackSize = (kBvh8Width - 1) * (int)kMaxBvhDepth;

struct alignas(128) WideBvhNode8 {
    float bounds[3][2][kBvh8Width];  // [axis][0 = min, 1 = max][child]
    uint32_t child[kBvh8Width];      // child references as WideBvhNode's
    uint32_t padding[kBvh8Width];    // to 256 bytes: four whole cache lines
};
static_assert(sizeof(WideBvhNode8) == 256, "an eight-wide node should fill exactly four 64-byte cache lines");

// The union of a wide node's child boxes (for the root: the whole BVH's bounds). Host code
// (accel/collapse_bvh.cpp).
Aabb wideNodeBounds(const WideBvhNode& node);

}  // namespace trazo
