// Ray–box slab test with the ray's inverse direction precomputed once per ray (host and device).
#pragma once

#include "core/host_simd.h"
#include "core/ray.h"

namespace trazo {

struct BoxRay {
    Vec3 origin;
    Vec3 invDirection;  // ±inf for a zero component (the sign of the zero picks which infinity)
};

TRAZO_HD BoxRay makeBoxRay(const Ray& ray) {
#if TRAZO_HOST_SSE  // one vector division: the same quotients, a third of the divider's time (as makeTriangleRay)
    alignas(16) float inv[4];
    const __m128 d = _mm_setr_ps(ray.direction.x, ray.direction.y, ray.direction.z, 1.0f);
    _mm_store_ps(inv, _mm_div_ps(_mm_set1_ps(1.0f), d));
    return {ray.origin, Vec3(inv[0], inv[1], inv[2])};
#else
    return {ray.origin, Vec3(1.0f / ray.direction.x, 1.0f / ray.direction.y, 1.0f / ray.direction.z)};
#endif
}

// Widens each box's exit distance by 2·gamma(3) so rounding never culls a box a contained primitive is hit
// in (pbrt-v4, Bounds3::IntersectP), and lets a box whose entry ties tMax within rounding still be visited.
constexpr float kBoxExitScale = 1.0f + 2.0f * 3.0f * 0.5f * 1.1920929e-7f / (1.0f - 3.0f * 0.5f * 1.1920929e-7f);

// One axis of the slab test: narrows [t0, t1] to where the ray is between the planes `lo` and `hi`, taken
// in the order the ray crosses them (negative: hi first). A zero direction component gives (b − o)·inf: ±inf,
// or NaN when the origin lies on that plane; the comparisons ignore a NaN (they keep the running bound), so
// a ray parallel to a slab is kept exactly when it lies inside or on it.
TRAZO_HD void narrowSlab(float lo, float hi, float origin, float invDirection, float& t0, float& t1) {
    const bool negative = invDirection < 0.0f;
    const float tNear = ((negative ? hi : lo) - origin) * invDirection;
    const float tFar = ((negative ? lo : hi) - origin) * invDirection;
    t0 = tNear > t0 ? tNear : t0;
    t1 = tFar < t1 ? tFar : t1;
}

// Whether the ray meets the closed box [boundsMin, boundsMax] within [tMin, tMax]; tEntry = where it enters.
TRAZO_HD bool intersectBounds(const BoxRay& r, Vec3 boundsMin, Vec3 boundsMax, float tMin, float tMax, float& tEntry) {
    float t0 = tMin, t1 = tMax;
    narrowSlab(boundsMin.x, boundsMax.x, r.origin.x, r.invDirection.x, t0, t1);
    narrowSlab(boundsMin.y, boundsMax.y, r.origin.y, r.invDirection.y, t0, t1);
    narrowSlab(boundsMin.z, boundsMax.z, r.origin.z, r.invDirection.z, t0, t1);
    tEntry = t0;
    return t0 <= t1 * kBoxExitScale;
}

}  // namespace trazo
