// The flattened scene: plain arrays with 32-bit indices (no pointers, names or STL in what kernels read),
// plus SceneView, the non-owning view of those arrays in host or device memory that kernels take.
#pragma once

#include <cstdint>
#include <type_traits>
#include <vector>

#include "core/vec3.h"
#include "device/feature_mask.h"
#include "geometry/csg.h"
#include "geometry/shapes.h"

namespace trazo {

struct MaterialData {
    Vec3 diffuse;
    Vec3 specular;
    Vec3 emissive;
    float roughness;
    float opacity;
    float refractionIndex;
    float reflectionHalfAngle;  // radians; 0 = mirror
    float reflectionAmount;
    int32_t diffuseTexture, specularTexture, emissiveTexture, normalTexture;  // -1 = none (issue 3)
};

enum class ObjectKind : uint32_t { Sphere = 0, Box = 1, Cylinder = 2, Csg = 3 };

// One renderable object: which shape array, which element, which material.
struct ObjectRef {
    ObjectKind kind;
    uint32_t index;
    uint32_t material;
};

struct PointLightData {
    Vec3 position;
    Vec3 color;
};

struct AreaLightData {
    RectangleShape rect;
    Vec3 color;
    uint32_t cellsU, cellsV;  // Subdivision: strata of the light's surface
};

// The render settings kernels need, as plain values (from SceneSettings).
struct RenderSettings {
    Vec3 background;
    uint32_t reflectionQuality;
    uint32_t reflectionSteps;
    uint32_t indirectQuality;
    float colorBleeding;
    uint32_t antialiasing;  // 1, 4 or 16
};

// Owning host copy of the flattened scene; what Backend::upload takes.
struct SceneArrays {
    std::vector<SphereShape> spheres;
    std::vector<BoxShape> boxes;
    std::vector<CylinderShape> cylinders;
    std::vector<CsgShape> csgs;
    std::vector<CsgNodeData> csgNodes;
    std::vector<ObjectRef> objects;
    std::vector<MaterialData> materials;
    std::vector<PointLightData> pointLights;
    std::vector<AreaLightData> areaLights;
    RenderSettings settings{};
    FeatureMask features = 0;
};

template <typename T>
struct ArrayView {
    const T* data = nullptr;
    uint32_t count = 0;
    TRAZO_HD const T& operator[](uint32_t i) const { return data[i]; }
};

struct SceneView {
    ArrayView<SphereShape> spheres;
    ArrayView<BoxShape> boxes;
    ArrayView<CylinderShape> cylinders;
    ArrayView<CsgShape> csgs;
    ArrayView<CsgNodeData> csgNodes;
    ArrayView<ObjectRef> objects;
    ArrayView<MaterialData> materials;
    ArrayView<PointLightData> pointLights;
    ArrayView<AreaLightData> areaLights;
    RenderSettings settings;
    FeatureMask features;
};

// A view of host-resident arrays (the CPU backend renders straight from them).
inline SceneView hostView(const SceneArrays& a) {
    auto view = [](const auto& v) {
        using T = typename std::decay_t<decltype(v)>::value_type;
        return ArrayView<T>{v.data(), (uint32_t)v.size()};
    };
    return SceneView{view(a.spheres), view(a.boxes), view(a.cylinders), view(a.csgs), view(a.csgNodes),
                     view(a.objects), view(a.materials),
                     view(a.pointLights), view(a.areaLights), a.settings, a.features};
}

}  // namespace trazo
