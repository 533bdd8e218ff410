// What the camera sees, asked of the backend's own ray query (RayQueryKind::Object: the image's traversal), so a
// click picks what the image shows: the object at a pixel, every pixel's object, a selection's mask. Host code,
// no window: ViewerSession answers with these for the scene it last uploaded.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "backends/backend.h"
#include "scene/object_id.h"
#include "scene/scene.h"

namespace trazo {

// What a click on the image found: the object (or area light) nearest along the camera ray, at distance t,
// at `point` (world space).
struct PickHit {
    ObjectId object;
    float t;
    Vec3 point;
};

// `sources`: the host object of each entry of the uploaded arrays' objects (FlattenResult::sources).
// The host object or area light of a RayAnswer::object; nullopt for a miss.
std::optional<ObjectId> objectOfAnswer(const std::vector<ObjectId>& sources, int32_t answer);

// The camera ray of `scene` through (x, y), in pixels of a width × height image ((0, 0) its top-left corner,
// pixel centres at +0.5), answered by `backend`. Nothing there (background): nullopt.
std::optional<PickHit> pickObject(Backend& backend, const Scene& scene, const std::vector<ObjectId>& sources,
                                  uint32_t width, uint32_t height, float x, float y);

// For every pixel centre of a width × height image (row 0 = top): what the camera ray hits first, as
// RayAnswer::object (an index into the arrays' objects, areaLightAnswer(i), or kMissAnswer).
std::vector<int32_t> objectIdsOf(Backend& backend, const Scene& scene, uint32_t width, uint32_t height);

// 1 where `ids` holds the answer that stands for `selected`, else 0 (the selection's outline is its edge).
std::vector<uint8_t> selectionMaskOf(const std::vector<ObjectId>& sources, const std::vector<int32_t>& ids,
                                     const ObjectId& selected);

}  // namespace trazo
