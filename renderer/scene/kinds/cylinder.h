// The Cylinder block on the host: the struct the reader fills, its flattening into the kernels' CylinderShape
// (objects/cylinder.h), and the editor's operations on one.
#pragma once

#include <optional>

#include "objects/cylinder.h"
#include "scene/object_basics.h"

namespace trazo {

struct Cylinder {
    static constexpr bool kReadFromFile = false;
    int32_t material = kDefaultMaterial;
    Vec3 base{0, 0, 0};
    Vec3 axis{0, 1, 0};
    float height = 1.0f;
    float radius = 1.0f;
    SourceLocation where;
};

// Appends the cylinder to out.cylinders (templated on the arrays: see the sphere's appendObject).
template <class Arrays>
bool appendObject(const Cylinder& c, Arrays& out, uint32_t& index) {
    index = (uint32_t)out.cylinders.size();
    out.cylinders.push_back({c.base, normalize(c.axis), c.height, c.radius});
    return true;
}

inline Aabb hostBounds(const Cylinder& c) {
    return objectBounds(SceneView{}, CylinderShape{c.base, normalize(c.axis), c.height, c.radius});
}
inline void translate(Cylinder& c, Vec3 delta) { c.base += delta; }
// Standing on +Y, `size` tall and across.
inline std::optional<Cylinder> newObject(KindTag<Cylinder>, Vec3 at, float size) {
    const float half = 0.5f * size;
    return Cylinder{kDefaultMaterial, at - Vec3(0, half, 0), Vec3(0, 1, 0), size, half, {}};
}
inline void scaleAboutOrigin(Cylinder& c, double factor) {
    c.base = scaledPoint(c.base, factor);
    c.height = float(c.height * factor);
    c.radius = float(c.radius * factor);
}

}  // namespace trazo
