// The light kinds of the scene language, listed once (host and device), as objects/object_kind_list.h lists the
// object kinds. The list generates LightKind, the lights' arrays of Scene, SceneView and SceneArrays, flatten()'s
// loop, the reader's, writer's, tables' and editor's handling of each kind's block, and the checks that each kind
// has its two halves: the kernel half lights/<kind>.h, the host half scene/kinds/<kind>.h
// (scene/kinds/light_kind_model.h), which this list includes (the kernel halves) or that file does (the host
// halves). X(device data type, array in Scene and SceneView, host struct, block keyword
// in a scene file, the editor's label, the feature bit a scene with one sets).
#pragma once

#include <cstdint>

#include "lights/area_light.h"
#include "lights/point_light.h"

#define TRAZO_LIGHT_KINDS(X)                                                                     \
    X(PointLightData, pointLights, PointLight, "PointLight", "Point light", kFeaturePointLights) \
    X(AreaLightData, areaLights, AreaLight, "AreaLight", "Area light", kFeatureAreaLights)

namespace trazo {

enum class LightKind : uint32_t {
#define TRAZO_X(Data, array, Kind, keyword, label, feature) Kind,
    TRAZO_LIGHT_KINDS(TRAZO_X)
#undef TRAZO_X
};

}  // namespace trazo
