// Ray–cylinder intersection (host and device): a capped cylinder as its side quadratic plus two disks.
#pragma once

#include "core/hd.h"
#include "core/ray.h"
#include "core/vec3.h"
#include "geometry/exact_float.h"
#include "geometry/shapes.h"

namespace trazo {

// Nearest hit with tMin < t < tMax among the side and both caps; fills hit.t and the unit outward
// normal. Closed: a ray through the rim hits. From inside, the hit is the exit point.
TRAZO_HD bool intersectCylinder(const CylinderShape& cyl, const Ray& ray, float tMin, float tMax, ShapeHit& hit) {
    const Vec3 axis = cyl.axis;
    const float r = cyl.radius;
    const Vec3 f = ray.origin - cyl.base;
    const Vec3 d = ray.direction;
    // axis × v is v's component orthogonal to the axis, turned by 90° about it (|axis| = 1): the side
    // is |F + t·D| = r, a quadratic in the plane orthogonal to the axis. Compensated cross products
    // keep |D| right for a ray nearly along the axis, and exactly 0 for one along it.
    const Vec3 fPerp = crossAccurate(axis, f);
    const Vec3 dPerp = crossAccurate(axis, d);
    const float fAlong = dot(axis, f);  // height above the base cap
    const float dAlong = dot(axis, d);

    float tBest = tMax;
    bool found = false;
    Vec3 normal;

    // Side. a = 0 exactly for a ray parallel to the axis: it cannot cross the side, only the caps.
    const float a = dot(dPerp, dPerp);
    if (a > 0.0f) {
        // RTG ch. 7's stable quadratic, in the cross-section. Unlike intersectSphere, c is not
        // compensated: a cylinder huge beside the camera is not worth the arithmetic.
        const float b = dot(fPerp, dPerp);
        const Vec3 l = fPerp - dPerp * (b / a);
        const float lLength = length(l);
        const float discriminant = a * ((r - lLength) * (r + lLength));
        if (discriminant >= 0.0f) {
            const float q = -b - copysignf(sqrtf(discriminant), b);
            const float c = dot(fPerp, fPerp) - r * r;
            float t0 = q / a;
            float t1 = q != 0.0f ? c / q : t0;
            if (t0 > t1) {
                const float swap = t0;
                t0 = t1;
                t1 = swap;
            }
            // A root counts only between the caps; the nearer one wins if both do.
            for (int i = 0; i < 2; ++i) {
                const float t = i == 0 ? t0 : t1;
                if (!(t > tMin && t < tBest)) continue;
                const float height = fAlong + t * dAlong;
                if (height >= 0.0f && height <= cyl.height) {
                    tBest = t;
                    found = true;
                    // (axis × p) × axis is p's radial component: the outward normal's direction.
                    normal = cross(fPerp + dPerp * t, axis);
                    break;
                }
            }
        }
    }

    // Caps: the planes height = 0 (normal −axis) and height = h (normal +axis), within the radius.
    // dAlong = 0 for a ray parallel to the caps: it meets them only through the side.
    if (dAlong != 0.0f) {
        for (int i = 0; i < 2; ++i) {
            const float capHeight = i == 0 ? 0.0f : cyl.height;
            const float t = (capHeight - fAlong) / dAlong;
            if (!(t > tMin && t < tBest)) continue;
            const Vec3 radial = fPerp + dPerp * t;
            if (dot(radial, radial) <= r * r) {
                tBest = t;
                found = true;
                normal = i == 0 ? -axis : axis;
            }
        }
    }

    if (!found) return false;
    hit.t = tBest;
    hit.normal = normalize(normal);
    return true;
}

}  // namespace trazo
