// visitLight: the one dispatch over light kinds (host and device). It calls f with the light's data; overloads of
// each kind's interface (lights/<kind>.h: sampleLi, pdfLi, arrivingLi, lightBounds) do the rest. Templated on the scene
// (SceneView, objects/, stands above lights/).
#pragma once

#include "lights/light_kind_list.h"

namespace trazo {

// One light of the flattened scene: which kind's array, which element.
struct LightRef {
    LightKind kind;
    uint32_t index;
};

template <class Scene, typename F>
TRAZO_HD auto visitLight(const Scene& scene, LightRef light, F&& f) -> decltype(f(scene.pointLights[0])) {
    switch (light.kind) {
#define TRAZO_X(Data, array, Kind, ...) \
    case LightKind::Kind: return f(scene.array[light.index]);
        TRAZO_LIGHT_KINDS(TRAZO_X)
#undef TRAZO_X
    }
    TRAZO_UNREACHABLE();
}

template <class Scene>
TRAZO_HD LightSample sampleLi(const Scene& scene, LightRef light, Vec3 p, float u1, float u2) {
    return visitLight(scene, light, [&](const auto& data) { return sampleLi(data, p, u1, u2); });
}

template <class Scene>
TRAZO_HD float pdfLi(const Scene& scene, LightRef light, Vec3 p, Vec3 wi) {
    return visitLight(scene, light, [&](const auto& data) { return pdfLi(data, p, wi); });
}

template <class Scene>
TRAZO_HD Vec3 arrivingLi(const Scene& scene, LightRef light, Vec3 p, Vec3 wi) {
    return visitLight(scene, light, [&](const auto& data) { return arrivingLi(data, p, wi); });
}

}  // namespace trazo
