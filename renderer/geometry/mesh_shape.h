// Triangle meshes as the kernels see them: world-space triangles in the order of their mesh's BVH, shading
// data per corner beside them (kept apart so traversal touches positions only), and one MeshShape per Mesh.
#pragma once

#include <cstdint>

#include "core/vec3.h"

namespace trazo {

struct MeshTriangle {
    Vec3 p0, p1, p2;
};

// One corner's shading data: unit normal, Lengyel tangent with the bitangent's handedness (bitangent =
// tangentSign · normal × tangent), and texture coordinates.
struct MeshCorner {
    Vec3 normal;
    Vec3 tangent;
    float tangentSign;
    float u, v;
};

struct TriangleCorners {
    MeshCorner corner[3];
};

struct MeshShape {
    uint32_t nodeOffset;      // root of the mesh's BVH in SceneView::meshNodes
    uint32_t triangleOffset;  // first triangle in SceneView::triangles / triangleCorners
    uint32_t triangleCount;
    uint32_t hasUvs;          // 0: the OBJ had no uvs; textures are ignored on it
};

}  // namespace trazo
