// ObjectKind and ObjectRef: which kind of object (scene/object_kind_list.h) an entry of the flattened scene is,
// and where its shape and material are (host and device).
#pragma once

#include <cstdint>

#include "scene/object_kind_list.h"

namespace trazo {

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
