// The CSG solid object kind's kernel side (host and device; the host block: scene/kinds/csg.h): ray intersection
// without allocation and bounds. The tree, flattened in post-order, is
// evaluated by one sweep that keeps each sub-tree's sorted list of [entry, exit] intervals along the ray in
// a fixed pool. Memory is bounded by the tree size: a list never holds more intervals than its sub-tree
// has leaves, so kCsgMaxLeaves intervals plus as many for the combine step suffice.
#pragma once

#include <cstdint>

#include "accel/bvh_traverse.h"
#include "accel/ray_box.h"
#include "core/aabb.h"
#include "core/affine.h"
#include "core/ray.h"
#include "geometry/surface_frame.h"
#include "objects/box.h"
#include "objects/cylinder.h"
#include "objects/scene_view.h"
#include "objects/sphere.h"

namespace trazo {

// The readers reject trees over 64 nodes; a binary tree of at most 63 nodes has at most 32 leaves.
constexpr int kCsgMaxLeaves = 32;

enum class CsgOp : uint32_t { Leaf = 0, Union = 1, Intersection = 2, Difference = 3 };
// Leaves are canonical shapes in their object space: the unit sphere, the unit cube [-0.5, 0.5]³ and the
// cylinder of radius 1 from y = 0 to y = 1; objectFromWorld carries every transform of the tree.
enum class CsgLeafShape : uint32_t { Sphere = 0, Box = 1, Cylinder = 2 };

struct CsgNodeData {
    CsgOp op;
    CsgLeafShape shape;      // leaves only
    Affine3 objectFromWorld;  // leaves only
    Affine3 worldFromObject;  // leaves only: where objectHitPoint maps a point of the canonical shape back
    // World bounds of the sub-tree's result (a union of its leaves, the left operand for a difference,
    // the overlap for an intersection), and the tree links that let the sweep skip a missed sub-tree.
    Vec3 boundsMin, boundsMax;
    uint32_t parent;       // node index within the object; the root points at itself
    uint32_t isLeftChild;  // 1 when this node is its parent's left operand
};

// One CSG object: its nodes are csgNodes[firstNode, firstNode + nodeCount) in post-order (root last).
struct CsgShape {
    uint32_t firstNode, nodeCount;
};

struct CsgEndpoint {
    float t;
    uint8_t leaf;     // node index (within the object, < 2·kCsgMaxLeaves) whose surface this is
    uint8_t flipped;  // 1 when the surface bounds a subtracted part: its outward normal is reversed
};

// Two endpoints in 12 bytes rather than two padded CsgEndpoints' 16: the pool is most of a GPU thread's
// stack frame when a scene has CSG solids.
struct CsgInterval {
    float t[2];  // [0] = entry, [1] = exit
    uint8_t leaf[2], flipped[2];

    TRAZO_HD CsgEndpoint endpoint(int side) const { return CsgEndpoint{t[side], leaf[side], flipped[side]}; }
    TRAZO_HD void set(int side, const CsgEndpoint& e) {
        t[side] = e.t;
        leaf[side] = e.leaf;
        flipped[side] = e.flipped;
    }
};
static_assert(sizeof(CsgInterval) == 12, "CsgInterval should pack two endpoints into 12 bytes");
static_assert(2 * kCsgMaxLeaves - 1 <= 255, "a CSG node index must fit CsgEndpoint::leaf");

// The canonical shape's interval along an object-space ray: false when the line misses it.
TRAZO_HD bool csgLeafInterval(CsgLeafShape shape, const Ray& rayObject, float& t0, float& t1) {
    ShapeHit first, second;
    auto intersect = [&](float tMin, ShapeHit& hit) {
        switch (shape) {
            case CsgLeafShape::Sphere: return intersectSphere(SphereShape{Vec3(0.0f), 1.0f}, rayObject, tMin, INFINITY, hit);
            case CsgLeafShape::Box: return intersectBox(BoxShape{}, rayObject, tMin, INFINITY, hit);
            case CsgLeafShape::Cylinder:
                return intersectCylinder(CylinderShape{Vec3(0.0f), Vec3(0, 1, 0), 1.0f, 1.0f}, rayObject, tMin, INFINITY, hit);
        }
        return false;
    };
    if (!intersect(-INFINITY, first) || !intersect(first.t, second)) return false;
    t0 = first.t;
    t1 = second.t;
    return true;
}

// Outward normal of a canonical shape at an object-space point on (or very near) its surface.
TRAZO_HD Vec3 csgLeafNormal(CsgLeafShape shape, Vec3 p) {
    switch (shape) {
        case CsgLeafShape::Sphere: return p;
        case CsgLeafShape::Box: {
            const Vec3 a = abs(p);
            if (a.x >= a.y && a.x >= a.z) return Vec3(copysignf(1.0f, p.x), 0, 0);
            if (a.y >= a.z) return Vec3(0, copysignf(1.0f, p.y), 0);
            return Vec3(0, 0, copysignf(1.0f, p.z));
        }
        case CsgLeafShape::Cylinder: {
            const float radial = sqrtf(p.x * p.x + p.z * p.z);
            const float side = fabsf(radial - 1.0f), bottom = fabsf(p.y), top = fabsf(p.y - 1.0f);
            if (side <= bottom && side <= top) return Vec3(p.x, 0, p.z);
            return Vec3(0, bottom < top ? -1.0f : 1.0f, 0);
        }
    }
    return Vec3(0, 1, 0);
}

TRAZO_HD bool csgInside(CsgOp op, bool inLeft, bool inRight) {
    switch (op) {
        case CsgOp::Union: return inLeft || inRight;
        case CsgOp::Intersection: return inLeft && inRight;
        default: return inLeft && !inRight;  // Difference: left minus right
    }
}

// Merges two sorted interval lists by a boolean operation into `out` (sorted, disjoint); returns its size.
// Endpoints of the right operand of a difference bound the result from the other side: flip them.
TRAZO_HD int csgCombine(CsgOp op, const CsgInterval* left, int leftCount, const CsgInterval* right, int rightCount,
                        CsgInterval* out) {
    int n = 0;
    bool inLeft = false, inRight = false, inside = false;
    // Each list contributes its endpoints in order: entry_k, exit_k, entry_k+1, …
    int li = 0, ri = 0;  // endpoint cursors (2 per interval)
    while (li < 2 * leftCount || ri < 2 * rightCount) {
        const float tl = li < 2 * leftCount ? left[li / 2].t[li % 2] : INFINITY;
        const float tr = ri < 2 * rightCount ? right[ri / 2].t[ri % 2] : INFINITY;
        CsgEndpoint e;
        if (tl <= tr) {
            e = left[li / 2].endpoint(li % 2);
            inLeft = !(li % 2);
            ++li;
        } else {
            e = right[ri / 2].endpoint(ri % 2);
            if (op == CsgOp::Difference) e.flipped ^= 1;
            inRight = !(ri % 2);
            ++ri;
        }
        const bool now = csgInside(op, inLeft, inRight);
        if (now == inside) continue;
        inside = now;
        // Coplanar faces: an interval that starts where the previous one ended continues it (two boxes
        // sharing a face are one solid), and an interval of zero length is no solid at all.
        if (now) {
            if (n > 0 && out[n - 1].t[1] >= e.t) --n;
            else out[n].set(0, e);
        } else if (e.t > out[n].t[0]) {
            out[n++].set(1, e);
        }
    }
    return n;
}

// Nearest surface of the solid with tMin < t < tMax and its outward normal (world space).
TRAZO_HD_CALL bool intersectCsg(const CsgShape& csg, const CsgNodeData* nodes, const Ray& ray, float tMin, float tMax,
                           ShapeHit& hit) {
    CsgInterval pool[2 * kCsgMaxLeaves];
    // Bytes: every start, count and node index is below 2·kCsgMaxLeaves (less stack on a GPU thread).
    uint8_t listStart[kCsgMaxLeaves + 1], listCount[kCsgMaxLeaves + 1];
    int lists = 0, used = 0;
    for (uint32_t k = 0; k < csg.nodeCount; ++k) {
        const CsgNodeData& node = nodes[csg.firstNode + k];
        if (node.op == CsgOp::Leaf) {
            // A leaf starts the sub-trees of the ancestors it is the leftmost leaf of. The outermost one
            // whose bounds the ray misses yields an empty list and is skipped whole.
            uint8_t chain[kCsgMaxLeaves + 1];
            int chainLength = 0;
            for (uint32_t n = k;; n = nodes[csg.firstNode + n].parent) {
                chain[chainLength++] = (uint8_t)n;
                const CsgNodeData& c = nodes[csg.firstNode + n];
                if (c.parent == n || !c.isLeftChild || chainLength > kCsgMaxLeaves) break;
            }
            uint32_t skippedRoot = 0xffffffffu;
            for (int i = chainLength - 1; i >= 0; --i) {
                const CsgNodeData& c = nodes[csg.firstNode + chain[i]];
                // The inverse direction is recomputed per test rather than held through the sweep: registers
                // are what a GPU thread running a CSG solid is short of.
                float tEntry;
                if (!intersectBounds(makeBoxRay(ray), c.boundsMin, c.boundsMax, 0.0f, tMax, tEntry)) {
                    skippedRoot = chain[i];
                    break;
                }
            }
            listStart[lists] = (uint8_t)used;
            listCount[lists] = 0;
            if (skippedRoot != 0xffffffffu) {
                ++lists;
                k = skippedRoot;  // the sub-tree ends at its root in post-order
                continue;
            }
            const Ray rayObject{node.objectFromWorld.applyToPoint(ray.origin), node.objectFromWorld.applyToVector(ray.direction)};
            float t0, t1;
            if (csgLeafInterval(node.shape, rayObject, t0, t1)) {
                pool[used++] = CsgInterval{{t0, t1}, {(uint8_t)k, (uint8_t)k}, {0, 0}};
                listCount[lists] = 1;
            }
            ++lists;
            continue;
        }
        // Operands are the two lists on top, contiguous in the pool; the result replaces them.
        const int right = --lists, left = lists - 1;
        CsgInterval* scratch = pool + used;
        const int n = csgCombine(node.op, pool + listStart[left], listCount[left], pool + listStart[right],
                                 listCount[right], scratch);
        for (int i = 0; i < n; ++i) pool[listStart[left] + i] = scratch[i];
        listCount[left] = (uint8_t)n;
        used = listStart[left] + n;
    }
    // The root's list: the first endpoint inside the window, entry or (from inside) exit.
    for (int i = 0; i < listCount[0]; ++i) {
        for (int side = 0; side < 2; ++side) {
            const CsgEndpoint e = pool[i].endpoint(side);
            if (!(e.t > tMin && e.t < tMax)) continue;
            const CsgNodeData& leaf = nodes[csg.firstNode + e.leaf];
            const Vec3 pObject = leaf.objectFromWorld.applyToPoint(pointAt(ray, e.t));
            Vec3 n = normalize(leaf.objectFromWorld.applyTransposeToVector(csgLeafNormal(leaf.shape, pObject)));
            hit.t = e.t;
            hit.normal = e.flipped ? -n : n;
            hit.triangle = e.leaf;  // the leaf whose surface it is, for objectHitPoint
            return true;
        }
    }
    return false;
}

// The object kind's interface (objects/visit_object.h dispatches to it). CSG solids have no texture
// coordinates.
TRAZO_HD bool intersectObject(const SceneView& scene, const CsgShape& csg, const Ray& ray, float tMax, ClosestStack&,
                              ShapeHit& hit) {
    return intersectCsg(csg, scene.csgNodes.data, ray, 0.0f, tMax, hit);
}

TRAZO_HD bool objectBlocks(const SceneView& scene, const CsgShape& csg, const Ray& ray, float tMax, AnyStack&) {
    ShapeHit hit;
    return intersectCsg(csg, scene.csgNodes.data, ray, 0.0f, tMax, hit);
}

TRAZO_HD SurfacePoint objectSurface(const SceneView&, const CsgShape&, const ShapeHit& hit, Vec3, bool) {
    return plainSurface(hit);
}

TRAZO_HD bool objectHasUvs(const SceneView&, const CsgShape&) { return false; }

// o + t·d put back on the leaf's canonical surface in its object space (the face, side or cap csgLeafNormal
// picks), mapped back to the world: off it by the rounding of that map, wherever the ray came from. The hit's
// normal is already the one at this point: intersectCsg takes it from the same object-space point.
TRAZO_HD_DEVICE_CALL HitPoint objectHitPoint(const SceneView& scene, const CsgShape& csg, const Ray& ray, const ShapeHit& hit) {
    const HitPoint along = rayHitPoint(ray, hit.t, hit.normal);
    const CsgNodeData& leaf = scene.csgNodes[csg.firstNode + hit.triangle];
    Vec3 q = leaf.objectFromWorld.applyToPoint(along.p);
    const Vec3 n = csgLeafNormal(leaf.shape, q);
    if (leaf.shape == CsgLeafShape::Sphere) {
        const float distance = length(q);
        if (!(distance > 0.0f)) return along;
        q = q / distance;
    } else if (leaf.shape == CsgLeafShape::Box) {
        for (int i = 0; i < 3; ++i)
            if (n[i] != 0.0f) q[i] = 0.5f * n[i];
    } else if (n.y != 0.0f) {  // a cylinder's cap
        q.y = n.y > 0.0f ? 1.0f : 0.0f;
    } else {
        const float r = sqrtf(q.x * q.x + q.z * q.z);
        if (!(r > 0.0f)) return along;
        q.x /= r, q.z /= r;
    }
    const Affine3& w = leaf.worldFromObject;
    const Vec3 p = w.applyToPoint(q);
    const Vec3 aq = abs(q);
    const Vec3 reach(dot(abs(w.row[0]), aq), dot(abs(w.row[1]), aq), dot(abs(w.row[2]), aq));
    return tighter(along, boundedHitPoint(p, (reach + abs(w.translation)) * roundoff(6.0f), hit.normal));
}

// The root's bounds: empty (min > max) for a solid that is empty everywhere.
inline Aabb objectBounds(const SceneView& scene, const CsgShape& csg) {
    const CsgNodeData& root = scene.csgNodes[csg.firstNode + csg.nodeCount - 1];
    Aabb b;
    b.grow(root.boundsMin);
    b.grow(root.boundsMax);
    return b;
}

}  // namespace trazo
