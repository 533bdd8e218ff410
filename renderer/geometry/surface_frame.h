// Texture coordinates and tangent frames of the analytic shapes, so textures and normal maps work on them
// (the thesis could texture meshes only). Every mapping is seen unmirrored from outside: tangent × bitangent
// = the outward normal, with the tangent along increasing u and the bitangent along increasing v.
//   Sphere:   u = longitude φ/2π with φ = atan2(−z, x) about +Y, v = 1 − polar angle/π (v = 1 at the top).
//   Box:      each face maps its unit square to [0,1]²; side faces have v up (+Y of the box), the top face
//             has u = +X and v = −Z, the bottom u = +X and v = +Z (all in the box's object space).
//   Cylinder: side u = angle about the axis / 2π, v = height / Height; caps map the disk of radius r to
//             the unit square, centred at (½, ½).
#pragma once

#include "core/vec3.h"
#include "geometry/shapes.h"

namespace trazo {

struct SurfaceFrame {
    float u, v;
    Vec3 tangent;    // unit, along increasing u
    Vec3 bitangent;  // unit, along increasing v
};

TRAZO_HD float wrapUnit(float x) { return x - floorf(x); }

constexpr float kInvTwoPi = 0.159154943091895f;
constexpr float kInvPi = 0.318309886183791f;

TRAZO_HD SurfaceFrame sphereFrame(const SphereShape& s, Vec3 p) {
    const Vec3 n = normalize(p - s.center);
    const float ring = sqrtf(n.x * n.x + n.z * n.z);
    const Vec3 tangent = ring > 1e-6f ? Vec3(n.z, 0.0f, -n.x) / ring : anyOrthonormal(n);  // poles: any
    const float u = wrapUnit(atan2f(-n.z, n.x) * kInvTwoPi);
    const float v = 1.0f - acosf(fminf(1.0f, fmaxf(-1.0f, n.y))) * kInvPi;
    return {u, v, tangent, cross(n, tangent)};
}

TRAZO_HD SurfaceFrame boxFrame(const BoxShape& box, Vec3 p) {
    const Vec3 q = box.objectFromWorld.applyToPoint(p);
    const Vec3 aq = abs(q);
    const int axis = aq.x >= aq.y && aq.x >= aq.z ? 0 : (aq.y >= aq.z ? 1 : 2);
    const float sign = q[axis] >= 0.0f ? 1.0f : -1.0f;
    Vec3 uAxis, vAxis;  // object-space directions of increasing u and v on this face
    if (axis == 0) {
        uAxis = Vec3(0.0f, 0.0f, -sign);
        vAxis = Vec3(0.0f, 1.0f, 0.0f);
    } else if (axis == 1) {
        uAxis = Vec3(1.0f, 0.0f, 0.0f);
        vAxis = Vec3(0.0f, 0.0f, -sign);
    } else {
        uAxis = Vec3(sign, 0.0f, 0.0f);
        vAxis = Vec3(0.0f, 1.0f, 0.0f);
    }
    return {dot(q, uAxis) + 0.5f, dot(q, vAxis) + 0.5f, normalize(box.worldFromObject.applyToVector(uAxis)),
            normalize(box.worldFromObject.applyToVector(vAxis))};
}

// `normal`: the unit outward normal of the hit (tells the side from the caps).
TRAZO_HD SurfaceFrame cylinderFrame(const CylinderShape& c, Vec3 p, Vec3 normal) {
    const Vec3 e1 = anyOrthonormal(c.axis);
    const Vec3 e2 = cross(c.axis, e1);
    const Vec3 r = p - c.base;
    const float along = dot(normal, c.axis);
    if (fabsf(along) > 0.5f) {  // a cap: its normal is ±axis
        const float s = along > 0.0f ? 1.0f : -1.0f;
        const Vec3 bitangent = e2 * s;
        const float scale = 0.5f / c.radius;
        return {dot(r, e1) * scale + 0.5f, dot(r, bitangent) * scale + 0.5f, e1, bitangent};
    }
    const float u = wrapUnit(atan2f(dot(r, e2), dot(r, e1)) * kInvTwoPi);
    const Vec3 radial = normalize(r - c.axis * dot(r, c.axis));
    return {u, dot(r, c.axis) / c.height, cross(c.axis, radial), c.axis};
}

}  // namespace trazo
