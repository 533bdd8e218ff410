// The sphere object kind's kernel side (host and device): its shape, ray intersection (the stable quadratic of
// Ray Tracing Gems ch. 7, made exact where a huge sphere is seen from close by), texture frame and bounds; the
// host block is scene/kinds/sphere.h.
// Texture frame: u = longitude φ/2π with φ = atan2(−z, x) about +Y, v = 1 − polar angle/π (v = 1 at the top).
#pragma once

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

struct SphereShape {
    Vec3 center;
    float radius;
};

// intersectSphere: nearest hit with tMin < t < tMax; fills hit.t and the unit outward normal. From inside
// the sphere the hit is the exit point, whose outward normal points along the ray.
//
// |f + t·d|² = r² with f = o − centre: a·t² + 2b·t + c = 0 (b is half the textbook b; d need not be
// unit, so a = d·d stays in every formula and t remains in units of ray.direction). The roots are
// q/a and c/q with q = −b − sign(b)·√Δ, Δ = b² − a·c, which never cancels (RTG ch. 7, after
// Numerical Recipes §5.6). What is left to get right is the rounding of the inputs to q and c:
//  - c/q is the near root, so c must be good to a few ulps of itself. For a huge sphere seen from
//    close (a ground sphere), c = |f|² − r² is small while |f|² and r² are ~r²: the rounding of f
//    alone would cost ε·r². So f is kept exactly as fHi + fLo and c is a compensated sum.
//  - Δ: RTG writes it as a·(r² − |l|²), l = f − (b/a)·d the closest point of the line to the centre,
//    which avoids b² ≈ a·c cancelling for a small sphere far away. Its error is ~ε·a·|l|·(r + |l|),
//    and b² − a·c (from accurate b, c) errs by ~ε·(b² + a·|c|): each form is used where it is the
//    better one. l comes from d × (f × d)/a, with f × d compensated, so it is accurate to ε·|l|
//    rather than ε·|f| (RTG's subtraction) — and so is the normal, from l ∓ d·√Δ/a.
//
// The roots are written over the number type T (core/number_ops.h), once for a ray and for SIMD lanes
// (integrator/packets/packet_lanes.h), whose rays may share an origin (a Vec3 and floats where V and F are lanes).

// What the roots need of the ray's origin o, once for all rays from it: f = o − centre exactly as f + fLo
// (twoSum), c = |f + fLo|² − r², and the reject's reach².
template <class T>
struct SphereSetupOf {
    typename T::V f, fLo;
    typename T::F c, reach2;
};

// The cheap conservative reject (most rays miss most spheres): the line's squared distance to the centre is
// |f × d|²/|d|², off in plain float by a few ulps of |o| + |centre|; miss only beyond that margin, reach.
template <class T>
TRAZO_HD typename T::F sphereReach2(const SphereShape& s, const typename T::V& origin, const typename T::V& f) {
    const typename T::F margin =
        1e-5f * (maxComponent(abs(origin)) + maxComponent(abs(s.center)) + maxComponent(abs(f)));
    const typename T::F reach = s.radius + margin;
    return reach * reach;
}
template <class O, class D, class F>
TRAZO_HD auto sphereBeyondReach(const O& f, const D& d, F reach2) {
    const auto fd = cross(f, d);
    return dot(fd, fd) > reach2 * dot(d, d);
}

template <class T>
TRAZO_HD_HOT SphereSetupOf<T> sphereSetupOf(const SphereShape& s, const typename T::V& origin) {
    using Two = TwoOf<typename T::F>;
    const Two fx = twoSum(origin.x, T::splat(-s.center.x));
    const Two fy = twoSum(origin.y, T::splat(-s.center.y));
    const Two fz = twoSum(origin.z, T::splat(-s.center.z));
    SphereSetupOf<T> k;
    k.f = {fx.hi, fy.hi, fz.hi};
    k.fLo = {fx.lo, fy.lo, fz.lo};
    // (fHi + fLo)² = fHi² + 2·fHi·fLo + fLo²; fLo² is below an ulp of anything that matters here.
    k.c = lengthSquaredMinusSquareAccurateOf<T>(k.f, s.radius) + 2.0f * dot(k.f, k.fLo);
    k.reach2 = sphereReach2<T>(s, origin, k.f);  // twoSum's hi is o − centre in plain float
    return k;
}

template <class T>
struct SphereRootsOf {
    typename T::F tNear, tFar;  // tNear ≤ tFar
    typename T::V l;            // the closest point of the line to the centre, relative to the centre
    typename T::F halfChord;    // √Δ / a: the hit points are l ∓ d·halfChord
};
using SphereRoots = SphereRootsOf<ScalarOps>;

// The two roots of the lines from the setup's origin along d, where they meet the sphere: `live` keeps those rays.
// Whether any does.
template <class T, class Setup>
TRAZO_HD_HOT bool sphereRootsOf(const Setup& k, float r, const typename T::V& d, typename T::B& live,
                                SphereRootsOf<T>& out) {
    const auto& f = k.f;
    const auto& fLo = k.fLo;
    const auto c = k.c;
    const typename T::F a = dot(d, d);
    // Plain b suffices: near the surface f is almost along the normal, so f·d rounds relative to b.
    const typename T::F b = dot(f, d) + dot(fLo, d);
    const typename T::V l = cross(d, crossAccurate(f, d) + cross(fLo, d)) * (1.0f / a);
    const typename T::F lLength = length(l);

    // The form with the smaller of the two error estimates above (their common factor ε dropped).
    const typename T::B nearForm = b * b + a * T::abs(c) < a * lLength * (r + lLength);
    const typename T::F discriminant = nearForm ? T::fma(b, b, -a * c) : a * ((r - lLength) * (r + lLength));
    live = live & (discriminant >= 0.0f);  // also rejects NaN from a zero direction
    if (!T::any(live)) return false;
    const typename T::F root = T::sqrt(discriminant);
    const typename T::F q = -b - T::copysign(root, b);
    const typename T::F t0 = q / a;
    const typename T::F t1 = q != 0.0f ? c / q : t0;  // q = 0 only when the line touches the sphere at t = 0
    const typename T::B swap = t0 > t1;
    out = {swap ? t1 : t0, swap ? t0 : t1, l, root / a};
    return true;
}

// The two roots of the line through the ray, or false when it misses the sphere.
TRAZO_HD bool sphereRoots(const SphereShape& s, const Ray& ray, SphereRoots& out) {
    const Vec3 f = ray.origin - s.center;  // the reject before the compensated set-up: most rays miss
    if (sphereBeyondReach(f, ray.direction, sphereReach2<ScalarOps>(s, ray.origin, f))) return false;
    bool live = true;
    return sphereRootsOf<ScalarOps>(sphereSetupOf<ScalarOps>(s, ray.origin), s.radius, ray.direction, live, out);
}

TRAZO_HD bool intersectSphere(const SphereShape& s, const Ray& ray, float tMin, float tMax, ShapeHit& hit) {
    SphereRoots r;
    if (!sphereRoots(s, ray, r)) return false;
    // The hit point relative to the centre is l ∓ d·√Δ/a for the near/far root: small numbers only,
    // where f + t·d would carry the rounding of f and t, both ~ε·|f|.
    if (r.tNear > tMin && r.tNear < tMax) {
        hit.t = r.tNear;
        hit.normal = normalize(r.l - ray.direction * r.halfChord);
        return true;
    }
    if (r.tFar > tMin && r.tFar < tMax) {
        hit.t = r.tFar;
        hit.normal = normalize(r.l + ray.direction * r.halfChord);
        return true;
    }
    return false;
}

// Shadow rays: whether either root lies in (tMin, tMax), the same roots as intersectSphere, no normal.
TRAZO_HD bool sphereBlocks(const SphereShape& s, const Ray& ray, float tMin, float tMax) {
    SphereRoots r;
    if (!sphereRoots(s, ray, r)) return false;
    return (r.tNear > tMin && r.tNear < tMax) || (r.tFar > tMin && r.tFar < tMax);
}

TRAZO_HD SurfaceFrame sphereFrame(const SphereShape& s, Vec3 p) {
    const Vec3 n = normalize(p - s.center);
    const float ring = sqrtf(n.x * n.x + n.z * n.z);
    const Vec3 tangent = ring > 1e-6f ? Vec3(n.z, 0.0f, -n.x) / ring : anyOrthonormal(n);  // poles: any
    const float u = wrapUnit(atan2f(-n.z, n.x) * kInvTwoPi);
    const float v = 1.0f - acosf(fminf(1.0f, fmaxf(-1.0f, n.y))) * kInvPi;
    return {u, v, tangent, cross(n, tangent)};
}

// The object kind's interface (objects/visit_object.h dispatches to it).
TRAZO_HD bool intersectObject(const SceneView&, const SphereShape& s, const Ray& ray, float tMax, ClosestStack&,
                              ShapeHit& hit) {
    return intersectSphere(s, ray, 0.0f, tMax, hit);
}

TRAZO_HD bool objectBlocks(const SceneView&, const SphereShape& s, const Ray& ray, float tMax, AnyStack&) {
    return sphereBlocks(s, ray, 0.0f, tMax);
}

TRAZO_HD SurfacePoint objectSurface(const SceneView&, const SphereShape& s, const ShapeHit& hit, Vec3 p, bool wantUv) {
    return wantUv ? surfaceWithFrame(hit, sphereFrame(s, p)) : plainSurface(hit);
}

TRAZO_HD bool objectHasUvs(const SceneView&, const SphereShape&) { return true; }

// o + t·d pushed radially onto the sphere (pbrt-v4's reprojection): off it by a few ulps of the radius and of
// the sum, wherever the ray came from.
TRAZO_HD_DEVICE_CALL HitPoint objectHitPoint(const SceneView&, const SphereShape& s, const Ray& ray, const ShapeHit& hit) {
    const HitPoint along = rayHitPoint(ray, hit.t, hit.normal);
    const Vec3 fromCentre = along.p - s.center;
    const float distance = length(fromCentre);
    if (!(distance > 0.0f)) return along;
    const Vec3 outward = fromCentre * (1.0f / distance);
    const Vec3 rel = outward * s.radius;
    const Vec3 p = s.center + rel;
    return tighter(along, boundedHitPoint(p, abs(rel) * roundoff(6.0f) + abs(p) * roundoff(1.0f), outward));
}

inline Aabb objectBounds(const SceneView&, const SphereShape& s) {
    return Aabb{s.center - Vec3(s.radius), s.center + Vec3(s.radius)};
}

}  // namespace trazo
