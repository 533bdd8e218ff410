// Mesh reuse across flattens. A mesh's arrays do not depend on where they sit: its BVH's child and triangle
// indices count from its own MeshShape offsets, so a reused mesh is its old segment copied to its new place.
#include "flatten/mesh_reuse.h"

#include <cstring>

#include "flatten/flatten_mesh.h"

namespace trazo {

namespace {

bool samePlacement(const FlattenedMesh& a, const std::shared_ptr<const MeshData>& data, const Affine3& worldFromObject) {
    return a.shape >= 0 && a.data == data && std::memcmp(&a.worldFromObject, &worldFromObject, sizeof(Affine3)) == 0;
}

// The earlier mesh (index into previous.meshes) with the same data and placement, not yet taken; -1 if none.
// The same position is tried first, so an unedited scene maps every mesh to itself.
int32_t findPrevious(const FlattenResult& previous, size_t j, const FlattenedMesh& now, const std::vector<bool>& taken) {
    const std::vector<FlattenedMesh>& old = previous.meshes;
    if (j < old.size() && !taken[j] && samePlacement(old[j], now.data, now.worldFromObject)) return int32_t(j);
    for (size_t i = 0; i < old.size(); ++i)
        if (!taken[i] && samePlacement(old[i], now.data, now.worldFromObject)) return int32_t(i);
    return -1;
}

template <typename T>
void appendRange(std::vector<T>& to, const std::vector<T>& from, size_t first, size_t count) {
    to.insert(to.end(), from.begin() + first, from.begin() + first + count);
}

// Copies MeshShape `shape` of `from` (its nodes, triangles and corners) to the end of `to`; returns its index.
uint32_t copyMesh(const SceneArrays& from, uint32_t shape, SceneArrays& to) {
    const MeshShape& m = from.meshes[shape];
    const MeshShape placed{(uint32_t)to.meshNodes.size(), (uint32_t)to.triangles.size(), m.triangleCount, m.hasUvs};
    appendRange(to.meshNodes, from.meshNodes, m.nodeOffset, meshNodeCount(from, shape));
    appendRange(to.triangles, from.triangles, m.triangleOffset, m.triangleCount);
    appendRange(to.triangleCorners, from.triangleCorners, m.triangleOffset, m.triangleCount);
    to.meshes.push_back(placed);
    return (uint32_t)to.meshes.size() - 1;
}

// A Mesh block with no triangles is not drawn.
bool drawsTriangles(const std::shared_ptr<const MeshData>& data) { return data && !data->corners.empty(); }

}  // namespace

void placeMeshes(const Scene& scene, FlattenResult* previous, FlattenResult& result) {
    SceneArrays& out = result.arrays;
    const size_t count = scene.meshes.size();
    result.meshes.assign(count, FlattenedMesh{});
    // from[j]: the earlier mesh that host mesh j reuses (-1: build it, or nothing to draw).
    std::vector<int32_t> from(count, -1);
    std::vector<bool> taken(previous ? previous->meshes.size() : 0, false);
    bool sameOrder = previous != nullptr;  // every earlier shape reused, in its order
    uint32_t nextShape = 0;
    for (size_t j = 0; j < count; ++j) {
        const Mesh& mesh = scene.meshes[j];
        FlattenedMesh& now = result.meshes[j];
        now.data = mesh.data;
        now.worldFromObject = composeTransforms(mesh.transforms);
        if (!drawsTriangles(mesh.data)) continue;
        if (previous) from[j] = findPrevious(*previous, j, now, taken);
        if (from[j] >= 0) taken[from[j]] = true;
        if (from[j] < 0 || previous->meshes[from[j]].shape != int32_t(nextShape)) sameOrder = false;
        ++nextShape;
    }
    if (sameOrder && nextShape != previous->arrays.meshes.size()) sameOrder = false;

    if (sameOrder) {  // the arrays as they were: moved, not copied
        out.meshes = std::move(previous->arrays.meshes);
        out.meshNodes = std::move(previous->arrays.meshNodes);
        out.triangles = std::move(previous->arrays.triangles);
        out.triangleCorners = std::move(previous->arrays.triangleCorners);
        result.reused = kMeshArrays;
    }
    uint32_t shape = 0;
    for (size_t j = 0; j < count; ++j) {
        FlattenedMesh& now = result.meshes[j];
        if (!drawsTriangles(now.data)) continue;
        if (sameOrder) {
            now.shape = int32_t(shape++);
            ++result.meshesReused;
        } else if (from[j] >= 0) {
            now.shape = int32_t(copyMesh(previous->arrays, uint32_t(previous->meshes[from[j]].shape), out));
            ++result.meshesReused;
        } else {
            now.shape = int32_t(appendMesh(*now.data, now.worldFromObject, out));
            ++result.meshesBuilt;
        }
    }
}

}  // namespace trazo
