// The object kinds of the scene language, listed once (host and device). The list generates ObjectKind, the
// shape arrays of SceneView and SceneArrays, visitObject's dispatch, flatten()'s loop over the host scene, and
// the reader's, writer's and tables' handling of each kind's block; each kind's kernel code lives in its own
// header (objects/<kind>.h). X(device shape type, array in Scene and SceneView, host struct in scene.h, block
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
