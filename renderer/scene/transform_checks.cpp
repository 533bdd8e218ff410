// The transform checks shared by the scene reader and the viewer's editor, and the bounds of a transformed mesh.
#include "scene/transform_checks.h"

#include <algorithm>
#include <cfloat>
#include <cstdio>

namespace trazo {

Aabb transformedBox(const Aabb& object, const std::vector<TransformStep>& steps) {
    if (object.empty()) return object;
    const Affine3 m = composeTransforms(steps);
    Aabb world;
    for (int c = 0; c < 8; ++c)
        world.grow(m.applyToPoint(Vec3((c & 1) ? object.max.x : object.min.x, (c & 2) ? object.max.y : object.min.y,
                                       (c & 4) ? object.max.z : object.min.z)));
    return world;
}

Aabb meshObjectBounds(const MeshData& data) {
    Aabb b;
    for (const Vec3& p : data.positions) b.grow(p);
    return b;
}

Aabb hostBounds(const Mesh& m) { return m.data ? transformedBox(meshObjectBounds(*m.data), m.transforms) : Aabb{}; }

std::string invertibleProblem(const std::vector<TransformStep>& steps) {
    if (steps.empty()) return "";
    const Affine3 m = composeTransforms(steps);
    const Affine3 inv = inverse(m);
    bool finite = isFinite(m.translation) && isFinite(inv.translation);
    for (int i = 0; i < 3; ++i) finite = finite && isFinite(m.row[i]) && isFinite(inv.row[i]);
    if (finite) return "";
    return "its transforms compose to a map single precision cannot hold or invert (scales multiply past float's "
           "range, about 1e±38)";
}

std::string boxNormalsProblem(const std::vector<TransformStep>& steps) {
    const Affine3 inv = inverse(composeTransforms(steps));
    for (int i = 0; i < 3; ++i) {
        if (!(dot(inv.row[i], inv.row[i]) >= 2.0f * FLT_MIN))
            return "its transforms scale an axis by more than about 6e18, where its face normals (of squared length "
                   "1/scale²) leave single precision";
    }
    return "";
}

std::string meshExtentProblem(const MeshData& data, const std::vector<TransformStep>& steps) {
    const Aabb world = transformedBox(meshObjectBounds(data), steps);
    if (world.empty()) return "";
    const double extent = std::max({double(world.max.x) - world.min.x, double(world.max.y) - world.min.y,
                                    double(world.max.z) - world.min.z});
    if (extent <= kMaxMeshExtent) return "";
    char spans[32];
    std::snprintf(spans, sizeof spans, "%.3g", extent);
    return std::string("spans ") + spans + " after its transforms; a mesh may span at most 1e9, where its "
           "triangles' normals still square inside single precision";
}

}  // namespace trazo
