// Mirror, glossy-cone and Snell refraction directions (SPEC §5 Reflection and Transmission).
#pragma once

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

// A direction at polar angle theta and azimuth phi about the unit axis.
TRAZO_HD Vec3 directionInCone(Vec3 axis, float theta, float phi) {
    const Vec3 t1 = anyOrthonormal(axis);
    const Vec3 t2 = cross(axis, t1);
    const float sinTheta = sinf(theta);
    return normalize(axis * cosf(theta) + (t1 * cosf(phi) + t2 * sinf(phi)) * sinTheta);
}

}  // namespace trazo
