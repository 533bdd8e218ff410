// BVH traversal (host and device): closest hit and any hit over a BvhNode array, the primitives tested by
// a caller-supplied leaf function. Iterative with a fixed stack; children are visited nearest first.
#pragma once

#include "accel/bvh_node.h"
#include "accel/ray_box.h"

namespace trazo {

struct BvhStackEntry {
    uint32_t node;
    float tEntry;  // lets a popped node be skipped once a closer hit is known
};

// Closest hit within (tMin, tMax). leaf(first, count, tMax) tests primitives [first, first + count), shrinks
// tMax on a closer hit and returns whether it hit. Returns whether any leaf hit; tMax is then the nearest t.
// `nodes` must hold a non-empty BVH (a BVH over zero primitives has no root: skip it).
template <class LeafFn>
TRAZO_HD bool traverseClosest(const BvhNode* nodes, const Ray& ray, float tMin, float& tMax, LeafFn&& leaf) {
    const BoxRay boxRay = makeBoxRay(ray);
    float tRoot;
    if (!intersectBounds(boxRay, nodes[0].boundsMin, nodes[0].boundsMax, tMin, tMax, tRoot)) return false;
    BvhStackEntry stack[kBvhStackSize];
    int size = 0;
    uint32_t index = 0;
    bool hit = false;
    for (;;) {
        const BvhNode& node = nodes[index];
        if (node.primCount == 0) {
            const uint32_t left = node.firstOrChild;
            float tLeft, tRight;
            const bool hitLeft = intersectBounds(boxRay, nodes[left].boundsMin, nodes[left].boundsMax, tMin, tMax, tLeft);
            const bool hitRight =
                intersectBounds(boxRay, nodes[left + 1].boundsMin, nodes[left + 1].boundsMax, tMin, tMax, tRight);
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
    const BoxRay boxRay = makeBoxRay(ray);
    float tRoot;
    if (!intersectBounds(boxRay, nodes[0].boundsMin, nodes[0].boundsMax, tMin, tMax, tRoot)) return false;
    uint32_t stack[kBvhStackSize];
    int size = 0;
    uint32_t index = 0;
    for (;;) {
        const BvhNode& node = nodes[index];
        if (node.primCount == 0) {
            const uint32_t left = node.firstOrChild;
            float tLeft, tRight;
            const bool hitLeft = intersectBounds(boxRay, nodes[left].boundsMin, nodes[left].boundsMax, tMin, tMax, tLeft);
            const bool hitRight =
                intersectBounds(boxRay, nodes[left + 1].boundsMin, nodes[left + 1].boundsMax, tMin, tMax, tRight);
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
