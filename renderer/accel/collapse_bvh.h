// Collapsing a binary BVH into the four-wide nodes every kernel traverses, and regrouping those into the eight-wide
// nodes the host's AVX kernels traverse meshes over (host).
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <vector>

#include "core/aabb.h"
#include "accel/bvh_build.h"
#include "accel/wide_bvh_node.h"

namespace trazo {

// The box of a wide node's child in `lane`, four- or eight-wide.
template <class Node>
Aabb laneBox(const Node& node, int lane) {
    return Aabb{Vec3(node.bounds[0][0][lane], node.bounds[1][0][lane], node.bounds[2][0][lane]),
                Vec3(node.bounds[0][1][lane], node.bounds[1][1][lane], node.bounds[2][1][lane])};
}

// The used lanes of a wide node, bit i for lane i.
template <class Node>
uint32_t usedLaneMask(const Node& node) {
    uint32_t mask = 0;
    for (int lane = 0; lane < int(sizeof(node.child) / sizeof(node.child[0])); ++lane)
        if (node.child[lane] != kBvhEmptyLane) mask |= 1u << lane;
    return mask;
}

// The union of the boxes of the node's lanes in `lanes` (bit i for lane i; empty for none). Plain min and max,
// exact in any order, where Aabb::grow would call libm's fminf and fmaxf.
template <class Node>
Aabb lanesBounds(const Node& node, uint32_t lanes) {
    if (lanes == 0) return Aabb{};
    Aabb box = laneBox(node, std::countr_zero(lanes));
    for (uint32_t m = lanes & (lanes - 1); m; m &= m - 1) {
        const int lane = std::countr_zero(m);
        for (int axis = 0; axis < 3; ++axis) {
            box.min[axis] = std::min(box.min[axis], node.bounds[axis][0][lane]);
            box.max[axis] = std::max(box.max[axis], node.bounds[axis][1][lane]);
        }
    }
    return box;
}

// The union of the boxes of a wide node's used lanes (for a root: the whole tree's bounds).
template <class Node>
Aabb usedLanesBounds(const Node& node) {
    return lanesBounds(node, usedLaneMask(node));
}

// Each wide node takes the children of a binary node and, while it has fewer than four, opens its interior
// child of largest surface area (the one a ray is most likely to enter). Leaves and the primitive order stay
// as they are. Nodes are laid out depth first, the root at 0. A binary BVH that is a single leaf becomes a
// root with one leaf child; an empty one stays empty. Needs leaves of ≤ kBvhMaxLeafSize primitives.
std::vector<WideBvhNode> collapseBvh(const Bvh& bvh);

// What widenBvh weighs: a node visit as three leaf-block tests. A node is eight slab tests, a sort and a stack; most
// block tests end at the edge functions. With 1 : 1 the trees took 15 % less cost and traced no faster; from 3 to 6
// the million-triangle sphere's rays were 4–10 % faster than the greedy trees' (bvh_bench, one thread).
constexpr double kWideNodeCost = 3.0;
constexpr double kWideBlockCost = 1.0;

// A box's surface area as widenBvh weighs it: in double, finite for any box of finite bounds (in float it may not be).
inline double wideCostArea(const Aabb& box) {
    if (box.empty()) return 0.0;
    const double x = (double)box.max.x - box.min.x, y = (double)box.max.y - box.min.y,
                 z = (double)box.max.z - box.min.z;
    return 2.0 * (x * y + y * z + z * x);
}

// The eight-wide tree of a four-wide one made by collapseBvh (nodes[0] its root, `count` nodes), as if collapsed
// from their binary tree: the lanes of each four-wide node are regrouped into the binary nodes they were opened
// from (WideBvhNode::opened), and of all eight-wide trees whose nodes are binary nodes, each node's lanes subtrees
// below it, the one of least SAH cost is made (Ylitie, Karras and Laine 2017, §4.1: dynamic programming over the
// binary nodes): Σ over nodes of area · kWideNodeCost, plus Σ over leaf lanes of area · blocks of four triangles ·
// kWideBlockCost, areas by wideCostArea. Leaves, their references and the primitive order stay as they are, so a
// closest-hit query answers the same over either tree; each node is a binary node, so a traversal keeps at most
// kBvh8StackSize entries. Laid out depth first, the root at 0; empty for count = 0. A node whose `opened` does not
// describe it is taken as flat (its lanes the binary node's children).
std::vector<WideBvhNode8> widenBvh(const WideBvhNode* nodes, size_t count);
// The same appended to `out`, its references counted from the first node appended.
//
// With `leaves`, each leaf lane names a run of the four-wide tree's leaves instead, their references appended to
// `leaves` in primitive order: bvhLeafFirst is where the run starts there, bvhLeafCount its length. A run is one
// leaf, or all the leaves of a subtree of at most `groupLeaves` (≤ kBvhMaxLeafRun) of them, weighed as its
// triangles packed four to a block (widenMeshBvhs): one lane whose leaves a ray tests together, instead of nodes of
// its own.
constexpr uint32_t kBvhMaxLeafRun = 4;  // a run's length fits a reference's count bits
void widenBvh(const WideBvhNode* nodes, size_t count, std::vector<WideBvhNode8>& out,
              std::vector<uint32_t>* leaves = nullptr, uint32_t groupLeaves = 1);

// The most entries a traversal of this BVH (nodes[0] its root, `count` nodes) keeps on its stack: each interior
// node on the way down pushes the children it enters but one, so a node needs (children − 1) above what its
// neediest interior child needs. Bounds traverseClosest and traverseAny alike; 0 for an empty BVH.
uint32_t wideBvhStackNeed(const WideBvhNode* nodes, size_t count);

// Depth of the deepest leaf below the root (a root with only leaf children: 1); 0 for an empty BVH.
uint32_t wideBvhDepth(const std::vector<WideBvhNode>& nodes);

}  // namespace trazo
