// Watertight ray–triangle intersection (host and device): Woop, Benthin & Wald, "Watertight Ray/Triangle
// Intersection", JCGT 2(1), 2013. Rays through a shared edge or vertex hit at least one of its triangles.
#pragma once

#include "core/host_simd.h"
#include "core/ray.h"

namespace trazo {

// The ray in the sheared space where it runs along +z from the origin: set up once per ray.
struct TriangleRay {
    Vec3 origin;
    int kx, ky, kz;    // kz = dominant axis of the direction; kx, ky = the next two axes, cyclically
    float sx, sy, sz;  // shear: x' = x − sx·z, y' = y − sy·z, z' = sz·z
};

// The paper swaps kx and ky when the ray points down kz, to keep the winding for back-face culling. The test
// below is two-sided, and the swap only negates all three edge functions, det and the scaled t together
// (exactly: every step is a product or difference whose sign flips), leaving hit/miss, t, b1 and b2 the same
// (checked against the swapping version on 2·10^7 random rays and triangles rich in zeros and shared planes;
// at most the sign of a zero t differs). Without it kx, ky follow from kz, so the host specialises on kz alone.
TRAZO_HD TriangleRay makeTriangleRay(const Ray& ray) {
    const Vec3 d = ray.direction;
    const Vec3 a = abs(d);
    const int kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
    const int kx = kz == 2 ? 0 : kz + 1;
    const int ky = kx == 2 ? 0 : kx + 1;
    const float dx = kx == 0 ? d.x : (kx == 1 ? d.y : d.z);
    const float dy = ky == 0 ? d.x : (ky == 1 ? d.y : d.z);
    const float dz = kz == 0 ? d.x : (kz == 1 ? d.y : d.z);
    TriangleRay r;
    r.origin = ray.origin;
    r.kx = kx;
    r.ky = ky;
    r.kz = kz;
#if TRAZO_HOST_SSE
    // The three quotients as one vector division: the same IEEE results, the divider busy a third as long (with
    // makeBoxRay's, bvh_bench's random bunny rays 3 % faster).
    alignas(16) float s[4];
    _mm_store_ps(s, _mm_div_ps(_mm_setr_ps(dx, dy, 1.0f, 1.0f), _mm_setr_ps(dz, dz, dz, 1.0f)));
    r.sx = s[0], r.sy = s[1], r.sz = s[2];
#else
    r.sx = dx / dz;
    r.sy = dy / dz;
    r.sz = 1.0f / dz;
#endif
    return r;
}

// The 2-D cross product px·qy − py·qx rounded as written. Watertightness needs edge(p, q) == −edge(q, p)
// exactly; a fused multiply-add (nvcc contracts by default, and the CUDA build uses --use_fast_math) would break that
// symmetry, so on the device the products and the difference are pinned with _rn intrinsics.
TRAZO_HD float triangleEdge(float px, float py, float qx, float qy) {
#if defined(__CUDA_ARCH__)
    return __fsub_rn(__fmul_rn(px, qy), __fmul_rn(py, qx));
#else
    return px * qy - py * qx;  // x86-64 without -mfma has no fused multiply-add to contract into
#endif
}

struct TriangleHit {
    float t, b1, b2;  // p = (1 − b1 − b2)·p0 + b1·p1 + b2·p2
};

namespace triangle_detail {

// A vertex relative to the ray origin in the sheared space (x', y'), and its z before the sz scale.
struct Sheared {
    float x, y, z;
};

TRAZO_HD Sheared shear(float px, float py, float pz, const TriangleRay& r) {  // p's components along kx, ky, kz
    return {px - r.sx * pz, py - r.sy * pz, pz};
}

// The test proper, once the three vertices are sheared (a, b, c: p0, p1, p2 relative to the origin).
TRAZO_HD bool intersectSheared(const TriangleRay& r, Sheared a, Sheared b, Sheared c, float tMin, float tMax,
                               TriangleHit& hit) {
    // Edge functions: u weighs p0, v p1, w p2. An exact zero (the ray through an edge) is re-evaluated in
    // double, where the products are exact, so both triangles of an edge see the same sign.
    float u = triangleEdge(c.x, c.y, b.x, b.y);
    float v = triangleEdge(a.x, a.y, c.x, c.y);
    float w = triangleEdge(b.x, b.y, a.x, a.y);
    if (u == 0.0f || v == 0.0f || w == 0.0f) {
        u = (float)((double)c.x * (double)b.y - (double)c.y * (double)b.x);
        v = (float)((double)a.x * (double)c.y - (double)a.y * (double)c.x);
        w = (float)((double)b.x * (double)a.y - (double)b.y * (double)a.x);
    }
    // Mixed signs miss. (A NaN is ignored here as it was in the original test; det and t are NaN then, and miss.)
    if ((u < 0.0f || v < 0.0f || w < 0.0f) && (u > 0.0f || v > 0.0f || w > 0.0f)) return false;
    const float det = u + v + w;
    if (det == 0.0f) return false;
    const float az = r.sz * a.z, bz = r.sz * b.z, cz = r.sz * c.z;
    const float tScaled = u * az + v * bz + w * cz;
    const float invDet = 1.0f / det;
    const float t = tScaled * invDet;
    if (!(t > tMin && t < tMax)) return false;
    hit.t = t;
    hit.b1 = v * invDet;
    hit.b2 = w * invDet;
    return true;
}

#if !TRAZO_DEVICE_PATHS
// Host: the axes as compile-time constants, so the vertices are read without selecting components.
template <int KZ>
inline bool intersectAlong(const TriangleRay& r, Vec3 p0, Vec3 p1, Vec3 p2, float tMin, float tMax, TriangleHit& hit) {
    const Vec3 a = p0 - r.origin, b = p1 - r.origin, c = p2 - r.origin;
    if constexpr (KZ == 0)
        return intersectSheared(r, shear(a.y, a.z, a.x, r), shear(b.y, b.z, b.x, r), shear(c.y, c.z, c.x, r), tMin,
                                tMax, hit);
    else if constexpr (KZ == 1)
        return intersectSheared(r, shear(a.z, a.x, a.y, r), shear(b.z, b.x, b.y, r), shear(c.z, c.x, c.y, r), tMin,
                                tMax, hit);
    else
        return intersectSheared(r, shear(a.x, a.y, a.z, r), shear(b.x, b.y, b.z, r), shear(c.x, c.y, c.z, r), tMin,
                                tMax, hit);
}
#endif

}  // namespace triangle_detail

// Two-sided hit with tMin < t < tMax. Degenerate (zero-area) triangles and rays in the triangle's plane miss.
TRAZO_HD bool intersectTriangle(const TriangleRay& r, Vec3 p0, Vec3 p1, Vec3 p2, float tMin, float tMax,
                                TriangleHit& hit) {
#if TRAZO_DEVICE_PATHS
    // Device: components picked at run time (selects); a switch on kz would diverge across incoherent rays.
    const Vec3 a = p0 - r.origin, b = p1 - r.origin, c = p2 - r.origin;
    return triangle_detail::intersectSheared(r, triangle_detail::shear(a[r.kx], a[r.ky], a[r.kz], r),
                                             triangle_detail::shear(b[r.kx], b[r.ky], b[r.kz], r),
                                             triangle_detail::shear(c[r.kx], c[r.ky], c[r.kz], r), tMin, tMax, hit);
#else
    // Host: one branch per triangle, the same way for every triangle a ray meets (so well predicted).
    if (r.kz == 2) return triangle_detail::intersectAlong<2>(r, p0, p1, p2, tMin, tMax, hit);
    if (r.kz == 0) return triangle_detail::intersectAlong<0>(r, p0, p1, p2, tMin, tMax, hit);
    return triangle_detail::intersectAlong<1>(r, p0, p1, p2, tMin, tMax, hit);
#endif
}

}  // namespace trazo
