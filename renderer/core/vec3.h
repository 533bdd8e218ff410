// Vec3: the float 3-vector used for points, directions and RGB colours, on host and device.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>

#include "core/hd.h"

namespace trazo {

struct Vec3 {
    float x = 0.0f, y = 0.0f, z = 0.0f;

    Vec3() = default;
    TRAZO_HD constexpr Vec3(float xIn, float yIn, float zIn) : x(xIn), y(yIn), z(zIn) {}
    TRAZO_HD explicit constexpr Vec3(float v) : x(v), y(v), z(v) {}

    TRAZO_HD float operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    TRAZO_HD float& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
};

// min and max of two floats without libm's NaN rules: on the host fminf/fmaxf are calls unless
// -ffinite-math-only; a comparison is one minss/maxss. A NaN argument gives the second operand.
TRAZO_HD float minOf(float a, float b) {
#if TRAZO_DEVICE_PATHS
    return fminf(a, b);
#else
    return a < b ? a : b;
#endif
}
TRAZO_HD float maxOf(float a, float b) {
#if TRAZO_DEVICE_PATHS
    return fmaxf(a, b);
#else
    return a > b ? a : b;
#endif
}

// The bits of a float and back (host: memcpy, which compilers turn into a register move).
TRAZO_HD uint32_t floatBits(float v) {
#if defined(__CUDA_ARCH__)
    return __float_as_uint(v);
#else
    uint32_t u;
    std::memcpy(&u, &v, sizeof u);
    return u;
#endif
}
TRAZO_HD float bitsFloat(uint32_t u) {
#if defined(__CUDA_ARCH__)
    return __uint_as_float(u);
#else
    float v;
    std::memcpy(&v, &u, sizeof v);
    return v;
#endif
}

TRAZO_HD Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
TRAZO_HD Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
TRAZO_HD Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
TRAZO_HD Vec3 operator*(Vec3 a, Vec3 b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
TRAZO_HD Vec3 operator*(Vec3 a, float s) { return {a.x * s, a.y * s, a.z * s}; }
TRAZO_HD Vec3 operator*(float s, Vec3 a) { return {a.x * s, a.y * s, a.z * s}; }
TRAZO_HD Vec3 operator/(Vec3 a, float s) { return a * (1.0f / s); }
TRAZO_HD Vec3 operator/(Vec3 a, Vec3 b) { return {a.x / b.x, a.y / b.y, a.z / b.z}; }
TRAZO_HD Vec3& operator+=(Vec3& a, Vec3 b) { a = a + b; return a; }
TRAZO_HD Vec3& operator-=(Vec3& a, Vec3 b) { a = a - b; return a; }
TRAZO_HD Vec3& operator*=(Vec3& a, Vec3 b) { a = a * b; return a; }
TRAZO_HD Vec3& operator*=(Vec3& a, float s) { a = a * s; return a; }

TRAZO_HD float dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
TRAZO_HD Vec3 cross(Vec3 a, Vec3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
TRAZO_HD float lengthSquared(Vec3 a) { return dot(a, a); }
TRAZO_HD float length(Vec3 a) { return sqrtf(dot(a, a)); }
TRAZO_HD Vec3 normalize(Vec3 a) { return a * (1.0f / sqrtf(dot(a, a))); }
TRAZO_HD Vec3 abs(Vec3 a) { return {fabsf(a.x), fabsf(a.y), fabsf(a.z)}; }
TRAZO_HD Vec3 min(Vec3 a, Vec3 b) { return {fminf(a.x, b.x), fminf(a.y, b.y), fminf(a.z, b.z)}; }
TRAZO_HD Vec3 max(Vec3 a, Vec3 b) { return {fmaxf(a.x, b.x), fmaxf(a.y, b.y), fmaxf(a.z, b.z)}; }
TRAZO_HD float maxComponent(Vec3 a) { return maxOf(a.x, maxOf(a.y, a.z)); }
TRAZO_HD bool isBlack(Vec3 a) { return a.x == 0.0f && a.y == 0.0f && a.z == 0.0f; }
TRAZO_HD bool isFinite(float a) {
#if defined(__CUDA_ARCH__)
    return isfinite(a);
#else
    return std::isfinite(a);
#endif
}
TRAZO_HD bool isFinite(Vec3 a) { return isFinite(a.x) && isFinite(a.y) && isFinite(a.z); }
TRAZO_HD Vec3 lerp(Vec3 a, Vec3 b, float t) { return a * (1.0f - t) + b * t; }

// Any unit vector orthogonal to n (n must be unit length); Duff et al. 2017, branch-free and stable.
TRAZO_HD Vec3 anyOrthonormal(Vec3 n) {
    const float sign = copysignf(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    return {1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x};
}

}  // namespace trazo
