// What a light kind provides, checked once per row of the light-kind list (lights/light_kind_list.h), as
// object_kind_model.h checks the object kinds: a kind missing a piece is one compiler error naming it. The one
// place every light kind's host half (scene/kinds/<kind>.h) is included.
//
// The host half: the struct the reader fills (`position`, `where`), appendLight (flatten()), and the editor's
// operations: hostBounds, translate, newObject, scaleAboutOrigin. The kernel half (lights/<kind>.h): sampleLi,
// pdfLi, arrivingLi and lightBounds over its data.
#pragma once

#include <concepts>
#include <optional>

#include "lights/visit_light.h"
#include "scene/kinds/area_light.h"
#include "scene/kinds/point_light.h"

namespace trazo {

template <class Host>
concept HostLightKind = std::default_initializable<Host> &&
    requires(const Host& light, Host& edited, Vec3 v, float size, double factor) {
        { light.position } -> std::convertible_to<Vec3>;
        { light.where } -> std::convertible_to<SourceLocation>;
        { hostBounds(light) } -> std::same_as<Aabb>;
        translate(edited, v);
        scaleAboutOrigin(edited, factor);
        { newObject(KindTag<Host>{}, v, size) } -> std::same_as<std::optional<Host>>;
    };

template <class Data>
concept KernelLightKind = requires(const Data& light, Vec3 p, float u) {
    { sampleLi(light, p, u, u) } -> std::same_as<LightSample>;
    { pdfLi(light, p, p) } -> std::same_as<float>;
    { arrivingLi(light, p, p) } -> std::same_as<Vec3>;
    { lightBounds(light) } -> std::same_as<Aabb>;
};

#define TRAZO_X(Data, array, Kind, keyword, label, feature)                                                      \
    static_assert(HostLightKind<Kind>, keyword ": its host half (scene/kinds/) lacks a piece of HostLightKind"); \
    static_assert(KernelLightKind<Data>, keyword ": its kernel half (lights/) lacks a piece of KernelLightKind");
TRAZO_LIGHT_KINDS(TRAZO_X)
#undef TRAZO_X

}  // namespace trazo
