// Ray–rectangle intersection (host and device) for area lights: a two-sided planar patch.
#pragma once

#include "core/hd.h"
#include "core/ray.h"
#include "core/vec3.h"
#include "geometry/shapes.h"

namespace trazo {

// Hit with tMin < t < tMax on either side; hit.normal is the rectangle's own normal, never flipped.
// The edges belong to the rectangle (|s| = 1 or |t| = 1 hits).
TRAZO_HD bool intersectRectangle(const RectangleShape& rect, const Ray& ray, float tMin, float tMax,
                                 ShapeHit& hit) {
    const float cosine = dot(rect.normal, ray.direction);
    if (cosine == 0.0f) return false;  // parallel to the plane (or in it: a zero-area view)
    // Everything relative to the centre, so a rectangle far from the world origin keeps its digits.
    const Vec3 f = ray.origin - rect.center;
    const float t = -dot(rect.normal, f) / cosine;
    if (!(t > tMin && t < tMax)) return false;
    const Vec3 local = f + ray.direction * t;
    // Coordinates in units of the half extents; halfU ⟂ halfV, so projections are independent.
    const float s = dot(local, rect.halfU) / dot(rect.halfU, rect.halfU);
    const float v = dot(local, rect.halfV) / dot(rect.halfV, rect.halfV);
    if (!(fabsf(s) <= 1.0f && fabsf(v) <= 1.0f)) return false;
    hit.t = t;
    hit.normal = rect.normal;
    return true;
}

}  // namespace trazo
