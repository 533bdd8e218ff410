// The box object kind (host and device): the unit cube [-0.5, 0.5]³ mapped by an affine transform (any
// parallelepiped), its ray intersection (a slab test in the box's object space), texture frame and bounds (the
// host block: scene/kinds/box.h). Texture frame: each face maps its unit square to [0,1]²; side faces have v up (+Y of the box),
// the top face has u = +X and v = −Z, the bottom u = +X and v = +Z (all in the box's object space).
#pragma once

#include "accel/bvh_traverse.h"
#include "core/aabb.h"
#include "core/affine.h"
#include "core/hd.h"
#include "core/number_ops.h"
#include "core/ray.h"
#include "core/vec3.h"
#include "geometry/shape_hit.h"
#include "geometry/surface_frame.h"
#include "objects/scene_view.h"

namespace trazo {

// Both transforms: rays go to object space, normals and tangents come back.
struct BoxShape {
    Affine3 objectFromWorld;
    Affine3 worldFromObject;
};

// The unit outward normal of the face on side `sign` (±1) of `axis`: the inverse transpose maps ±e_axis to ± row
// `axis` of objectFromWorld. A box thinner than about 5e-20 has rows whose squares leave float: those are scaled
// down first (only then, so every other box's normals keep their bits).
TRAZO_HD Vec3 boxFaceNormal(const BoxShape& box, int axis, float sign) {
    const Vec3 row = box.objectFromWorld.row[axis] * sign;
    if (isFinite(dot(row, row))) return normalize(row);
    return normalize(row * (1.0f / maxComponent(abs(row))));
}

// The slab test in the box's object space, written over the number type T (core/number_ops.h) for a ray and for
// SIMD lanes (integrator/packets/packet_lanes.h, whose rays may share an origin, a Vec3): where the line enters
// (tEnter) and leaves (tExit) the box and through which face, 2·axis + 1 for the + face of the axis; `live` loses
// the rays parallel to a slab outside it. Whether any is left. The box is closed: a line lying in a face's plane
// counts as inside that slab. The line meets the box where tEnter ≤ tExit.
template <class T, class O>
TRAZO_HD_HOT bool boxSlabsOf(const BoxShape& box, const O& originWorld, const typename T::V& directionWorld,
                             typename T::B& live, typename T::F& tEnter, typename T::F& tExit,
                             typename T::I& enterFace, typename T::I& exitFace) {
    // The object-space ray is not normalised, so its t is the world t (an affine map keeps ratios).
    const O o = applyToPoint(box.objectFromWorld, originWorld);
    const typename T::V d = applyToVector(box.objectFromWorld, directionWorld);
    tEnter = T::splat(-INFINITY);
    tExit = T::splat(INFINITY);
    enterFace = exitFace = typename T::I{};
    for (int axis = 0; axis < 3; ++axis) {
        const typename T::F oi = T::splat(o[axis]), di = d[axis];
        const typename T::B parallel = di == 0.0f;  // true for −0 too: parallel to this slab, inside it or never
        if (T::any(parallel)) {
            live = live & !(parallel & ((oi < -0.5f) | (oi > 0.5f)));
            if (!T::any(live)) return false;
            if (T::all(parallel)) continue;
        }
        // Divisions rather than a reciprocal: 0/tiny stays 0 where 0·(1/tiny) = 0·inf would be NaN.
        const typename T::F tLow = (-0.5f - oi) / di;
        const typename T::F tHigh = (0.5f - oi) / di;
        const typename T::B forward = di > 0.0f;  // enters through the −face, leaves through the +face
        const typename T::F tNear = forward ? tLow : tHigh;
        const typename T::F tFar = forward ? tHigh : tLow;
        const typename T::B enters = (!parallel) & (tNear > tEnter), exits = (!parallel) & (tFar < tExit);
        tEnter = enters ? tNear : tEnter;
        tExit = exits ? tFar : tExit;
        enterFace = enters ? 2 * axis + (forward ? 0 : 1) : enterFace;
        exitFace = exits ? 2 * axis + (forward ? 1 : 0) : exitFace;
    }
    return true;
}

// Nearest hit with tMin < t < tMax; fills hit.t and the unit outward normal. From inside, the hit is the exit point.
TRAZO_HD bool intersectBox(const BoxShape& box, const Ray& ray, float tMin, float tMax, ShapeHit& hit) {
    bool live = true;
    float tEnter, tExit;
    int enterFace, exitFace;
    if (!boxSlabsOf<ScalarOps>(box, ray.origin, ray.direction, live, tEnter, tExit, enterFace, exitFace)) return false;
    if (!(tEnter <= tExit)) return false;
    int face;
    if (tEnter > tMin && tEnter < tMax) {
        hit.t = tEnter;
        face = enterFace;
    } else if (tExit > tMin && tExit < tMax) {
        hit.t = tExit;
        face = exitFace;
    } else {
        return false;
    }
    hit.normal = boxFaceNormal(box, face >> 1, face & 1 ? 1.0f : -1.0f);
    hit.triangle = uint32_t(face);  // for objectHitPoint
    return true;
}

TRAZO_HD SurfaceFrame boxFrame(const BoxShape& box, Vec3 p) {
    const Vec3 q = box.objectFromWorld.applyToPoint(p);
    const Vec3 aq = abs(q);
    const int axis = aq.x >= aq.y && aq.x >= aq.z ? 0 : (aq.y >= aq.z ? 1 : 2);
    const float sign = q[axis] >= 0.0f ? 1.0f : -1.0f;
    Vec3 uAxis, vAxis;  // object-space directions of increasing u and v on this face
    if (axis == 0) {
        uAxis = Vec3(0.0f, 0.0f, -sign);
        vAxis = Vec3(0.0f, 1.0f, 0.0f);
    } else if (axis == 1) {
        uAxis = Vec3(1.0f, 0.0f, 0.0f);
        vAxis = Vec3(0.0f, 0.0f, -sign);
    } else {
        uAxis = Vec3(sign, 0.0f, 0.0f);
        vAxis = Vec3(0.0f, 1.0f, 0.0f);
    }
    return {dot(q, uAxis) + 0.5f, dot(q, vAxis) + 0.5f, normalize(box.worldFromObject.applyToVector(uAxis)),
            normalize(box.worldFromObject.applyToVector(vAxis))};
}

// The object kind's interface (objects/visit_object.h dispatches to it).
TRAZO_HD bool intersectObject(const SceneView&, const BoxShape& box, const Ray& ray, float tMax, ClosestStack&,
                              ShapeHit& hit) {
    return intersectBox(box, ray, 0.0f, tMax, hit);
}

TRAZO_HD bool objectBlocks(const SceneView&, const BoxShape& box, const Ray& ray, float tMax, AnyStack&) {
    ShapeHit hit;
    return intersectBox(box, ray, 0.0f, tMax, hit);
}

TRAZO_HD SurfacePoint objectSurface(const SceneView&, const BoxShape& box, const ShapeHit& hit, Vec3 p, bool wantUv) {
    return wantUv ? surfaceWithFrame(hit, boxFrame(box, p)) : plainSurface(hit);
}

TRAZO_HD bool objectHasUvs(const SceneView&, const BoxShape&) { return true; }

// o + t·d moved onto its face (hit.triangle: 2·axis + 1 for the + face of the axis) along the box's own axis:
// by the face coordinate's distance from ±½ in object space, times worldFromObject's column `axis`. Off the face
// by the rounding of that coordinate (a few ulps of its terms, carried along the column), of the two transforms'
// disagreement over the step and of the sum, wherever the ray came from. One row and one column, not two whole
// transforms: it runs at every hit on a box (scene 6: a fifth of its time as two transforms).
TRAZO_HD_HOT HitPoint objectHitPoint(const SceneView&, const BoxShape& box, const Ray& ray, const ShapeHit& hit) {
    const HitPoint along = rayHitPoint(ray, hit.t, hit.normal);
    const int axis = int(hit.triangle >> 1);
    const Vec3 row = box.objectFromWorld.row[axis];
    const float translation = box.objectFromWorld.translation[axis];
    const float step = (hit.triangle & 1u ? 0.5f : -0.5f) - (dot(row, along.p) + translation);
    const Affine3& w = box.worldFromObject;
    const Vec3 column(w.row[0][axis], w.row[1][axis], w.row[2][axis]);
    const Vec3 p = along.p + column * step;
    const float coordinateError = (dot(abs(row), abs(along.p)) + fabsf(translation)) * roundoff(4.0f);
    const Vec3 error = abs(column) * (coordinateError + fabsf(step) * roundoff(8.0f)) + abs(p) * roundoff(2.0f);
    return tighter(along, boundedHitPoint(p, error, hit.normal));
}

inline Aabb objectBounds(const SceneView&, const BoxShape& box) {
    Aabb b;
    for (int c = 0; c < 8; ++c)
        b.grow(box.worldFromObject.applyToPoint(
            Vec3((c & 1) ? 0.5f : -0.5f, (c & 2) ? 0.5f : -0.5f, (c & 4) ? 0.5f : -0.5f)));
    return b;
}

}  // namespace trazo
