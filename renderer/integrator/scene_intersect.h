// Ray queries against the whole scene: nearest hit (with visible area-light rectangles) and shadow any-hit.
// Two levels of BVH: the top level over the scene's objects (SceneView::topNodes, objects in its leaf
// order), and one per mesh over its triangles. Area-light rectangles are few and tested one by one.
#pragma once

#include "accel/bvh_traverse.h"
#include "device/scene_arrays.h"
#include "geometry/csg.h"
#include "geometry/intersect_box.h"
#include "geometry/intersect_cylinder.h"
#include "geometry/intersect_rectangle.h"
#include "geometry/intersect_sphere.h"
#include "geometry/intersect_triangle_leaf.h"

namespace trazo {

constexpr uint32_t kNoObject = 0xffffffffu;
static_assert(kBvhMaxLeafSize <= kMaxLeafTriangles, "a mesh leaf must fit intersectTriangleLeaf");

struct SurfaceHit {
    float t;
    Vec3 normal;        // unit outward geometric normal
    uint32_t object;    // index into SceneView::objects, or kNoObject when a light rectangle was hit
    uint32_t areaLight; // index of the light rectangle hit (when object == kNoObject)
    uint32_t triangle;  // mesh hits: index into SceneView::triangles, with barycentrics b1, b2
    float b1, b2;
};

// Nearest triangle of the mesh in (tMin, tMax); the normal follows the triangle's winding (p0, p1, p2).
TRAZO_HD bool intersectMesh(const SceneView& scene, const MeshShape& mesh, const Ray& ray, float tMin, float tMax,
                            ClosestStack& stack, ShapeHit& hit) {
    const TriangleRay tr = makeTriangleRay(ray);
    const MeshTriangle* triangles = scene.triangles.data + mesh.triangleOffset;
    uint32_t best = 0;
    TriangleHit bestHit{};
    auto leaf = [&](uint32_t first, uint32_t count, float& tNearest) {
        uint32_t which = 0;
        if (!intersectTriangleLeaf(tr, triangles + first, count, tMin, tNearest, bestHit, which)) return false;
        tNearest = bestHit.t;
        best = first + which;
        return true;
    };
    if (!traverseClosest(scene.meshNodes.data + mesh.nodeOffset, ray, tMin, tMax, stack, leaf)) return false;
    const MeshTriangle& t = triangles[best];
    hit.t = bestHit.t;
    hit.normal = normalize(cross(t.p1 - t.p0, t.p2 - t.p0));
    hit.triangle = mesh.triangleOffset + best;
    hit.b1 = bestHit.b1;
    hit.b2 = bestHit.b2;
    return true;
}

TRAZO_HD bool meshBlocks(const SceneView& scene, const MeshShape& mesh, const Ray& ray, float tMax, AnyStack& stack) {
    const TriangleRay tr = makeTriangleRay(ray);
    const MeshTriangle* triangles = scene.triangles.data + mesh.triangleOffset;
    auto leaf = [&](uint32_t first, uint32_t count, float tLimit) {
        return triangleLeafBlocks(tr, triangles + first, count, 0.0f, tLimit);
    };
    return traverseAny(scene.meshNodes.data + mesh.nodeOffset, ray, 0.0f, tMax, stack, leaf);
}

// Spheres, boxes, cylinders and CSG solids: every kind but meshes, which traverse a BVH of their own.
TRAZO_HD bool intersectAnalytic(const SceneView& scene, const ObjectRef& o, const Ray& ray, float tMax, ShapeHit& hit) {
    switch (o.kind) {
        case ObjectKind::Sphere: return intersectSphere(scene.spheres[o.index], ray, 0.0f, tMax, hit);
        case ObjectKind::Box: return intersectBox(scene.boxes[o.index], ray, 0.0f, tMax, hit);
        case ObjectKind::Cylinder: return intersectCylinder(scene.cylinders[o.index], ray, 0.0f, tMax, hit);
        case ObjectKind::Csg: return intersectCsg(scene.csgs[o.index], scene.csgNodes.data, ray, 0.0f, tMax, hit);
        case ObjectKind::Mesh: break;
    }
    return false;
}

// `stack`: the traversal stack a mesh continues on (the top level's, in intersectScene).
TRAZO_HD bool intersectObject(const SceneView& scene, const ObjectRef& o, const Ray& ray, float tMax,
                              ClosestStack& stack, ShapeHit& hit) {
    if (o.kind == ObjectKind::Mesh) return intersectMesh(scene, scene.meshes[o.index], ray, 0.0f, tMax, stack, hit);
    return intersectAnalytic(scene, o, ray, tMax, hit);
}

TRAZO_HD bool intersectObject(const SceneView& scene, const ObjectRef& o, const Ray& ray, float tMax, ShapeHit& hit) {
    bvh_detail::StackEntry entries[kBvhStackSize];
    ClosestStack stack{entries, kBvhStackSize, 0};
    return intersectObject(scene, o, ray, tMax, stack, hit);
}

// Nearest object or area-light rectangle along the ray, in (0, tMax).
TRAZO_HD bool intersectScene(const SceneView& scene, const Ray& ray, float tMax, SurfaceHit& out) {
    bool found = false;
    if (scene.topNodes.count > 0) {
        ShapeHit best{};
        uint32_t bestObject = 0;
        bvh_detail::StackEntry entries[kTraversalStackSize];
        ClosestStack stack{entries, kTraversalStackSize, 0};
        auto leaf = [&](uint32_t first, uint32_t count, float& tNearest) {
            bool any = false;
            for (uint32_t i = first; i < first + count; ++i) {
                ShapeHit hit;
                if (intersectObject(scene, scene.objects[i], ray, tNearest, stack, hit)) {
                    tNearest = hit.t;
                    best = hit;
                    bestObject = i;
                    any = true;
                }
            }
            return any;
        };
        if (traverseClosest(scene.topNodes.data, ray, 0.0f, tMax, stack, leaf)) {
            tMax = best.t;
            out = SurfaceHit{best.t, best.normal, bestObject, 0, best.triangle, best.b1, best.b2};
            found = true;
        }
    }
    ShapeHit hit;
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
    if (scene.topNodes.count == 0) return false;
    uint32_t entries[kTraversalStackSize];
    AnyStack stack{entries, kTraversalStackSize, 0};
    auto leaf = [&](uint32_t first, uint32_t count, float tLimit) {
        for (uint32_t i = first; i < first + count; ++i) {
            const ObjectRef& o = scene.objects[i];
            if (o.kind == ObjectKind::Mesh) {
                if (meshBlocks(scene, scene.meshes[o.index], ray, tLimit, stack)) return true;
                continue;
            }
            if (o.kind == ObjectKind::Sphere) {
                if (sphereBlocks(scene.spheres[o.index], ray, 0.0f, tLimit)) return true;
                continue;
            }
            ShapeHit hit;
            if (intersectAnalytic(scene, o, ray, tLimit, hit)) return true;
        }
        return false;
    };
    return traverseAny(scene.topNodes.data, ray, 0.0f, tMax, stack, leaf);
}

}  // namespace trazo
