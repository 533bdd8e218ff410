// Collapsing a binary BVH into the four-wide nodes the kernels traverse (host).
#pragma once

#include <vector>

#include "core/aabb.h"
#include "accel/bvh_build.h"
#include "accel/wide_bvh_node.h"

namespace trazo {

// Each wide node takes the children of a binary node and, while it has fewer than four, opens its interior
// child of largest surface area (the one a ray is most likely to enter). Leaves and the primitive order stay
// as they are. Nodes are laid out depth first, the root at 0. A binary BVH that is a single leaf becomes a
// root with one leaf child; an empty one stays empty. Needs leaves of ≤ kBvhMaxLeafSize primitives.
std::vector<WideBvhNode> collapseBvh(const Bvh& bvh);

// The eight-wide tree of a four-wide one (nodes[0] its root, `count` nodes): each eight-wide node takes a
// four-wide node's children and, while they fit in eight lanes, opens the interior child of largest surface
// area into its children. Leaves, their references and the primitive order stay as they are, so a closest-hit
// query answers the same over either tree; every node is at least as deep in the four-wide tree, so a
// traversal keeps at most kBvh8StackSize entries. Laid out depth first, the root at 0; empty for count = 0.
std::vector<WideBvhNode8> widenBvh(const WideBvhNode* nodes, size_t count);
// The same appended to `out`, its references counted from the first node appended.
//
// With `leaves`, each leaf lane names a run of the four-wide tree's leaves instead, their references appended to
// `leaves`: bvhLeafFirst is where the run starts there, bvhLeafCount its length (leaves of disjoint, ascending
// primitive ranges). A run is one leaf, or the leaves of an interior child that is left over when its node's lanes
// are filled and has only leaf children, at most `groupLeaves` of them: one lane whose leaves a ray tests
// together, instead of an eight-wide node of its own (a node visit less at the price of a wider leaf test).
void widenBvh(const WideBvhNode* nodes, size_t count, std::vector<WideBvhNode8>& out,
              std::vector<uint32_t>* leaves = nullptr, uint32_t groupLeaves = 1);

// The most entries a traversal of this BVH (nodes[0] its root, `count` nodes) keeps on its stack: each interior
// node on the way down pushes the children it enters but one, so a node needs (children − 1) above what its
// neediest interior child needs. Bounds traverseClosest and traverseAny alike; 0 for an empty BVH.
uint32_t wideBvhStackNeed(const WideBvhNode* nodes, size_t count);

// Depth of the deepest leaf below the root (a root with only leaf children: 1); 0 for an empty BVH.
uint32_t wideBvhDepth(const std::vector<WideBvhNode>& nodes);

}  // namespace trazo
