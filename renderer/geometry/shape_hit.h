// ShapeHit: what every intersection routine reports (host and device).
#pragma once

#include <cstdint>

#include "core/vec3.h"

namespace trazo {

// The ray parameter and the unit outward geometric normal (outward = away from the solid's interior; for
// a rectangle, the shape's own normal).
struct ShapeHit {
    float t;
    Vec3 normal;
    uint32_t triangle;  // meshes only: the triangle hit (index into SceneView::triangles) and its
    float b1, b2;       // barycentrics; analytic shapes leave these unset
};

}  // namespace trazo
