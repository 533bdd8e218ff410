// Mirror, glossy-cone and Snell refraction directions (SPEC §5 Reflection and Transmission).
#pragma once

#include "core/sin_cos.h"
#include "core/vec3.h"

namespace trazo {

// d incoming, n unit normal facing against d.
TRAZO_HD Vec3 reflectDirection(Vec3 d, Vec3 n) { return d - n * (2.0f * dot(d, n)); }

// Snell's law with eta = n_incident / n_transmitted; false on total internal reflection.
TRAZO_HD bool refractDirection(Vec3 d, Vec3 n, float eta, Vec3& out) {
    const float cosI = -dot(d, n);
    const float k = 1.0f - eta * eta * (1.0f - cosI * cosI);
    if (k < 0.0f) return false;
    out = normalize(d * eta + n * (eta * cosI - sqrtf(k)));
    return true;
}

// The tangent frame directionInCone turns about `axis`: made once for many directions about the same axis.
struct ConeFrame {
    Vec3 axis, t1, t2;
};

TRAZO_HD ConeFrame coneFrame(Vec3 axis) {
    const Vec3 t1 = anyOrthonormal(axis);
    return ConeFrame{axis, t1, cross(axis, t1)};
}

// A direction at polar angle theta and azimuth phi about the frame's unit axis.
// theta and phi: 0 ≤ angle < 2¹²·π/2 (sinCos).
TRAZO_HD Vec3 directionInCone(const ConeFrame& f, float theta, float phi) {
    float sinTheta, cosTheta, sinPhi, cosPhi;
    sinCos(theta, sinTheta, cosTheta);
    sinCos(phi, sinPhi, cosPhi);
    return normalize(f.axis * cosTheta + (f.t1 * cosPhi + f.t2 * sinPhi) * sinTheta);
}

// The same about a unit axis.
TRAZO_HD Vec3 directionInCone(Vec3 axis, float theta, float phi) {
    return directionInCone(coneFrame(axis), theta, phi);
}

}  // namespace trazo
