// Watertight ray–triangle intersection (host and device): Woop, Benthin & Wald, "Watertight Ray/Triangle
// Intersection", JCGT 2(1), 2013. Rays through a shared edge or vertex hit at least one of its triangles.
#pragma once

#include "core/ray.h"

namespace trazo {

// The ray in the sheared space where it runs along +z from the origin: set up once per ray.
struct TriangleRay {
    Vec3 origin;
    int kx, ky, kz;    // kz = dominant axis of the direction; kx, ky swapped when it points down kz (keeps winding)
    float sx, sy, sz;  // shear: x' = x − sx·z, y' = y − sy·z, z' = sz·z
};

TRAZO_HD TriangleRay makeTriangleRay(const Ray& ray) {
    const Vec3 d = ray.direction;
    const Vec3 a = abs(d);
    int kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
    int kx = kz == 2 ? 0 : kz + 1;
    int ky = kx == 2 ? 0 : kx + 1;
    if (d[kz] < 0.0f) {
        const int s = kx;
        kx = ky;
        ky = s;
    }
    TriangleRay r;
    r.origin = ray.origin;
    r.kx = kx;
    r.ky = ky;
    r.kz = kz;
    r.sx = d[kx] / d[kz];
    r.sy = d[ky] / d[kz];
    r.sz = 1.0f / d[kz];
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

// Two-sided hit with tMin < t < tMax. Degenerate (zero-area) triangles and rays in the triangle's plane miss.
TRAZO_HD bool intersectTriangle(const TriangleRay& r, Vec3 p0, Vec3 p1, Vec3 p2, float tMin, float tMax,
                                TriangleHit& hit) {
    const Vec3 a = p0 - r.origin, b = p1 - r.origin, c = p2 - r.origin;
    const float ax = a[r.kx] - r.sx * a[r.kz], ay = a[r.ky] - r.sy * a[r.kz];
    const float bx = b[r.kx] - r.sx * b[r.kz], by = b[r.ky] - r.sy * b[r.kz];
    const float cx = c[r.kx] - r.sx * c[r.kz], cy = c[r.ky] - r.sy * c[r.kz];
    // Edge functions: u weighs p0, v p1, w p2. An exact zero (the ray through an edge) is re-evaluated in
    // double, where the products are exact, so both triangles of an edge see the same sign.
    float u = triangleEdge(cx, cy, bx, by);
    float v = triangleEdge(ax, ay, cx, cy);
    float w = triangleEdge(bx, by, ax, ay);
    if (u == 0.0f || v == 0.0f || w == 0.0f) {
        u = (float)((double)cx * (double)by - (double)cy * (double)bx);
        v = (float)((double)ax * (double)cy - (double)ay * (double)cx);
        w = (float)((double)bx * (double)ay - (double)by * (double)ax);
    }
    if ((u < 0.0f || v < 0.0f || w < 0.0f) && (u > 0.0f || v > 0.0f || w > 0.0f)) return false;
    const float det = u + v + w;
    if (det == 0.0f) return false;
    const float az = r.sz * a[r.kz], bz = r.sz * b[r.kz], cz = r.sz * c[r.kz];
    const float tScaled = u * az + v * bz + w * cz;
    const float invDet = 1.0f / det;
    const float t = tScaled * invDet;
    if (!(t > tMin && t < tMax)) return false;
    hit.t = t;
    hit.b1 = v * invDet;
    hit.b2 = w * invDet;
    return true;
}

}  // namespace trazo
