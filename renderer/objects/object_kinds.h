// ObjectRef: which kind of object (ObjectKind, objects/object_kind_list.h) an entry of the flattened scene is, and
// where its shape and material are (host and device).
#pragma once

#include <cstdint>

#include "objects/object_kind_list.h"

namespace trazo {

// One renderable object: which shape array, which element, which material. Objects are stored in the order
// of the top-level BVH (topNodes), whose leaves cover ranges of them.
struct ObjectRef {
    ObjectKind kind;
    uint32_t index;
    uint32_t material;
};

}  // namespace trazo
