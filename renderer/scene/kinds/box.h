// The Box block on the host: the struct the reader fills (a unit cube and its transform steps), its flattening
// into the kernels' BoxShape (objects/box.h), and the editor's operations on one.
#pragma once

#include <optional>
#include <vector>

#include "objects/box.h"
#include "scene/object_basics.h"

namespace trazo {

struct Box {
    static constexpr bool kReadFromFile = false;
    int32_t material = kDefaultMaterial;
    std::vector<TransformStep> transforms;  // applied to the unit cube centred at the origin
    SourceLocation where;
};

// Appends the box to out.boxes (templated on the arrays: see the sphere's appendObject).
template <class Arrays>
bool appendObject(const Box& box, Arrays& out, uint32_t& index) {
    const Affine3 worldFromObject = composeTransforms(box.transforms);
    index = (uint32_t)out.boxes.size();
    out.boxes.push_back({inverse(worldFromObject), worldFromObject});
    return true;
}

inline Aabb hostBounds(const Box& b) {
    const Affine3 worldFromObject = composeTransforms(b.transforms);
    return objectBounds(SceneView{}, BoxShape{inverse(worldFromObject), worldFromObject});
}
inline void translate(Box& b, Vec3 delta) { translateSteps(b.transforms, delta); }
inline std::optional<Box> newObject(KindTag<Box>, Vec3 at, float size) {
    using Step = TransformStep::Kind;
    return Box{kDefaultMaterial, {{Step::Scale, Vec3(size), 0.0f}, {Step::Translation, at, 0.0f}}, {}};
}
inline void scaleAboutOrigin(Box& b, double factor) { scaleSteps(b.transforms, factor); }

}  // namespace trazo
