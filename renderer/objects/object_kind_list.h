// The object kinds of the scene language, listed once (host and device). The list generates ObjectKind, the
// kinds' arrays of Scene, SceneView and SceneArrays, visitObject's dispatch, flatten()'s loop over the host
// scene, the reader's, writer's, tables' and editor's handling of each kind's block, and the checks that each
// kind has its two halves: the kernel half objects/<kind>.h, the host half scene/kinds/<kind>.h
// (scene/kinds/object_kind_model.h). X(device shape type, array in Scene and SceneView, host struct, block
// keyword in a scene file).
#pragma once

#include <cstdint>

#define TRAZO_OBJECT_KINDS(X)                       \
    X(SphereShape, spheres, Sphere, "Sphere")       \
    X(BoxShape, boxes, Box, "Box")                  \
    X(CylinderShape, cylinders, Cylinder, "Cylinder") \
    X(CsgShape, csgs, Csg, "CSG")                   \
    X(MeshShape, meshes, Mesh, "Mesh")

namespace trazo {

enum class ObjectKind : uint32_t {
#define TRAZO_X(Shape, array, Kind, keyword) Kind,
    TRAZO_OBJECT_KINDS(TRAZO_X)
#undef TRAZO_X
};

}  // namespace trazo
