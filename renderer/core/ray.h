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
// the error of t itself, which is relative to t). It grows with |o|: a camera far from what it sees makes it
// large, so each object kind also computes its hit point from the surface itself (HitPoint below).
TRAZO_HD Vec3 hitPointError(const Ray& r, float t) {
    constexpr float kRelative = 64.0f * 1.1920929e-7f;  // 64 ulps
    return (abs(r.origin) + abs(r.direction * t)) * kRelative;
}

// The next float above / below v (pbrt-v4's NextFloatUp/Down): a bit step, where libm's nextafterf is a
// call on the host. ±0 step to the smallest subnormal of that direction; ±∞ and NaN stay.
TRAZO_HD float nextFloatUp(float v) {
    if (!(v < INFINITY)) return v;
    if (v == 0.0f) return 1.4e-45f;
    uint32_t bits = floatBits(v);
    bits = v > 0.0f ? bits + 1u : bits - 1u;
    return bitsFloat(bits);
}
TRAZO_HD float nextFloatDown(float v) { return -nextFloatUp(-v); }

// Moves p off its surface along the geometric normal ng, to the side `towards` points at, by the
// error bound projected on the normal (pbrt-v4's OffsetRayOrigin), then one more ulp outwards.
// The distance along ng is offsetDistance; bumpedOrigin applies an offset and the extra ulp.
TRAZO_HD float offsetDistance(Vec3 pError, Vec3 ng) { return dot(abs(ng), pError); }

TRAZO_HD Vec3 bumpedOrigin(Vec3 p, Vec3 offset) {
    Vec3 po = p + offset;
    for (int i = 0; i < 3; ++i) {
        if (offset[i] > 0.0f) po[i] = nextFloatUp(po[i]);
        else if (offset[i] < 0.0f) po[i] = nextFloatDown(po[i]);
    }
    return po;
}

TRAZO_HD_HOT Vec3 offsetRayOrigin(Vec3 p, float offset, Vec3 ng, Vec3 towards) {
    return bumpedOrigin(p, dot(towards, ng) < 0.0f ? -(ng * offset) : ng * offset);
}
TRAZO_HD Vec3 offsetRayOrigin(Vec3 p, Vec3 pError, Vec3 ng, Vec3 towards) {
    return offsetRayOrigin(p, offsetDistance(pError, ng), ng, towards);
}

// A hit point, the unit outward geometric normal there, and how far along it the point's error bound reaches
// (offsetDistance): what a ray leaving the point needs. A point put back on a curved surface from o + t·d is not
// where the ray met it (o + t·d errs along the ray by ulps of the ray's length): it takes the normal of where it is.
struct HitPoint {
    Vec3 p;
    Vec3 normal;
    float offset;
};

// n units of roundoff (2⁻²⁴), pbrt-v4's γ(n) without its 1/(1 − nε): the bounds use n with room to spare.
TRAZO_HD constexpr float roundoff(float n) { return n * 5.96046448e-8f; }

TRAZO_HD_HOT HitPoint boundedHitPoint(Vec3 p, Vec3 error, Vec3 normal) {
    return HitPoint{p, normal, offsetDistance(error, normal)};
}

TRAZO_HD_HOT HitPoint rayHitPoint(const Ray& r, float t, Vec3 normal) {
    return boundedHitPoint(pointAt(r, t), hitPointError(r, t), normal);
}

// Of two estimates of one hit point, the one whose bound reaches less far: the surface's own computation where
// the ray came from far away, o + t·d where it started close (a huge ground sphere beside the camera, whose own
// bound is a few ulps of its radius).
TRAZO_HD_HOT HitPoint tighter(const HitPoint& a, const HitPoint& b) { return b.offset < a.offset ? b : a; }

}  // namespace trazo
