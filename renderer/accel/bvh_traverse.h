// BVH traversal (host and device): closest hit and any hit over a BvhNode array, the primitives tested by
// a caller-supplied leaf function. Iterative with a fixed stack; children are visited nearest first.
#pragma once

#include <cstddef>

#include "accel/bvh_node.h"
#include "accel/ray_box.h"

namespace trazo {

namespace bvh_detail {

// The slab test of ray_box.h specialised for BvhNode: the node is read as 8 floats (boundsMin at 0–2,
// boundsMax at 4–6), and which of a slab's two planes the ray crosses first is settled once per ray as a
// float index, so a box test is plain loads and arithmetic (no per-axis sign selection, no branches).
static_assert(offsetof(BvhNode, boundsMin) == 0 && offsetof(BvhNode, boundsMax) == 4 * sizeof(float),
              "intersectNode reads a BvhNode as floats: bounds at 0..2 and 4..6");

struct NodeRay {
    Vec3 origin;
    Vec3 invDirection;
    int nearX, nearY, nearZ;  // float index of the slab plane entered first; the exit plane is nearX ^ 4
};

TRAZO_HD NodeRay makeNodeRay(const Ray& ray) {
    const BoxRay b = makeBoxRay(ray);
    NodeRay r;
    r.origin = b.origin;
    r.invDirection = b.invDirection;
    // The same choice as narrowSlab: the max plane first exactly when invDirection < 0 (so −0 → −inf picks it).
    r.nearX = b.invDirection.x < 0.0f ? 4 : 0;
    r.nearY = b.invDirection.y < 0.0f ? 5 : 1;
    r.nearZ = b.invDirection.z < 0.0f ? 6 : 2;
    return r;
}

// Bit for bit intersectBounds(makeBoxRay(ray), node.boundsMin, node.boundsMax, tMin, tMax, tEntry).
TRAZO_HD bool intersectNode(const NodeRay& r, const BvhNode* node, float tMin, float tMax, float& tEntry) {
    const float* b = reinterpret_cast<const float*>(node);
    const float nearX = (b[r.nearX] - r.origin.x) * r.invDirection.x;
    const float farX = (b[r.nearX ^ 4] - r.origin.x) * r.invDirection.x;
    const float nearY = (b[r.nearY] - r.origin.y) * r.invDirection.y;
    const float farY = (b[r.nearY ^ 4] - r.origin.y) * r.invDirection.y;
    const float nearZ = (b[r.nearZ] - r.origin.z) * r.invDirection.z;
    const float farZ = (b[r.nearZ ^ 4] - r.origin.z) * r.invDirection.z;
    // The comparison order of intersectBounds: a NaN (ray on a plane it runs along) keeps the running bound.
    float t0 = nearX > tMin ? nearX : tMin;
    t0 = nearY > t0 ? nearY : t0;
    t0 = nearZ > t0 ? nearZ : t0;
    float t1 = farX < tMax ? farX : tMax;
    t1 = farY < t1 ? farY : t1;
    t1 = farZ < t1 ? farZ : t1;
    tEntry = t0;
    return t0 <= t1 * kBoxExitScale;
}

}  // namespace bvh_detail

struct BvhStackEntry {
    uint32_t node;
    float tEntry;  // lets a popped node be skipped once a closer hit is known
};

// Closest hit within (tMin, tMax). leaf(first, count, tMax) tests primitives [first, first + count), shrinks
// tMax on a closer hit and returns whether it hit. Returns whether any leaf hit; tMax is then the nearest t.
// `nodes` must hold a non-empty BVH (a BVH over zero primitives has no root: skip it).
template <class LeafFn>
TRAZO_HD bool traverseClosest(const BvhNode* nodes, const Ray& ray, float tMin, float& tMax, LeafFn&& leaf) {
    const bvh_detail::NodeRay nodeRay = bvh_detail::makeNodeRay(ray);
    float tRoot;
    if (!bvh_detail::intersectNode(nodeRay, nodes, tMin, tMax, tRoot)) return false;
    BvhStackEntry stack[kBvhStackSize];
    int size = 0;
    uint32_t index = 0;
    bool hit = false;
    for (;;) {
        const BvhNode& node = nodes[index];
        if (node.primCount == 0) {
            const uint32_t left = node.firstOrChild;
            float tLeft, tRight;
            const bool hitLeft = bvh_detail::intersectNode(nodeRay, nodes + left, tMin, tMax, tLeft);
            const bool hitRight = bvh_detail::intersectNode(nodeRay, nodes + left + 1, tMin, tMax, tRight);
            if (hitLeft && hitRight) {
                const bool rightFirst = tRight < tLeft;
                stack[size++] = {rightFirst ? left : left + 1, rightFirst ? tLeft : tRight};
                index = rightFirst ? left + 1 : left;
                continue;
            }
            if (hitLeft || hitRight) {
                index = hitLeft ? left : left + 1;
                continue;
            }
        } else if (leaf(node.firstOrChild, node.primCount, tMax)) {
            hit = true;
        }
        // Pop the nearest pending node that may still hold something closer than tMax.
        for (;;) {
            if (size == 0) return hit;
            const BvhStackEntry e = stack[--size];
            if (e.tEntry <= tMax * kBoxExitScale) {
                index = e.node;
                break;
            }
        }
    }
}

// Whether anything blocks the ray within (tMin, tMax). leaf(first, count, tMax) returns true as soon as one of
// its primitives does; traversal stops there.
template <class LeafFn>
TRAZO_HD bool traverseAny(const BvhNode* nodes, const Ray& ray, float tMin, float tMax, LeafFn&& leaf) {
    const bvh_detail::NodeRay nodeRay = bvh_detail::makeNodeRay(ray);
    float tRoot;
    if (!bvh_detail::intersectNode(nodeRay, nodes, tMin, tMax, tRoot)) return false;
    uint32_t stack[kBvhStackSize];
    int size = 0;
    uint32_t index = 0;
    for (;;) {
        const BvhNode& node = nodes[index];
        if (node.primCount == 0) {
            const uint32_t left = node.firstOrChild;
            float tLeft, tRight;
            const bool hitLeft = bvh_detail::intersectNode(nodeRay, nodes + left, tMin, tMax, tLeft);
            const bool hitRight = bvh_detail::intersectNode(nodeRay, nodes + left + 1, tMin, tMax, tRight);
            if (hitLeft && hitRight) {
                // Nearest first still pays for shadow rays: occluders near the origin are found sooner.
                const bool rightFirst = tRight < tLeft;
                stack[size++] = rightFirst ? left : left + 1;
                index = rightFirst ? left + 1 : left;
                continue;
            }
            if (hitLeft || hitRight) {
                index = hitLeft ? left : left + 1;
                continue;
            }
        } else if (leaf(node.firstOrChild, node.primCount, tMax)) {
            return true;
        }
        if (size == 0) return false;
        index = stack[--size];
    }
}

}  // namespace trazo
