// Ray–box slab test with the ray's inverse direction precomputed once per ray (host and device).
#pragma once

#include "core/ray.h"

namespace trazo {

struct BoxRay {
    Vec3 origin;
    Vec3 invDirection;  // ±inf for a zero component (the sign of the zero picks which infinity)
};

TRAZO_HD BoxRay makeBoxRay(const Ray& ray) {
    return {ray.origin, Vec3(1.0f / ray.direction.x, 1.0f / ray.direction.y, 1.0f / ray.direction.z)};
}

// Widens each box's exit distance by 2·gamma(3) so rounding never culls a box a contained primitive is hit
// in (pbrt-v4, Bounds3::IntersectP), and lets a box whose entry ties tMax within rounding still be visited.
constexpr float kBoxExitScale = 1.0f + 2.0f * 3.0f * 0.5f * 1.1920929e-7f / (1.0f - 3.0f * 0.5f * 1.1920929e-7f);

// Whether the ray meets the closed box [boundsMin, boundsMax] within [tMin, tMax]; tEntry = where it enters.
// Slab planes are picked by the direction's sign, so a zero component gives (b − o)·inf: ±inf, or NaN when
// the origin lies on that plane. The comparisons below ignore a NaN (they keep the running bound), so a ray
// parallel to a slab is kept exactly when it lies inside or on it.
TRAZO_HD bool intersectBounds(const BoxRay& r, Vec3 boundsMin, Vec3 boundsMax, float tMin, float tMax, float& tEntry) {
    float t0 = tMin, t1 = tMax;
    for (int a = 0; a < 3; ++a) {
        const bool negative = r.invDirection[a] < 0.0f;
        const float tNear = ((negative ? boundsMax[a] : boundsMin[a]) - r.origin[a]) * r.invDirection[a];
        const float tFar = ((negative ? boundsMin[a] : boundsMax[a]) - r.origin[a]) * r.invDirection[a];
        t0 = tNear > t0 ? tNear : t0;
        t1 = tFar < t1 ? tFar : t1;
    }
    tEntry = t0;
    return t0 <= t1 * kBoxExitScale;
}

}  // namespace trazo
