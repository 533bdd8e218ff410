// The cylinder object kind (host and device): a capped cylinder, its ray intersection (the side quadratic
// plus two disks), texture frame and bounds (the host block: scene/kinds/cylinder.h). Texture frame: side u = angle about the axis / 2π,
// v = height / Height; caps map the disk of radius r to the unit square, centred at (½, ½).
#pragma once

#include <initializer_list>

#include "accel/bvh_traverse.h"
#include "core/aabb.h"
#include "core/hd.h"
#include "core/number_ops.h"
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

// The nearest t in (tMin, tBest) among the side and both caps, written over the number type T
// (core/number_ops.h) for a ray and for SIMD lanes (integrator/packets/packet_lanes.h, whose rays may share an
// origin, a Vec3): returns the rays of `live` that hit, their t in tBest and, where asked, the outward normal's
// direction (not unit) in *normal. Closed: a ray through the rim hits.
template <class T, class O>
TRAZO_HD_HOT typename T::B cylinderHitsOf(const CylinderShape& cyl, const O& origin, const typename T::V& d,
                                          float tMin, typename T::B live, typename T::F& tBest,
                                          typename T::V* normal) {
    using F = typename T::F;
    using B = typename T::B;
    const Vec3 axis = cyl.axis;
    const float r = cyl.radius;
    const O f = origin - cyl.base;
    // axis × v is v's component orthogonal to the axis, turned by 90° about it (|axis| = 1): the side
    // is |F + t·D| = r, a quadratic in the plane orthogonal to the axis. Compensated cross products
    // keep |D| right for a ray nearly along the axis, and exactly 0 for one along it.
    const O fPerp = crossAccurate(axis, f);
    const typename T::V dPerp = crossAccurate(axis, d);
    const auto fAlong = dot(axis, f);  // height above the base cap
    const F dAlong = dot(axis, d);
    B found = B{};

    // Side. a = 0 exactly for a ray parallel to the axis: it cannot cross the side, only the caps.
    const F a = dot(dPerp, dPerp);
    const B side = live & (a > 0.0f);
    if (T::any(side)) {
        // RTG ch. 7's stable quadratic, in the cross-section. Unlike intersectSphere, c is not
        // compensated: a cylinder huge beside the camera is not worth the arithmetic.
        const F b = dot(fPerp, dPerp);
        const typename T::V l = fPerp - dPerp * (b / a);
        const F lLength = length(l);
        const F discriminant = a * ((r - lLength) * (r + lLength));
        const B roots = side & (discriminant >= 0.0f);
        if (T::any(roots)) {
            const F q = -b - T::copysign(T::sqrt(discriminant), b);
            const auto c = dot(fPerp, fPerp) - r * r;
            const F t0 = q / a;
            const F t1 = q != 0.0f ? c / q : t0;
            const B swap = t0 > t1;
            // A root counts only between the caps; the nearer one wins if both do (then the farther is not
            // below tBest).
            for (int i = 0; i < 2; ++i) {
                const F t = i == 0 ? (swap ? t1 : t0) : (swap ? t0 : t1);
                const F height = fAlong + t * dAlong;
                const B hit = roots & (t > tMin) & (t < tBest) & (height >= 0.0f) & (height <= cyl.height);
                tBest = hit ? t : tBest;
                found = found | hit;
                // (axis × p) × axis is p's radial component: the outward normal's direction.
                if (normal && T::any(hit)) *normal = T::select(hit, cross(fPerp + dPerp * t, axis), *normal);
            }
        }
    }

    // Caps: the planes height = 0 (normal −axis) and height = h (normal +axis), within the radius.
    // dAlong = 0 for a ray parallel to the caps: it meets them only through the side.
    const B caps = live & (dAlong != 0.0f);
    if (T::any(caps)) {
        for (int i = 0; i < 2; ++i) {
            const float capHeight = i == 0 ? 0.0f : cyl.height;
            const F t = (capHeight - fAlong) / dAlong;
            const typename T::V radial = fPerp + dPerp * t;
            const B hit = caps & (t > tMin) & (t < tBest) & (dot(radial, radial) <= r * r);
            tBest = hit ? t : tBest;
            found = found | hit;
            if (normal && T::any(hit)) *normal = T::select(hit, T::splat(i == 0 ? -axis : axis), *normal);
        }
    }
    return found;
}

// Nearest hit with tMin < t < tMax among the side and both caps; fills hit.t and the unit outward
// normal. From inside, the hit is the exit point.
TRAZO_HD bool intersectCylinder(const CylinderShape& cyl, const Ray& ray, float tMin, float tMax, ShapeHit& hit) {
    float tBest = tMax;
    Vec3 normal;
    if (!cylinderHitsOf<ScalarOps>(cyl, ray.origin, ray.direction, tMin, true, tBest, &normal)) return false;
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
