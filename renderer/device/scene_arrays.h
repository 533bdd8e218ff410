// The flattened scene: plain arrays with 32-bit indices (no pointers, names or STL in what kernels read),
// plus SceneView, the non-owning view of those arrays in host or device memory that kernels take.
#pragma once

#include <cstdint>
#include <vector>

#include "accel/wide_bvh_node.h"
#include "core/vec3.h"
#include "device/feature_mask.h"
#include "geometry/csg.h"
#include "geometry/mesh_shape.h"
#include "geometry/shapes.h"
#include "shading/texture.h"

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
    int32_t diffuseTexture, specularTexture, emissiveTexture, normalTexture;  // into textures; -1 = none
};

enum class ObjectKind : uint32_t { Sphere = 0, Box = 1, Cylinder = 2, Csg = 3, Mesh = 4 };

// One renderable object: which shape array, which element, which material. Objects are stored in the order
// of the top-level BVH (topNodes), whose leaves cover ranges of them.
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

// Every array of the flattened scene, once: SceneArrays, SceneView, hostView() and the backends' uploads
// are all generated from this list, so adding an array is a one-line change. X(element type, member name).
#define TRAZO_SCENE_ARRAYS(X)          \
    X(SphereShape, spheres)            \
    X(BoxShape, boxes)                 \
    X(CylinderShape, cylinders)        \
    X(CsgShape, csgs)                  \
    X(CsgNodeData, csgNodes)           \
    X(ObjectRef, objects)              \
    X(MaterialData, materials)         \
    X(PointLightData, pointLights)     \
    X(AreaLightData, areaLights)       \
    X(TextureData, textures)           \
    X(Vec3, texels)                    \
    X(MeshShape, meshes)               \
    X(WideBvhNode, meshNodes)          \
    X(MeshTriangle, triangles)         \
    X(TriangleCorners, triangleCorners) \
    X(WideBvhNode, topNodes)

// Owning host copy of the flattened scene; what Backend::upload takes.
struct SceneArrays {
#define TRAZO_X(T, name) std::vector<T> name;
    TRAZO_SCENE_ARRAYS(TRAZO_X)
#undef TRAZO_X
    RenderSettings settings{};
    FeatureMask features = 0;
    // Entries of the traversal stack the two BVH levels need together (the top level's need plus the
    // neediest mesh's): a backend whose kernels hold fewer refuses the scene at upload.
    uint32_t traversalStackNeed = 0;
};

template <typename T>
struct ArrayView {
    const T* data = nullptr;
    uint32_t count = 0;
    TRAZO_HD const T& operator[](uint32_t i) const { return data[i]; }
};

struct SceneView {
#define TRAZO_X(T, name) ArrayView<T> name;
    TRAZO_SCENE_ARRAYS(TRAZO_X)
#undef TRAZO_X
    RenderSettings settings;
    FeatureMask features;
};

template <typename T>
ArrayView<T> viewOf(const std::vector<T>& v) {
    return ArrayView<T>{v.data(), (uint32_t)v.size()};
}

// A view of host-resident arrays (the CPU backend renders straight from them).
inline SceneView hostView(const SceneArrays& a) {
    SceneView view{};
#define TRAZO_X(T, name) view.name = viewOf(a.name);
    TRAZO_SCENE_ARRAYS(TRAZO_X)
#undef TRAZO_X
    view.settings = a.settings;
    view.features = a.features;
    return view;
}

}  // namespace trazo
