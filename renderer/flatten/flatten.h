// flatten(): host Scene -> SceneArrays (world-space shapes and meshes, textures, the two BVH levels,
// material indices, feature mask), optionally reusing the meshes of an earlier result.
#pragma once

#include <memory>
#include <vector>

#include "core/affine.h"
#include "flatten/array_mask.h"
#include "flatten/scene_arrays.h"
#include "scene/object_id.h"
#include "scene/scene.h"

namespace trazo {

// What one Mesh block's arrays were built from, and which MeshShape holds them: a later flatten reuses the
// arrays of a mesh with the same data (the same MeshData object) and the same composed transform.
struct FlattenedMesh {
    std::shared_ptr<const MeshData> data;  // kept alive, so the pointer cannot name another mesh later
    Affine3 worldFromObject;
    int32_t shape = -1;  // index into SceneArrays::meshes; -1: no triangles, not drawn
};

struct FlattenResult {
    SceneArrays arrays;
    // What of the scene is read but not drawn as written (textures on an object without texture coordinates),
    // at the line of its block; the rest of the scene renders.
    Diagnostics warnings;
    // Host-only (never uploaded). sources[i]: the host object arrays.objects[i] was made from (objects are in
    // the top-level BVH's leaf order, and objects that draw nothing have no entry).
    std::vector<ObjectId> sources;
    std::vector<FlattenedMesh> meshes;  // one per Scene::meshes entry, in its order
    ArrayMask reused = kNoArrays;       // arrays taken whole from `previous` (kMeshArrays or none)
    uint32_t meshesBuilt = 0;           // meshes whose BVH this flatten built
    uint32_t meshesReused = 0;          // meshes copied or taken from `previous`
};

// `previous` (optional): an earlier result for a scene the caller edited since. Meshes whose data and
// transform are unchanged are not rebuilt: their triangles, corners and BVH nodes come from `previous`, moved
// out of it whole when every mesh is reused in the same order (those arrays are then listed in `reused` and
// left empty in `previous`; the rest of `previous` is untouched). The result is the same, byte for byte, as
// flatten(scene) without `previous`.
FlattenResult flatten(const Scene& scene, FlattenResult* previous = nullptr);


}  // namespace trazo
