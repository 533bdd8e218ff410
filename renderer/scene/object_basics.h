// What every object kind's host struct (scene/kinds/<kind>.h) is made of: a material index (kDefaultMaterial
// when the block names none), transform steps kept as written, and the block's place in the file.
#pragma once

#include <cstdint>
#include <vector>

#include "core/affine.h"
#include "core/vec3.h"
#include "scene/diagnostic.h"

namespace trazo {

constexpr int32_t kDefaultMaterial = -1;  // an object without `Material` uses the Material defaults

// One step of an ordered transform list, kept as written (the viewer and "save scene" need it).
struct TransformStep {
    enum class Kind { Translation, Rotation, Scale } kind = Kind::Translation;
    Vec3 value{0, 0, 0};  // translation, rotation axis, or scale factors
    float angle = 0.0f;   // radians, rotations only
};

// Composes the steps in written order: later steps act on the result of earlier ones.
Affine3 composeTransforms(const std::vector<TransformStep>& steps);

// Moves a transformed object by `delta` through its trailing Translation step: appended when the list does not
// end with one, removed when it becomes exactly zero, so a drag's many moves never lengthen the list.
void translateSteps(std::vector<TransformStep>& steps, Vec3 delta);

// Scaling the whole scene about the origin by `factor` (scaleAboutOrigin of each kind): a point's and a length's
// product rounded once to float, and a transformed object's uniform Scale step appended (it acts on the world).
inline Vec3 scaledPoint(Vec3 p, double factor) {
    return Vec3(float(p.x * factor), float(p.y * factor), float(p.z * factor));
}
inline void scaleSteps(std::vector<TransformStep>& steps, double factor) {
    const float f = float(factor);
    steps.push_back({TransformStep::Kind::Scale, Vec3(f, f, f), 0.0f});
}

// The tag newObject(KindTag<Kind>{}, at, size) is overloaded on (scene/kinds/object_kind_model.h).
template <class Kind>
struct KindTag {};

}  // namespace trazo
