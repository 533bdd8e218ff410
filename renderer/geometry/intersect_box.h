// Ray–box intersection (host and device): a slab test on the unit cube in the box's object space.
#pragma once

#include "core/affine.h"
#include "core/hd.h"
#include "core/ray.h"
#include "core/vec3.h"
#include "geometry/shapes.h"

namespace trazo {

// Nearest hit with tMin < t < tMax; fills hit.t and the unit outward normal. The box is closed: a
// ray lying in a face's plane counts as inside that slab. From inside, the hit is the exit point.
TRAZO_HD bool intersectBox(const BoxShape& box, const Ray& ray, float tMin, float tMax, ShapeHit& hit) {
    // The object-space ray is not normalised, so its t is the world t (an affine map keeps ratios).
    const Vec3 o = box.objectFromWorld.applyToPoint(ray.origin);
    const Vec3 d = box.objectFromWorld.applyToVector(ray.direction);

    float tEnter = -INFINITY, tExit = INFINITY;
    int enterAxis = -1, exitAxis = -1;
    float enterSign = 0.0f, exitSign = 0.0f;  // which face of the axis: −1 or +1
    for (int axis = 0; axis < 3; ++axis) {
        const float oi = o[axis], di = d[axis];
        if (di == 0.0f) {  // true for −0 too: parallel to this slab, inside it or never
            if (oi < -0.5f || oi > 0.5f) return false;
            continue;
        }
        // Divisions rather than a reciprocal: 0/tiny stays 0 where 0·(1/tiny) = 0·inf would be NaN.
        const float tLow = (-0.5f - oi) / di;
        const float tHigh = (0.5f - oi) / di;
        const bool forward = di > 0.0f;  // enters through the −face, leaves through the +face
        const float tNear = forward ? tLow : tHigh;
        const float tFar = forward ? tHigh : tLow;
        if (tNear > tEnter) {
            tEnter = tNear;
            enterAxis = axis;
            enterSign = forward ? -1.0f : 1.0f;
        }
        if (tFar < tExit) {
            tExit = tFar;
            exitAxis = axis;
            exitSign = forward ? 1.0f : -1.0f;
        }
    }
    if (!(tEnter <= tExit)) return false;

    int axis;
    float sign;
    if (tEnter > tMin && tEnter < tMax) {
        hit.t = tEnter;
        axis = enterAxis;
        sign = enterSign;
    } else if (tExit > tMin && tExit < tMax) {
        hit.t = tExit;
        axis = exitAxis;
        sign = exitSign;
    } else {
        return false;
    }
    // Normals map by the inverse transpose: objectFromWorldᵀ·(±e_axis) is ± row `axis` of the matrix.
    hit.normal = normalize(box.objectFromWorld.row[axis] * sign);
    return true;
}

}  // namespace trazo
