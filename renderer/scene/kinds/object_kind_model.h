// What an object kind provides, checked once per row of the kind list (objects/object_kind_list.h) so that a
// kind missing a piece is one compiler error naming it, not a silent gap in the editor or the tests. The one
// place every kind's host half (scene/kinds/<kind>.h) is included.
//
// The host half: the struct the reader fills (`material`, `where`, kReadFromFile), appendObject (flatten(),
// except for meshes, which flatten/mesh_reuse.h places), and the editor's operations: hostBounds, translate,
// newObject (nullopt for a kind read from a file), scaleAboutOrigin. The kernel half (objects/<kind>.h):
// intersectObject, objectBlocks, objectSurface, objectHasUvs, objectBounds over its shape.
#pragma once

#include <concepts>
#include <optional>

#include "objects/object_kind_list.h"
#include "objects/visit_object.h"
#include "scene/kinds/box.h"
#include "scene/kinds/csg.h"
#include "scene/kinds/cylinder.h"
#include "scene/kinds/mesh.h"
#include "scene/kinds/sphere.h"

namespace trazo {

template <class Host>
concept HostObjectKind = std::default_initializable<Host> &&
    requires(const Host& object, Host& edited, Vec3 v, float size, double factor) {
        { object.material } -> std::convertible_to<int32_t>;
        { object.where } -> std::convertible_to<SourceLocation>;
        { Host::kReadFromFile } -> std::convertible_to<bool>;
        { hostBounds(object) } -> std::same_as<Aabb>;
        translate(edited, v);
        scaleAboutOrigin(edited, factor);
        { newObject(KindTag<Host>{}, v, size) } -> std::same_as<std::optional<Host>>;
    };

template <class Shape>
concept KernelObjectKind =
    requires(const SceneView& scene, const Shape& shape, const Ray& ray, float tMax, ClosestStack& closest,
             AnyStack& any, ShapeHit& hit, Vec3 p) {
        { intersectObject(scene, shape, ray, tMax, closest, hit) } -> std::same_as<bool>;
        { objectBlocks(scene, shape, ray, tMax, any) } -> std::same_as<bool>;
        { objectSurface(scene, shape, hit, p, true) } -> std::same_as<SurfacePoint>;
        { objectHasUvs(scene, shape) } -> std::same_as<bool>;
        { objectBounds(scene, shape) } -> std::same_as<Aabb>;
    };

#define TRAZO_X(Shape, array, Kind, keyword)                                                                 \
    static_assert(HostObjectKind<Kind>, keyword ": its host half (scene/kinds/) lacks a piece of HostObjectKind"); \
    static_assert(KernelObjectKind<Shape>, keyword ": its kernel half (objects/) lacks a piece of KernelObjectKind");
TRAZO_OBJECT_KINDS(TRAZO_X)
#undef TRAZO_X

}  // namespace trazo
