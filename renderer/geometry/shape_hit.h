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
    uint32_t triangle;  // meshes: the triangle hit (index into SceneView::triangles); boxes: the face,
                        // 2·axis + 1 for the + face; CSG solids: the leaf (node within the object)
    float b1, b2;       // meshes only: the triangle's barycentrics
};

}  // namespace trazo
