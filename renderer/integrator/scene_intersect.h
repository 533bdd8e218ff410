// Ray queries against the whole scene: nearest hit (with visible area-light rectangles) and shadow any-hit.
// Two levels of BVH: the top level over the scene's objects (SceneView::topNodes, objects in its leaf
// order), and one per mesh over its triangles. Area-light rectangles are few and tested one by one.
#pragma once

#include "accel/bvh_traverse.h"
#include "objects/light_data.h"
#include "objects/rectangle.h"
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
        if (topHit) {
            tMax = best.t;
            out = SurfaceHit{best.t, best.normal, bestObject, 0, best.triangle, best.b1, best.b2};
            found = true;
        }
    }
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
    const uint32_t lone = loneLeaf(scene.topNodes.data);  // as in intersectScene
    if (lone != kBvhEmptyLane) return leaf(bvhLeafFirst(lone), bvhLeafCount(lone), tMax);
#endif
    return traverseAny(scene.topNodes.data, ray, 0.0f, tMax, stack, leaf);
}

}  // namespace trazo
