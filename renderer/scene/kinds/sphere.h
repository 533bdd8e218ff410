// The Sphere block on the host: the struct the reader fills, its flattening into the kernels' SphereShape
// (objects/sphere.h), and the editor's operations on one (bounds, move, a new one, scale).
#pragma once

#include <optional>

#include "objects/sphere.h"
#include "scene/object_basics.h"

namespace trazo {

struct Sphere {
    static constexpr bool kReadFromFile = false;
    int32_t material = kDefaultMaterial;  // index into Scene::materials
    Vec3 center{0, 0, 0};
    float radius = 1.0f;
    SourceLocation where;
};

// Appends the sphere to out.spheres; `index`: its place there. Templated on the arrays so that scene/ need not
// see SceneArrays (flatten/, to its right).
template <class Arrays>
bool appendObject(const Sphere& sphere, Arrays& out, uint32_t& index) {
    index = (uint32_t)out.spheres.size();
    out.spheres.push_back({sphere.center, sphere.radius});
    return true;
}

inline Aabb hostBounds(const Sphere& s) { return objectBounds(SceneView{}, SphereShape{s.center, s.radius}); }
inline void translate(Sphere& s, Vec3 delta) { s.center += delta; }
inline std::optional<Sphere> newObject(KindTag<Sphere>, Vec3 at, float size) {
    return Sphere{kDefaultMaterial, at, 0.5f * size, {}};
}
inline void scaleAboutOrigin(Sphere& s, double factor) {
    s.center = scaledPoint(s.center, factor);
    s.radius = float(s.radius * factor);
}

}  // namespace trazo
