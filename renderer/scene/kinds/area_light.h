// The AreaLight block on the host: the struct the reader fills, its rectangle (SPEC §3's axes), its flattening
// into the kernels' AreaLightData (lights/area_light.h), and the editor's operations on one.
#pragma once

#include <cmath>
#include <optional>

#include "lights/area_light.h"
#include "scene/object_basics.h"

namespace trazo {

struct AreaLight {
    Vec3 color{1, 1, 1};
    Vec3 position{0, 0, 0};    // centre
    Vec3 direction{0, -1, 0};  // normal, not necessarily unit length as written
    float rollAngle = 0.0f;    // radians
    float width = 1.0f;
    float height = 1.0f;
    int subdivisionX = 5;
    int subdivisionY = 5;
    SourceLocation where;
    SourceLocation subdivisionAt;  // the Subdivision line; empty when not recorded (then `where` is used)
};

// u and v axes of an area light's rectangle (SPEC §3 AreaLight), unit length, before Width/Height.
inline void areaLightAxes(Vec3 normal, float rollAngle, Vec3& u, Vec3& v) {
    constexpr float kDegrees = 3.14159265358979f / 180.0f;
    const Vec3 n = normalize(normal);
    // Within 0.1° of ±Y the reference axis becomes +Z (SPEC §3).
    const bool nearVertical = fabsf(n.y) > cosf(0.1f * kDegrees);
    const Vec3 a = nearVertical ? Vec3(0, 0, 1) : Vec3(0, 1, 0);
    const Vec3 u0 = normalize(cross(a, n));
    const Vec3 v0 = cross(n, u0);
    const float c = cosf(rollAngle), s = sinf(rollAngle);
    u = u0 * c + v0 * s;
    v = v0 * c - u0 * s;
}

inline AreaLightData areaLightData(const AreaLight& l) {
    Vec3 u, v;
    areaLightAxes(l.direction, l.rollAngle, u, v);
    const RectangleShape rect{l.position, u * (0.5f * l.width), v * (0.5f * l.height), normalize(l.direction)};
    return AreaLightData{rect, l.color, (uint32_t)l.subdivisionX, (uint32_t)l.subdivisionY};
}

// Templated on the arrays so that scene/ need not see SceneArrays (flatten/, to its right).
template <class Arrays>
void appendLight(const AreaLight& light, Arrays& out) {
    out.areaLights.push_back(areaLightData(light));
}

inline Aabb hostBounds(const AreaLight& l) { return lightBounds(areaLightData(l)); }
inline void translate(AreaLight& l, Vec3 delta) { l.position += delta; }
inline std::optional<AreaLight> newObject(KindTag<AreaLight>, Vec3 at, float size) {
    AreaLight light;
    light.position = at;
    light.width = light.height = size;
    return light;
}
inline void scaleAboutOrigin(AreaLight& l, double factor) {
    l.position = scaledPoint(l.position, factor);
    l.width = float(l.width * factor);
    l.height = float(l.height * factor);
}

}  // namespace trazo
