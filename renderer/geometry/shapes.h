// The shapes as the kernels see them: plain structs in world space (boxes keep both transforms).
#pragma once

#include <cstdint>

#include "core/affine.h"
#include "core/vec3.h"

namespace trazo {

struct SphereShape {
    Vec3 center;
    float radius;
};

// The unit cube [-0.5, 0.5]³ mapped by worldFromObject (any parallelepiped).
struct BoxShape {
    Affine3 objectFromWorld;
    Affine3 worldFromObject;
};

// A capped cylinder: bottom cap centred at `base`, top cap at base + axis·height.
struct CylinderShape {
    Vec3 base;
    Vec3 axis;  // unit length
    float height;
    float radius;
};

// A rectangle (area light): centre ± halfU ± halfV; normal = unit normal. Two-sided.
struct RectangleShape {
    Vec3 center;
    Vec3 halfU;  // half the Width along u
    Vec3 halfV;  // half the Height along v
    Vec3 normal;
};

// What an intersection routine reports: the ray parameter and the unit outward geometric normal
// (outward = away from the solid's interior; for a rectangle, `normal` of the shape).
struct ShapeHit {
    float t;
    Vec3 normal;
    uint32_t triangle;  // meshes only: the triangle hit (index into SceneView::triangles) and its
    float b1, b2;       // barycentrics; analytic shapes leave these unset
};

}  // namespace trazo
