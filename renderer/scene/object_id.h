// ObjectId: one object of the host scene (Scene::spheres[index], Scene::boxes[index], ... by kind) or one of
// its lights. What the viewer selects, edits and picks; flatten() maps every drawn object back to it.
#pragma once

#include <cstdint>

#include "objects/object_kind_list.h"

namespace trazo {

struct ObjectId {
    // The object kinds of objects/object_kind_list.h, then the two lights (not ObjectKinds: nothing draws them).
    enum class Kind : uint32_t {
#define TRAZO_X(Shape, array, HostKind, keyword) HostKind,
        TRAZO_OBJECT_KINDS(TRAZO_X)
#undef TRAZO_X
        PointLight,
        AreaLight,
    };
    Kind kind = Kind::Sphere;
    uint32_t index = 0;  // into the Scene vector of that kind

    static ObjectId of(ObjectKind k, uint32_t i) { return {Kind(uint32_t(k)), i}; }
    bool isLight() const { return kind == Kind::PointLight || kind == Kind::AreaLight; }
    ObjectKind objectKind() const { return ObjectKind(uint32_t(kind)); }  // only when !isLight()
    friend bool operator==(const ObjectId&, const ObjectId&) = default;
};

}  // namespace trazo
