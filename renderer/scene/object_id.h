// ObjectId: one object of the host scene (Scene::spheres[index], Scene::boxes[index], ... by kind) or one of
// its lights. What the viewer selects, edits and picks; flatten() maps every drawn object back to it.
#pragma once

#include <cstdint>

#include "lights/light_kind_list.h"
#include "objects/object_kind_list.h"

namespace trazo {

struct ObjectId {
    // The object kinds of objects/object_kind_list.h, then the light kinds of lights/light_kind_list.h (not
    // ObjectKinds: no object is drawn for them).
    enum class Kind : uint32_t {
#define TRAZO_X(Shape, array, HostKind, keyword) HostKind,
        TRAZO_OBJECT_KINDS(TRAZO_X)
#undef TRAZO_X
#define TRAZO_X(Data, array, HostKind, ...) HostKind,
        TRAZO_LIGHT_KINDS(TRAZO_X)
#undef TRAZO_X
    };
    // The first light kind: lights follow the object kinds.
    static constexpr uint32_t kFirstLight = 0
#define TRAZO_X(...) +1
        TRAZO_OBJECT_KINDS(TRAZO_X)
#undef TRAZO_X
        ;
    Kind kind = Kind::Sphere;
    uint32_t index = 0;  // into the Scene vector of that kind

    static ObjectId of(ObjectKind k, uint32_t i) { return {Kind(uint32_t(k)), i}; }
    static constexpr uint32_t kKindCount = kFirstLight
#define TRAZO_X(...) +1
        TRAZO_LIGHT_KINDS(TRAZO_X)
#undef TRAZO_X
        ;
    bool isLight() const { return uint32_t(kind) >= kFirstLight; }
    ObjectKind objectKind() const { return ObjectKind(uint32_t(kind)); }  // only when !isLight()
    friend bool operator==(const ObjectId&, const ObjectId&) = default;
};

}  // namespace trazo
