// BVH traversal (host and device): closest hit and any hit over a WideBvhNode array, the primitives tested
// by a caller-supplied leaf function. Iterative with a fixed stack; the children a ray enters are visited
// nearest first.
#pragma once

#include "accel/ray_box.h"
#include "accel/wide_bvh_node.h"
#include "core/host_simd.h"

namespace trazo {

namespace bvh_detail {

// The slab test of ray_box.h for a node's four children at once. Which of a slab's two planes the ray
// crosses first is settled once per ray, so a box test is plain loads and arithmetic, without branches.
struct NodeRay {
    Vec3 origin;
    Vec3 invDirection;
    int nearSide[3];  // per axis: 0 = the min plane is entered first, 1 = the max plane; the exit is 1 − it
#if TRAZO_HOST_SSE
    __m128 originLanes[3], invLanes[3];  // broadcast once per ray rather than once per node
    // Per axis, where the entry and the exit planes' four floats start in WideBvhNode::bounds (floats from
    // bounds[0][0]): no index arithmetic per node.
    int entryOffset[3], exitOffset[3];
#endif
};

TRAZO_HD_HOT NodeRay makeNodeRay(const Ray& ray) {
    const BoxRay b = makeBoxRay(ray);
    NodeRay r;
    r.origin = b.origin;
    r.invDirection = b.invDirection;
    // The same choice as narrowSlab: the max plane first exactly when invDirection < 0 (so −0 → −inf picks it).
    for (int axis = 0; axis < 3; ++axis) r.nearSide[axis] = b.invDirection[axis] < 0.0f ? 1 : 0;
#if TRAZO_HOST_SSE
    for (int axis = 0; axis < 3; ++axis) {
        r.originLanes[axis] = _mm_set1_ps(b.origin[axis]);
        r.invLanes[axis] = _mm_set1_ps(b.invDirection[axis]);
        r.entryOffset[axis] = (2 * axis + r.nearSide[axis]) * kBvhWidth;
        r.exitOffset[axis] = (2 * axis + 1 - r.nearSide[axis]) * kBvhWidth;
    }
#endif
    return r;
}

// Lane by lane, bit for bit intersectBounds(makeBoxRay(ray), child box, tMin, tMax, tEntry[lane]); bit
// `lane` of the result is set when the ray meets that box. The host's SSE version below computes the same
// IEEE operations in the same order, so both backends visit the same nodes.
TRAZO_HD unsigned intersectChildrenScalar(const NodeRay& r, const WideBvhNode& node, float tMin, float tMax,
                                          float tEntry[kBvhWidth]) {
    unsigned mask = 0;
    for (int lane = 0; lane < kBvhWidth; ++lane) {
        float t0 = tMin, t1 = tMax;
        for (int axis = 0; axis < 3; ++axis) {
            const float tNear = (node.bounds[axis][r.nearSide[axis]][lane] - r.origin[axis]) * r.invDirection[axis];
            const float tFar = (node.bounds[axis][1 - r.nearSide[axis]][lane] - r.origin[axis]) * r.invDirection[axis];
            // The comparison order of narrowSlab: a NaN (ray on a plane it runs along) keeps the running bound.
            t0 = tNear > t0 ? tNear : t0;
            t1 = tFar < t1 ? tFar : t1;
        }
        tEntry[lane] = t0;
        if (t0 <= t1 * kBoxExitScale) mask |= 1u << lane;
    }
    return mask;
}

#if TRAZO_HOST_SSE
// _mm_max_ps(a, b) is a > b ? a : b and _mm_min_ps(a, b) is a < b ? a : b, NaN handling included: exactly
// the scalar selects above.
inline unsigned intersectChildrenSse(const NodeRay& r, const WideBvhNode& node, float tMin, float tMax,
                                     float tEntry[kBvhWidth]) {
    __m128 t0 = _mm_set1_ps(tMin), t1 = _mm_set1_ps(tMax);
    const float* bounds = &node.bounds[0][0][0];
#if !defined(__CUDACC__)  // nvcc's host pass reads this code too, and knows no GCC pragma
#pragma GCC unroll 3  // GCC would loop over the axes (3-4 % of a ray's time, bvh_bench)
#endif
    for (int axis = 0; axis < 3; ++axis) {
        const __m128 origin = r.originLanes[axis], inv = r.invLanes[axis];
        const __m128 tNear = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(bounds + r.entryOffset[axis]), origin), inv);
        const __m128 tFar = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(bounds + r.exitOffset[axis]), origin), inv);
        t0 = _mm_max_ps(tNear, t0);
        t1 = _mm_min_ps(tFar, t1);
    }
    _mm_storeu_ps(tEntry, t0);
    return (unsigned)_mm_movemask_ps(_mm_cmple_ps(t0, _mm_mul_ps(t1, _mm_set1_ps(kBoxExitScale))));
}
#endif

TRAZO_HD unsigned intersectChildren(const NodeRay& r, const WideBvhNode& node, float tMin, float tMax,
                                    float tEntry[kBvhWidth]) {
#if TRAZO_HOST_SSE
    return intersectChildrenSse(r, node, tMin, tMax, tEntry);
#else
    return intersectChildrenScalar(r, node, tMin, tMax, tEntry);
#endif
}

#if TRAZO_HOST_SSE
// Host: the lanes whose reference is a leaf or empty (bit 31 set in both), and the lanes in use, read from
// the four references at once.
inline unsigned leafOrEmptyLanes(const WideBvhNode& node) {
    return (unsigned)_mm_movemask_ps(_mm_load_ps(reinterpret_cast<const float*>(node.child)));
}
inline unsigned usedLanes(const WideBvhNode& node) {
    const __m128i refs = _mm_load_si128(reinterpret_cast<const __m128i*>(node.child));
    const __m128i empty = _mm_cmpeq_epi32(refs, _mm_set1_epi32((int)kBvhEmptyLane));
    return ~(unsigned)_mm_movemask_ps(_mm_castsi128_ps(empty)) & 0xfu;
}
#endif

// Host: starts loading the interior children the ray entered before they are popped; random rays wait on
// memory for most of their time (measure with build/bench/bvh/bvh_bench --only random).
TRAZO_HD void prefetchChildren(const WideBvhNode* nodes, const WideBvhNode& node, unsigned mask) {
#if TRAZO_HOST_SSE
    for (unsigned interior = mask & ~leafOrEmptyLanes(node); interior; interior &= interior - 1) {
        const char* child = reinterpret_cast<const char*>(nodes + node.child[__builtin_ctz(interior)]);
        __builtin_prefetch(child);
        __builtin_prefetch(child + 64);
    }
#elif !defined(__CUDA_ARCH__)
    for (int lane = 0; lane < kBvhWidth; ++lane)
        if ((mask & (1u << lane)) && !bvhIsLeaf(node.child[lane])) {
            const char* child = reinterpret_cast<const char*>(nodes + node.child[lane]);
            __builtin_prefetch(child);
            __builtin_prefetch(child + 64);
        }
#endif
}

struct StackEntry {
    uint32_t ref;
    float tEntry;  // lets a popped node be skipped once a closer hit is known
};

}  // namespace bvh_detail

// Entries of the traversal stack the two BVH levels share (a mesh's traversal continues above the top level's
// entries). The host holds the bound of any pair of trees the builder makes (the top level's four-wide, a
// mesh's four- or eight-wide: accel/wide8_traverse.h); a GPU thread's stack lives in local memory, so the
// device holds 64 entries and the upload refuses a scene whose trees need more (traversalStackNeed).
constexpr int kHostTraversalStackSize = kBvhStackSize + kBvh8StackSize;
constexpr int kDeviceTraversalStackSize = 64;
#if TRAZO_DEVICE_PATHS
constexpr int kTraversalStackSize = kDeviceTraversalStackSize;
#else
constexpr int kTraversalStackSize = kHostTraversalStackSize;
#endif

// A stack of pending children: closest-hit queries keep StackEntry, any-hit queries references only. A
// traversal pushes above `size` and returns with `size` where it found it, so a traversal started from a
// leaf function (a mesh inside the top level) shares the caller's stack: the caller publishes its size
// before each leaf call. On the device a push beyond `capacity` is dropped: the upload's check makes that
// unreachable, the guard keeps memory safe regardless.
template <typename Entry>
struct TraversalStack {
    Entry* entries;
    int capacity;
    int size;
};

namespace bvh_detail {
template <typename Entry>
TRAZO_HD void push(Entry* entries, int& size, int capacity, const Entry& e) {
#if TRAZO_DEVICE_PATHS
    if (size >= capacity) return;
#else
    (void)capacity;  // the host's stacks hold the bound of any tree the builder makes: no test per push
#endif
    entries[size++] = e;
}
}  // namespace bvh_detail

using ClosestStack = TraversalStack<bvh_detail::StackEntry>;
using AnyStack = TraversalStack<uint32_t>;

namespace bvh_detail {

// For closest-hit queries: orders the children in `mask` by entry distance, pushes all but the nearest
// (the farthest deepest) and returns the nearest, or kBvhEmptyLane when `mask` holds only unused lanes.
TRAZO_HD uint32_t pushFartherChildren(const WideBvhNode& node, unsigned mask, const float tEntry[kBvhWidth],
                                      StackEntry* stack, int& size, int capacity) {
    StackEntry hits[kBvhWidth];
    int count = 0;
    for (int lane = 0; lane < kBvhWidth; ++lane) {
        if (!(mask & (1u << lane)) || node.child[lane] == kBvhEmptyLane) continue;
        // Insertion into descending order of tEntry: the nearest ends up last.
        int i = count++;
        for (; i > 0 && hits[i - 1].tEntry < tEntry[lane]; --i) hits[i] = hits[i - 1];
        hits[i] = {node.child[lane], tEntry[lane]};
    }
    if (count == 0) return kBvhEmptyLane;
    for (int i = 0; i < count - 1; ++i) push(stack, size, capacity, hits[i]);
    return hits[count - 1].ref;
}

// The same order without the sort where it is not needed: one child entered (the common case) is taken
// without a push, two are ordered by one comparison (the insertion above puts the higher lane nearer on a
// tie), three or four are sorted as above. Prefetches the children entered (prefetchChildren), but on the
// host not the one read next: its node test loads both its lines a few instructions later anyway.
TRAZO_HD_HOT uint32_t nearestChildPushOthers(const WideBvhNode* nodes, const WideBvhNode& node, unsigned mask,
                                         const float tEntry[kBvhWidth], StackEntry* stack, int& size, int capacity) {
#if TRAZO_HOST_SSE
    mask &= usedLanes(node);
    if (!mask) return kBvhEmptyLane;
    const int a = __builtin_ctz(mask);
    unsigned rest = mask & (mask - 1);
    if (!rest) return node.child[a];
    const int b = __builtin_ctz(rest);
    if (!(rest & (rest - 1))) {
        const bool aNearer = tEntry[a] < tEntry[b];
        const int nearer = aNearer ? a : b, farther = aNearer ? b : a;
        prefetchChildren(nodes, node, 1u << farther);
        push(stack, size, capacity, StackEntry{node.child[farther], tEntry[farther]});
        return node.child[nearer];
    }
#endif
    prefetchChildren(nodes, node, mask);
    return pushFartherChildren(node, mask, tEntry, stack, size, capacity);
}

// For any-hit queries: pushes the children in `mask` but the first in lane order, returns the first. Not
// sorted by distance as closest-hit does: any occluder will do, and sorting costs shadow rays more than it
// saves (build/bench/bvh/bvh_bench --only shadow).
TRAZO_HD uint32_t pushLaterChildren(const WideBvhNode& node, unsigned mask, uint32_t* stack, int& size,
                                    int capacity) {
    uint32_t first = kBvhEmptyLane;
    for (int lane = kBvhWidth - 1; lane >= 0; --lane) {
        if (!(mask & (1u << lane)) || node.child[lane] == kBvhEmptyLane) continue;
        if (first != kBvhEmptyLane) push(stack, size, capacity, first);
        first = node.child[lane];
    }
    return first;
}

}  // namespace bvh_detail

// The leaf that is the whole tree (collapseBvh puts a root leaf in lane 0 and no other lane is used), or
// kBvhEmptyLane. A caller whose leaf test is exact by itself can skip the traversal of such a tree: its one box
// test would only repeat what the leaf's primitives decide (intersectScene's top level).
TRAZO_HD uint32_t loneLeaf(const WideBvhNode* nodes) {
    return nodes[0].child[1] == kBvhEmptyLane ? nodes[0].child[0] : kBvhEmptyLane;
}

// Closest hit within (tMin, tMax). leaf(first, count, tMax) tests primitives [first, first + count), shrinks
// tMax on a closer hit and returns whether it hit. Returns whether any leaf hit; tMax is then the nearest t.
// `nodes` must hold a non-empty BVH (a BVH over zero primitives has no root: skip it).
template <class LeafFn>
TRAZO_HD bool traverseClosest(const WideBvhNode* nodes, const Ray& ray, float tMin, float& tMax, ClosestStack& stack,
                              LeafFn&& leaf) {
    const bvh_detail::NodeRay nodeRay = bvh_detail::makeNodeRay(ray);
    bvh_detail::StackEntry* const entries = stack.entries;
    const int base = stack.size, capacity = stack.capacity;
    int size = base;
    uint32_t ref = 0;
    bool hit = false;
    for (;;) {
        if (!bvhIsLeaf(ref)) {
            const WideBvhNode& node = nodes[ref];
            float tEntry[kBvhWidth];
            const unsigned mask = bvh_detail::intersectChildren(nodeRay, node, tMin, tMax, tEntry);
            if (mask) {
                ref = bvh_detail::nearestChildPushOthers(nodes, node, mask, tEntry, entries, size, capacity);
                if (ref != kBvhEmptyLane) continue;
            }
        } else {
            stack.size = size;  // a traversal the leaf starts continues above this one's entries
            if (leaf(bvhLeafFirst(ref), bvhLeafCount(ref), tMax)) hit = true;
        }
        // Pop the nearest pending child that may still hold something closer than tMax.
        for (;;) {
            if (size == base) {
                stack.size = base;
                return hit;
            }
            const bvh_detail::StackEntry e = entries[--size];
            if (e.tEntry <= tMax * kBoxExitScale) {
                ref = e.ref;
                break;
            }
        }
    }
}

// The same with a stack of its own.
template <class LeafFn>
TRAZO_HD bool traverseClosest(const WideBvhNode* nodes, const Ray& ray, float tMin, float& tMax, LeafFn&& leaf) {
    bvh_detail::StackEntry entries[kBvhStackSize];
    ClosestStack stack{entries, kBvhStackSize, 0};
    return traverseClosest(nodes, ray, tMin, tMax, stack, leaf);
}

// Whether anything blocks the ray within (tMin, tMax). leaf(first, count, tMax) returns true as soon as one of
// its primitives does; traversal stops there.
template <class LeafFn>
TRAZO_HD bool traverseAny(const WideBvhNode* nodes, const Ray& ray, float tMin, float tMax, AnyStack& stack,
                          LeafFn&& leaf) {
    const bvh_detail::NodeRay nodeRay = bvh_detail::makeNodeRay(ray);
    uint32_t* const entries = stack.entries;
    const int base = stack.size, capacity = stack.capacity;
    int size = base;
    uint32_t ref = 0;
    for (;;) {
        if (!bvhIsLeaf(ref)) {
            const WideBvhNode& node = nodes[ref];
            float tEntry[kBvhWidth];
            const unsigned mask = bvh_detail::intersectChildren(nodeRay, node, tMin, tMax, tEntry);
            if (mask) {
                bvh_detail::prefetchChildren(nodes, node, mask & (mask - 1));  // not the first lane: it is read next
                ref = bvh_detail::pushLaterChildren(node, mask, entries, size, capacity);
                if (ref != kBvhEmptyLane) continue;
            }
        } else {
            stack.size = size;  // a traversal the leaf starts continues above this one's entries
            if (leaf(bvhLeafFirst(ref), bvhLeafCount(ref), tMax)) {
                stack.size = base;
                return true;
            }
        }
        if (size == base) {
            stack.size = base;
            return false;
        }
        ref = entries[--size];
    }
}

template <class LeafFn>
TRAZO_HD bool traverseAny(const WideBvhNode* nodes, const Ray& ray, float tMin, float tMax, LeafFn&& leaf) {
    uint32_t entries[kBvhStackSize];  // references only: no culling by distance, so half the closest-hit stack
    AnyStack stack{entries, kBvhStackSize, 0};
    return traverseAny(nodes, ray, tMin, tMax, stack, leaf);
}

}  // namespace trazo
