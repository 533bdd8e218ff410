// Ray and the floating-point-aware offset that keeps secondary rays off the surface they leave.
#pragma once

#include "core/vec3.h"

namespace trazo {

struct Ray {
    Vec3 origin;
    Vec3 direction;  // not necessarily unit length for object-space rays; world rays are unit
};

TRAZO_HD Vec3 pointAt(const Ray& r, float t) { return r.origin + r.direction * t; }

// Conservative bound on the error of a hit point computed as o + t·d (a few ulps of each term, plus
// the error of t itself, which is relative to t). Scales with the scene, so it works at any scale.
TRAZO_HD Vec3 hitPointError(const Ray& r, float t) {
    constexpr float kRelative = 64.0f * 1.1920929e-7f;  // 64 ulps
    return (abs(r.origin) + abs(r.direction * t)) * kRelative;
}

// Moves p off its surface along the geometric normal ng, to the side `towards` points at, by the
// error bound projected on the normal (pbrt-v4's OffsetRayOrigin), then one more ulp outwards.
TRAZO_HD Vec3 offsetRayOrigin(Vec3 p, Vec3 pError, Vec3 ng, Vec3 towards) {
    const float d = dot(abs(ng), pError);
    Vec3 offset = ng * d;
    if (dot(towards, ng) < 0.0f) offset = -offset;
    Vec3 po = p + offset;
    for (int i = 0; i < 3; ++i) {
        if (offset[i] > 0.0f) po[i] = nextafterf(po[i], INFINITY);
        else if (offset[i] < 0.0f) po[i] = nextafterf(po[i], -INFINITY);
    }
    return po;
}

}  // namespace trazo
