// The cylinder object kind (host and device): a capped cylinder, its ray intersection (the side quadratic
// plus two disks), texture frame and bounds (the host block: scene/kinds/cylinder.h). Texture frame: side u = angle about the axis / 2π,
// v = height / Height; caps map the disk of radius r to the unit square, centred at (½, ½).
#pragma once

#include <initializer_list>

#include "accel/bvh_traverse.h"
#include "core/aabb.h"
#include "core/hd.h"
#include "core/ray.h"
#include "core/vec3.h"
#include "geometry/exact_float.h"
#include "geometry/shape_hit.h"
#include "geometry/surface_frame.h"
#include "objects/scene_view.h"

namespace trazo {

// Bottom cap centred at `base`, top cap at base + axis·height.
struct CylinderShape {
    Vec3 base;
    Vec3 axis;  // unit length
    float height;
    float radius;
};

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

// `normal`: the unit outward normal of the hit (tells the side from the caps).
TRAZO_HD SurfaceFrame cylinderFrame(const CylinderShape& c, Vec3 p, Vec3 normal) {
    const Vec3 e1 = anyOrthonormal(c.axis);
    const Vec3 e2 = cross(c.axis, e1);
    const Vec3 r = p - c.base;
    const float along = dot(normal, c.axis);
    if (fabsf(along) > 0.5f) {  // a cap: its normal is ±axis
        const float s = along > 0.0f ? 1.0f : -1.0f;
        const Vec3 bitangent = e2 * s;
        const float scale = 0.5f / c.radius;
        return {dot(r, e1) * scale + 0.5f, dot(r, bitangent) * scale + 0.5f, e1, bitangent};
    }
    const float u = wrapUnit(atan2f(dot(r, e2), dot(r, e1)) * kInvTwoPi);
    const Vec3 radial = normalize(r - c.axis * dot(r, c.axis));
    return {u, dot(r, c.axis) / c.height, cross(c.axis, radial), c.axis};
}

// The object kind's interface (objects/visit_object.h dispatches to it).
TRAZO_HD bool intersectObject(const SceneView&, const CylinderShape& c, const Ray& ray, float tMax, ClosestStack&,
                              ShapeHit& hit) {
    return intersectCylinder(c, ray, 0.0f, tMax, hit);
}

TRAZO_HD bool objectBlocks(const SceneView&, const CylinderShape& c, const Ray& ray, float tMax, AnyStack&) {
    ShapeHit hit;
    return intersectCylinder(c, ray, 0.0f, tMax, hit);
}

TRAZO_HD SurfacePoint objectSurface(const SceneView&, const CylinderShape& c, const ShapeHit& hit, Vec3 p,
                                    bool wantUv) {
    return wantUv ? surfaceWithFrame(hit, cylinderFrame(c, p, hit.normal)) : plainSurface(hit);
}

TRAZO_HD bool objectHasUvs(const SceneView&, const CylinderShape&) { return true; }

// o + t·d put back on the surface the hit's normal names: on a cap its height set exactly, on the side its
// radial part scaled to the radius; off it by a few ulps of the base, the height and the radius.
TRAZO_HD_DEVICE_CALL HitPoint objectHitPoint(const SceneView&, const CylinderShape& c, const Ray& ray, const ShapeHit& hit) {
    const HitPoint along = rayHitPoint(ray, hit.t, hit.normal);
    const Vec3 rel = along.p - c.base;
    float height = dot(rel, c.axis);
    Vec3 radial = rel - c.axis * height;
    Vec3 normal = hit.normal;
    const float towardsAxis = dot(hit.normal, c.axis);
    if (fabsf(towardsAxis) > 0.5f) {
        height = towardsAxis > 0.0f ? c.height : 0.0f;
    } else {
        const float r = length(radial);
        if (!(r > 0.0f)) return along;
        normal = radial * (1.0f / r);
        radial = normal * c.radius;
    }
    const Vec3 p = c.base + c.axis * height + radial;
    const Vec3 error = (abs(c.base) + abs(c.axis * height) + abs(radial) + abs(rel)) * roundoff(6.0f);
    return tighter(along, boundedHitPoint(p, error, normal));
}

inline Aabb objectBounds(const SceneView&, const CylinderShape& c) {
    // Each cap is a disk: along axis i it reaches r·√(1 − axisᵢ²) from its centre.
    const Vec3 reach = Vec3(std::sqrt(std::fmax(0.0f, 1.0f - c.axis.x * c.axis.x)),
                            std::sqrt(std::fmax(0.0f, 1.0f - c.axis.y * c.axis.y)),
                            std::sqrt(std::fmax(0.0f, 1.0f - c.axis.z * c.axis.z))) * c.radius;
    Aabb b;
    for (const Vec3 centre : {c.base, c.base + c.axis * c.height}) {
        b.grow(centre - reach);
        b.grow(centre + reach);
    }
    return b;
}

}  // namespace trazo
