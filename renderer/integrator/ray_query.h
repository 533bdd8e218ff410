// One ray query against the whole scene, as both backends answer it for benchmarks, agreement tests and the
// viewer's picking: the nearest hit (intersectScene), whose it is, or whether anything blocks the segment.
#pragma once

#include <cmath>
#include <cstdint>

#include "integrator/scene_intersect.h"

namespace trazo {

struct RayQuery {
    Ray ray;
    float tMax;  // the query covers (0, tMax)
};

enum class RayQueryKind : uint32_t {
    Nearest,  // t of the nearest hit (+inf on a miss)
    Shadow,   // 1 when anything blocks the segment, else 0
    Object,   // t of the nearest hit and what it hit (RayAnswer::object)
};

// RayAnswer::object for a miss; an area light's rectangle i is areaLightAnswer(i).
constexpr int32_t kMissAnswer = -1;
TRAZO_HD constexpr int32_t areaLightAnswer(uint32_t light) { return -2 - int32_t(light); }
TRAZO_HD constexpr bool isAreaLightAnswer(int32_t object) { return object <= -2; }
TRAZO_HD constexpr uint32_t areaLightOfAnswer(int32_t object) { return uint32_t(-2 - object); }

struct RayAnswer {
    float t;         // Nearest and Object: the nearest hit's t (+inf on a miss); Shadow: 1 or 0
    int32_t object;  // Object: index into SceneView::objects, areaLightAnswer(i), or kMissAnswer
};

// Nearest query: the hit's t, or +inf on a miss. Shadow query: 1 when blocked, else 0.
TRAZO_HD float answerRayQuery(const SceneView& scene, const RayQuery& query, bool shadow) {
    if (shadow) return occluded(scene, query.ray, query.tMax) ? 1.0f : 0.0f;
    SurfaceHit hit;
    return intersectScene(scene, query.ray, query.tMax, hit) ? hit.t : INFINITY;
}

// Any kind of query; the same traversal the image's camera rays take (intersectScene).
TRAZO_HD RayAnswer answerRayQuery(const SceneView& scene, const RayQuery& query, RayQueryKind kind) {
    if (kind != RayQueryKind::Object)
        return RayAnswer{answerRayQuery(scene, query, kind == RayQueryKind::Shadow), kMissAnswer};
    SurfaceHit hit;
    if (!intersectScene(scene, query.ray, query.tMax, hit)) return RayAnswer{INFINITY, kMissAnswer};
    return RayAnswer{hit.t, hit.object == kNoObject ? areaLightAnswer(hit.areaLight) : int32_t(hit.object)};
}

}  // namespace trazo
