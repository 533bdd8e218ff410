// Ray queries against the whole scene: nearest hit (with visible area-light rectangles) and shadow any-hit.
// A linear loop over the objects for now; the two-level BVH of issue 3 replaces the loop, not the interface.
#pragma once

#include "device/scene_arrays.h"
#include "geometry/csg.h"
#include "geometry/intersect_box.h"
#include "geometry/intersect_cylinder.h"
#include "geometry/intersect_rectangle.h"
#include "geometry/intersect_sphere.h"

namespace trazo {

constexpr uint32_t kNoObject = 0xffffffffu;

struct SurfaceHit {
    float t;
    Vec3 normal;        // unit outward geometric normal
    uint32_t object;    // index into SceneView::objects, or kNoObject when a light rectangle was hit
    uint32_t areaLight; // index of the light rectangle hit (when object == kNoObject)
    uint32_t triangle;  // mesh hits: index into SceneView::triangles, with barycentrics b1, b2
    float b1, b2;
};

TRAZO_HD bool intersectObject(const SceneView& scene, const ObjectRef& o, const Ray& ray, float tMax, ShapeHit& hit) {
    switch (o.kind) {
        case ObjectKind::Sphere: return intersectSphere(scene.spheres[o.index], ray, 0.0f, tMax, hit);
        case ObjectKind::Box: return intersectBox(scene.boxes[o.index], ray, 0.0f, tMax, hit);
        case ObjectKind::Cylinder: return intersectCylinder(scene.cylinders[o.index], ray, 0.0f, tMax, hit);
        case ObjectKind::Csg: return intersectCsg(scene.csgs[o.index], scene.csgNodes.data, ray, 0.0f, tMax, hit);
    }
    return false;
}

// Nearest object or area-light rectangle along the ray, in (0, tMax).
TRAZO_HD bool intersectScene(const SceneView& scene, const Ray& ray, float tMax, SurfaceHit& out) {
    bool found = false;
    ShapeHit hit;
    for (uint32_t i = 0; i < scene.objects.count; ++i) {
        if (intersectObject(scene, scene.objects[i], ray, tMax, hit)) {
            tMax = hit.t;
            out = SurfaceHit{hit.t, hit.normal, i, 0, 0, 0.0f, 0.0f};
            found = true;
        }
    }
    for (uint32_t i = 0; i < scene.areaLights.count; ++i) {
        if (intersectRectangle(scene.areaLights[i].rect, ray, 0.0f, tMax, hit)) {
            tMax = hit.t;
            out = SurfaceHit{hit.t, hit.normal, kNoObject, i, 0, 0.0f, 0.0f};
            found = true;
        }
    }
    return found;
}

// True when any object blocks the segment (0, tMax). Light rectangles cast no shadow (SPEC §5).
TRAZO_HD bool occluded(const SceneView& scene, const Ray& ray, float tMax) {
    ShapeHit hit;
    for (uint32_t i = 0; i < scene.objects.count; ++i) {
        if (intersectObject(scene, scene.objects[i], ray, tMax, hit)) return true;
    }
    return false;
}

}  // namespace trazo
