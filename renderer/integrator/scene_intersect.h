// Ray queries against the whole scene: nearest hit (with visible area-light rectangles) and shadow any-hit.
// Two levels of BVH: the top level over the scene's objects (SceneView::topNodes, objects in its leaf
// order), and one per mesh over its triangles. Area-light rectangles are few and tested one by one.
#pragma once

#include "accel/bvh_traverse.h"
#include "lights/area_light.h"
#include "lights/point_light.h"
#include "lights/rectangle.h"
#include "objects/visit_object.h"

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

// The object kind's own view of an object's hit (what objectSurface and objectHitPoint take).
TRAZO_HD ShapeHit shapeHitOf(const SurfaceHit& hit) { return ShapeHit{hit.t, hit.normal, hit.triangle, hit.b1, hit.b2}; }

// A ray and its intersectScene answer (found: whether there is one), for code that traced the ray already: the
// CPU's tile loop traces a block of camera rays together, indirect light a shading point's directions
// (nearest_packet.h's tracePacket).
struct TracedRay {
    Ray ray;
    SurfaceHit hit;
    bool found;
};

// `stack`: the traversal stack a mesh continues on (the top level's, in intersectScene).
TRAZO_HD bool intersectObject(const SceneView& scene, const ObjectRef& o, const Ray& ray, float tMax,
                              ClosestStack& stack, ShapeHit& hit) {
    return visitObject(scene, o, [&](const auto& shape) { return intersectObject(scene, shape, ray, tMax, stack, hit); });
}

TRAZO_HD bool intersectObject(const SceneView& scene, const ObjectRef& o, const Ray& ray, float tMax, ShapeHit& hit) {
    bvh_detail::StackEntry entries[kBvhStackSize];
    ClosestStack stack{entries, kBvhStackSize, 0};
    return intersectObject(scene, o, ray, tMax, stack, hit);
}

// The nearest light rectangle along the ray in (0, tMax), if any: out and tMax become its hit.
TRAZO_HD bool intersectAreaLights(const SceneView& scene, const Ray& ray, float& tMax, SurfaceHit& out) {
    bool found = false;
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

// The nearest object along the ray in (0, tMax), over the top level: out and tMax become its hit.
TRAZO_HD bool intersectObjects(const SceneView& scene, const Ray& ray, float& tMax, SurfaceHit& out) {
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
#if TRAZO_DEVICE_PATHS
    const bool topHit = traverseClosest(scene.topNodes.data, ray, 0.0f, tMax, stack, leaf);
#else
    // A top level that is one leaf (one object, or a few close ones) is not traversed: its box test only
    // repeats its objects' own (bvh_bench's one-mesh scenes: 1.04-1.21x the rays a second). The device keeps
    // the traversal: a second call site of the leaf put a render kernel over its spill budget (kernel_budget).
    const uint32_t lone = loneLeaf(scene.topNodes.data);
    const bool topHit = lone != kBvhEmptyLane ? leaf(bvhLeafFirst(lone), bvhLeafCount(lone), tMax)
                                              : traverseClosest(scene.topNodes.data, ray, 0.0f, tMax, stack, leaf);
#endif
    if (!topHit) return false;
    tMax = best.t;
    out = SurfaceHit{best.t, best.normal, bestObject, 0, best.triangle, best.b1, best.b2};
    return true;
}

#if !TRAZO_DEVICE_PATHS
// The object index of the scene's one mesh when the top level is a lone leaf holding nothing else (a model on
// its own, as in bvh_bench), else kNoObject. Its queries then go to the mesh straight away, without the top
// level's leaf loop, the dispatch over kinds and the out-of-line call through it: bvh_bench's bunny camera rays
// 1.11x as fast. Host only, as the lone-leaf path.
inline uint32_t loneMeshObject(const SceneView& scene) {
    if (scene.topNodes.count == 0) return kNoObject;
    const uint32_t lone = loneLeaf(scene.topNodes.data);
    if (lone == kBvhEmptyLane || bvhLeafCount(lone) != 1) return kNoObject;
    return scene.objects[bvhLeafFirst(lone)].kind == ObjectKind::Mesh ? bvhLeafFirst(lone) : kNoObject;
}

// intersectObjects for such a scene. Flattened, so the whole mesh query is one call a ray (with GCC's own choice,
// intersectMesh out of line below it, bvh_bench's bunny camera rays were 6 % slower than through the dispatch).
__attribute__((flatten, noinline)) inline bool intersectLoneMesh(const SceneView& scene, uint32_t object,
                                                                  const Ray& ray, float& tMax, SurfaceHit& out) {
    bvh_detail::StackEntry entries[kBvhStackSize > kBvh8StackSize ? kBvhStackSize : kBvh8StackSize];
    ClosestStack stack{entries, int(sizeof entries / sizeof entries[0]), 0};
    ShapeHit hit;
    if (!intersectMesh(scene, scene.meshes[scene.objects[object].index], ray, 0.0f, tMax, stack, hit)) return false;
    tMax = hit.t;
    out = SurfaceHit{hit.t, hit.normal, object, 0, hit.triangle, hit.b1, hit.b2};
    return true;
}
#endif

// Nearest object or area-light rectangle along the ray, in (0, tMax).
TRAZO_HD bool intersectScene(const SceneView& scene, const Ray& ray, float tMax, SurfaceHit& out) {
    bool found = false;
#if TRAZO_DEVICE_PATHS
    if (scene.topNodes.count > 0) found = intersectObjects(scene, ray, tMax, out);
#else
    const uint32_t meshObject = loneMeshObject(scene);
    if (meshObject != kNoObject)
        found = intersectLoneMesh(scene, meshObject, ray, tMax, out);
    else if (scene.topNodes.count > 0)
        found = intersectObjects(scene, ray, tMax, out);
#endif
    return intersectAreaLights(scene, ray, tMax, out) || found;
}

// True when any object blocks the segment (0, tMax). Light rectangles cast no shadow (SPEC §5).
TRAZO_HD bool occluded(const SceneView& scene, const Ray& ray, float tMax) {
    if (scene.topNodes.count == 0) return false;
    uint32_t entries[kTraversalStackSize];
    AnyStack stack{entries, kTraversalStackSize, 0};
    auto leaf = [&](uint32_t first, uint32_t count, float tLimit) {
        for (uint32_t i = first; i < first + count; ++i) {
            const bool blocks = visitObject(scene, scene.objects[i], [&](const auto& shape) {
                return objectBlocks(scene, shape, ray, tLimit, stack);
            });
            if (blocks) return true;
        }
        return false;
    };
#if !TRAZO_DEVICE_PATHS
    const uint32_t meshObject = loneMeshObject(scene);  // as in intersectScene
    if (meshObject != kNoObject)
        return meshBlocks(scene, scene.meshes[scene.objects[meshObject].index], ray, tMax, stack);
    const uint32_t lone = loneLeaf(scene.topNodes.data);
    if (lone != kBvhEmptyLane) return leaf(bvhLeafFirst(lone), bvhLeafCount(lone), tMax);
#endif
    return traverseAny(scene.topNodes.data, ray, 0.0f, tMax, stack, leaf);
}

}  // namespace trazo
