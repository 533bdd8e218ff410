// The rectangle of an area light (host and device): a two-sided planar patch and its ray intersection.
// Not an object kind: lights are tested one by one after the objects (integrator/scene_intersect.h).
#pragma once

#include "core/hd.h"
#include "core/ray.h"
#include "core/vec3.h"
#include "geometry/shape_hit.h"

namespace trazo {

// centre ± halfU ± halfV; normal = unit normal.
struct RectangleShape {
    Vec3 center;
    Vec3 halfU;  // half the Width along u
    Vec3 halfV;  // half the Height along v
    Vec3 normal;
};

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
