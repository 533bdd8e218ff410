// The Mesh block on the host: the struct the reader fills (its OBJ data, shared between blocks that name the
// same file, and its transform steps) and the editor's operations on one. flatten() places meshes itself
// (flatten/mesh_reuse.h: a mesh's BVH is kept across edits), so a Mesh has no appendObject.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "objects/mesh.h"
#include "scene/object_basics.h"

namespace trazo {

// A mesh as read from its OBJ file, before the Mesh block's transforms (flatten/flatten_mesh.h places it).
struct MeshData {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;        // one per position-index corner, see `corners`
    std::vector<float> uvs;           // 2 floats per uv
    struct Corner { int32_t position, normal, uv; };  // -1 = absent
    std::vector<Corner> corners;      // 3 per triangle, fan-triangulated
    bool hasNormals = false;
    bool hasUvs = false;
};

struct Mesh {
    static constexpr bool kReadFromFile = true;  // added by addObjectFromFile, never by newObject
    int32_t material = kDefaultMaterial;
    std::string source;  // resolved path
    std::vector<TransformStep> transforms;
    std::shared_ptr<const MeshData> data;
    SourceLocation where;
};

// The box of its positions after its transforms (each corner of their box transformed: the reader's measure);
// empty when its file did not load. Linear in the vertices (scene/transform_checks.cpp).
Aabb hostBounds(const Mesh& m);
inline void translate(Mesh& m, Vec3 delta) { translateSteps(m.transforms, delta); }
inline std::optional<Mesh> newObject(KindTag<Mesh>, Vec3, float) { return std::nullopt; }
inline void scaleAboutOrigin(Mesh& m, double factor) { scaleSteps(m.transforms, factor); }

}  // namespace trazo
