// SceneView: the flattened scene as kernels read it, non-owning views over arrays in host or device memory
// (plain structs with 32-bit indices: no pointers, names or STL). Element types are only declared here, so
// each object kind's header can take a SceneView while SceneView lists that kind's array.
#pragma once

#include <cstdint>

#include "core/feature_mask.h"
#include "core/hd.h"
#include "core/render_settings.h"
#include "core/vec3.h"
#include "lights/light_kind_list.h"
#include "objects/object_kinds.h"

namespace trazo {

#define TRAZO_X(Shape, ...) struct Shape;
TRAZO_OBJECT_KINDS(TRAZO_X)
#undef TRAZO_X
struct CsgNodeData;
struct MeshTriangle;
struct TriangleBlock;
struct TriangleCorners;
struct WideBvhNode;
struct WideBvhNode8;
struct MaterialData;
struct TextureData;
struct EnvironmentData;
struct SceneArrays;  // flatten/scene_arrays.h: the owning host copy

// Every array of the flattened scene, once: the object kinds' shape arrays (objects/object_kind_list.h), then
// the rest, the light kinds' arrays (lights/light_kind_list.h) among them. SceneArrays, SceneView, hostView() and
// the backends' uploads are all generated from this list, so adding an array is a one-line change. X(element type, member name, ...).
#define TRAZO_SCENE_ARRAYS(X)           \
    TRAZO_OBJECT_KINDS(X)               \
    X(CsgNodeData, csgNodes)            \
    X(ObjectRef, objects)               \
    X(MaterialData, materials)          \
    TRAZO_LIGHT_KINDS(X)                \
    X(TextureData, textures)            \
    X(Vec3, texels)                     \
    X(EnvironmentData, environment)     \
    X(float, environmentCdf)            \
    X(WideBvhNode, meshNodes)           \
    X(MeshTriangle, triangles)          \
    X(TriangleCorners, triangleCorners) \
    X(WideBvhNode, topNodes)

template <typename T>
struct ArrayView {
    const T* data = nullptr;
    uint32_t count = 0;
    TRAZO_HD const T& operator[](uint32_t i) const { return data[i]; }
};

struct SceneView {
#define TRAZO_X(T, name, ...) ArrayView<T> name;
    TRAZO_SCENE_ARRAYS(TRAZO_X)
#undef TRAZO_X
    RenderSettings settings;
    FeatureMask features;
    // Host only, outside the uploaded list: the meshes' eight-wide BVHs (MeshShape::nodeOffset8), where the CPU
    // backend's AVX2 or AVX-512 kernels run, and the blocks their leaves name (widenMeshBvhs,
    // flatten/flatten_mesh.h); empty elsewhere.
    ArrayView<WideBvhNode8> meshNodes8;
    ArrayView<TriangleBlock> triangleBlocks;
};

}  // namespace trazo
