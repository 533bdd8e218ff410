// The kinds of object a scene holds, listed once (host and device). The list generates ObjectKind, the
// shape arrays of SceneView and SceneArrays, visitObject's dispatch and flatten()'s loop over the host
// scene; each kind's code lives in its own header (objects/<kind>.h). X(shape type, array, kind name, the
// kind's block keyword in a scene file).
#pragma once

#include <cstdint>

namespace trazo {

#define TRAZO_OBJECT_KINDS(X)                       \
    X(SphereShape, spheres, Sphere, "Sphere")       \
    X(BoxShape, boxes, Box, "Box")                  \
    X(CylinderShape, cylinders, Cylinder, "Cylinder") \
    X(CsgShape, csgs, Csg, "CSG")                   \
    X(MeshShape, meshes, Mesh, "Mesh")

enum class ObjectKind : uint32_t {
#define TRAZO_X(Shape, array, Kind, keyword) Kind,
    TRAZO_OBJECT_KINDS(TRAZO_X)
#undef TRAZO_X
};

// One renderable object: which shape array, which element, which material. Objects are stored in the order
// of the top-level BVH (topNodes), whose leaves cover ranges of them.
struct ObjectRef {
    ObjectKind kind;
    uint32_t index;
    uint32_t material;
};

}  // namespace trazo
