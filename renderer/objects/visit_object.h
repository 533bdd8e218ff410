// visitObject: the one dispatch over object kinds (host and device), and the one place that includes every
// kind's header (a new kind adds its line here and in objects/object_kind_list.h). It calls f with the object's shape,
// and overloads of each kind's interface (objects/<kind>.h: intersectObject, objectBlocks, objectSurface,
// objectHasUvs, objectBounds) do the rest, as pbrt-v4's TaggedPointer::Dispatch does; no virtual calls.
#pragma once

#include "objects/box.h"
#include "objects/csg.h"
#include "objects/cylinder.h"
#include "objects/mesh.h"
#include "objects/object_kinds.h"
#include "objects/scene_view.h"
#include "objects/sphere.h"

namespace trazo {

template <typename F>
TRAZO_HD auto visitObject(const SceneView& scene, const ObjectRef& o, F&& f) -> decltype(f(scene.spheres[0])) {
    switch (o.kind) {
#define TRAZO_X(Shape, array, Kind, keyword) \
    case ObjectKind::Kind: return f(scene.array[o.index]);
        TRAZO_OBJECT_KINDS(TRAZO_X)
#undef TRAZO_X
    }
    TRAZO_UNREACHABLE();
}

}  // namespace trazo
