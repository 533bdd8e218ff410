// Affine3: a 3x4 affine transform (linear part + translation), for boxes, meshes and CSG solids.
#pragma once

#include "core/vec3.h"

namespace trazo {

struct Affine3 {
    // Rows of the linear part; row i gives output coordinate i.
    Vec3 row[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    Vec3 translation = {0, 0, 0};

    TRAZO_HD Vec3 applyToVector(Vec3 v) const { return {dot(row[0], v), dot(row[1], v), dot(row[2], v)}; }
    TRAZO_HD Vec3 applyToPoint(Vec3 p) const { return applyToVector(p) + translation; }
    // Transposed linear part applied to v; with the inverse transform this maps normals (inverse transpose).
    TRAZO_HD Vec3 applyTransposeToVector(Vec3 v) const {
        return row[0] * v.x + row[1] * v.y + row[2] * v.z;
    }
};

// The members as functions, for code written over the number type (core/number_ops.h), whose lanes overload them.
TRAZO_HD Vec3 applyToVector(const Affine3& m, Vec3 v) { return m.applyToVector(v); }
TRAZO_HD Vec3 applyToPoint(const Affine3& m, Vec3 p) { return m.applyToPoint(p); }

// this-then-other, i.e. other ∘ first: the result maps p to other(first(p)).
TRAZO_HD Affine3 then(const Affine3& first, const Affine3& other) {
    Affine3 r;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            r.row[i][j] = other.row[i].x * first.row[0][j] + other.row[i].y * first.row[1][j] +
                          other.row[i].z * first.row[2][j];
        }
    }
    r.translation = other.applyToPoint(first.translation);
    return r;
}

TRAZO_HD float determinant(const Affine3& a) { return dot(a.row[0], cross(a.row[1], a.row[2])); }

// The inverse in double precision: cofactors and determinant of a map scaled by s are s² and s³, which
// leave float's range for |s| beyond about 1e12 or below 1e-12 while the inverse itself (1/s) is fine.
TRAZO_HD Affine3 inverseInDouble(const Affine3& a) {
    double m[3][3], inv[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m[i][j] = a.row[i][j];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {  // inv[j][i] = cofactor (i, j)
            const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            inv[j][i] = m[i1][j1] * m[i2][j2] - m[i1][j2] * m[i2][j1];
        }
    const double invDet = 1.0 / (m[0][0] * inv[0][0] + m[0][1] * inv[1][0] + m[0][2] * inv[2][0]);
    Affine3 r;
    for (int i = 0; i < 3; ++i) r.row[i] = Vec3(float(inv[i][0] * invDet), float(inv[i][1] * invDet), float(inv[i][2] * invDet));
    for (int i = 0; i < 3; ++i)
        r.translation[i] = float(-(inv[i][0] * a.translation.x + inv[i][1] * a.translation.y + inv[i][2] * a.translation.z) * invDet);
    return r;
}

// Inverse of an affine map; the caller guarantees it is not singular (the scene reader refuses transforms
// whose inverse is not finite). In float where float holds every intermediate, otherwise in double.
TRAZO_HD Affine3 inverse(const Affine3& a) {
    const Vec3 c0 = cross(a.row[1], a.row[2]);
    const Vec3 c1 = cross(a.row[2], a.row[0]);
    const Vec3 c2 = cross(a.row[0], a.row[1]);
    const float det = dot(a.row[0], c0);
    // A determinant or cofactor that overflowed, or lost its precision below float's normal range, would
    // make the float inverse 0, inf or NaN.
    const float largest = fmaxf(fmaxf(maxComponent(abs(c0)), maxComponent(abs(c1))), maxComponent(abs(c2)));
    if (!(fabsf(det) >= 1.17549435e-38f && fabsf(det) < 3.0e38f && largest < 3.0e38f)) return inverseInDouble(a);
    const float invDet = 1.0f / det;
    Affine3 r;
    // The inverse's columns are the cofactor rows; transpose them into rows.
    r.row[0] = Vec3(c0.x, c1.x, c2.x) * invDet;
    r.row[1] = Vec3(c0.y, c1.y, c2.y) * invDet;
    r.row[2] = Vec3(c0.z, c1.z, c2.z) * invDet;
    r.translation = -r.applyToVector(a.translation);
    return r;
}

TRAZO_HD Affine3 makeTranslation(Vec3 t) {
    Affine3 r;
    r.translation = t;
    return r;
}

TRAZO_HD Affine3 makeScale(Vec3 s) {
    Affine3 r;
    r.row[0] = {s.x, 0, 0};
    r.row[1] = {0, s.y, 0};
    r.row[2] = {0, 0, s.z};
    return r;
}

// Rotation by angle radians about axis (right-handed, Rodrigues); axis need not be unit length.
TRAZO_HD Affine3 makeRotation(Vec3 axis, float angle) {
    const Vec3 a = normalize(axis);
    const float c = cosf(angle), s = sinf(angle), t = 1.0f - c;
    Affine3 r;
    r.row[0] = {t * a.x * a.x + c, t * a.x * a.y - s * a.z, t * a.x * a.z + s * a.y};
    r.row[1] = {t * a.x * a.y + s * a.z, t * a.y * a.y + c, t * a.y * a.z - s * a.x};
    r.row[2] = {t * a.x * a.z - s * a.y, t * a.y * a.z + s * a.x, t * a.z * a.z + c};
    return r;
}

}  // namespace trazo
