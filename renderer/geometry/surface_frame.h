// What shading needs at a hit beyond the hit itself (host and device): SurfacePoint, the shading normal and
// texture frame, and SurfaceFrame, the texture coordinates and tangents each object kind maps its surface
// to (objects/<kind>.h), so textures and normal maps work on analytic shapes too (the thesis could texture
// meshes only). Every mapping is seen unmirrored from outside: tangent × bitangent = the outward normal,
// with the tangent along increasing u and the bitangent along increasing v.
#pragma once

#include "core/hd.h"
#include "core/vec3.h"
#include "geometry/shape_hit.h"

namespace trazo {

struct SurfaceFrame {
    float u, v;
    Vec3 tangent;    // unit, along increasing u
    Vec3 bitangent;  // unit, along increasing v
};

TRAZO_HD float wrapUnit(float x) { return x - floorf(x); }

constexpr float kInvTwoPi = 0.159154943091895f;
constexpr float kInvPi = 0.318309886183791f;

struct SurfacePoint {
    Vec3 ng;  // unit outward geometric normal
    Vec3 n;   // unit outward shading normal
    bool hasUv;
    float u, v;
    Vec3 tangent, bitangent;  // unit; along increasing u and v (only when hasUv)
};

// A surface without texture coordinates: both normals the hit's.
TRAZO_HD SurfacePoint plainSurface(const ShapeHit& hit) {
    return SurfacePoint{hit.normal, hit.normal, false, 0.0f, 0.0f, Vec3(0.0f), Vec3(0.0f)};
}

// The hit's normals with the texture frame `f`.
TRAZO_HD SurfacePoint surfaceWithFrame(const ShapeHit& hit, const SurfaceFrame& f) {
    return SurfacePoint{hit.normal, hit.normal, true, f.u, f.v, f.tangent, f.bitangent};
}

}  // namespace trazo
