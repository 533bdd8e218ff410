// One ray query against the whole scene, as both backends answer it for benchmarks and agreement tests:
// the nearest hit (intersectScene) or, for a shadow query, whether anything blocks the segment (occluded).
#pragma once

#include <cmath>

#include "integrator/scene_intersect.h"

namespace trazo {

struct RayQuery {
    Ray ray;
    float tMax;  // the query covers (0, tMax)
};

// Nearest query: the hit's t, or +inf on a miss. Shadow query: 1 when blocked, else 0.
TRAZO_HD float answerRayQuery(const SceneView& scene, const RayQuery& query, bool shadow) {
    if (shadow) return occluded(scene, query.ray, query.tMax) ? 1.0f : 0.0f;
    SurfaceHit hit;
    return intersectScene(scene, query.ray, query.tMax, hit) ? hit.t : INFINITY;
}

}  // namespace trazo
