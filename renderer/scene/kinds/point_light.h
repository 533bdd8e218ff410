// The PointLight block on the host: the struct the reader fills, its flattening into the kernels' PointLightData
// (lights/point_light.h), and the editor's operations on one (bounds, move, a new one, scale).
#pragma once

#include <optional>

#include "lights/point_light.h"
#include "scene/object_basics.h"

namespace trazo {

struct PointLight {
    Vec3 position{0, 0, 0};
    Vec3 color{1, 1, 1};
    SourceLocation where;
};

// Templated on the arrays so that scene/ need not see SceneArrays (flatten/, to its right).
template <class Arrays>
void appendLight(const PointLight& light, Arrays& out) {
    out.pointLights.push_back({light.position, light.color});
}

inline Aabb hostBounds(const PointLight& l) { return lightBounds(PointLightData{l.position, l.color}); }
inline void translate(PointLight& l, Vec3 delta) { l.position += delta; }
inline std::optional<PointLight> newObject(KindTag<PointLight>, Vec3 at, float) {
    return PointLight{at, Vec3(1, 1, 1), {}};
}
inline void scaleAboutOrigin(PointLight& l, double factor) { l.position = scaledPoint(l.position, factor); }

}  // namespace trazo
