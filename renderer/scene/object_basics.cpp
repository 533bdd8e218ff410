// Transform lists (host): composed in written order as one affine map, and moved by their trailing Translation.
#include "scene/object_basics.h"

namespace trazo {

Affine3 composeTransforms(const std::vector<TransformStep>& steps) {
    Affine3 result;
    for (const TransformStep& s : steps) {
        Affine3 step;
        switch (s.kind) {
            case TransformStep::Kind::Translation: step = makeTranslation(s.value); break;
            case TransformStep::Kind::Rotation: step = makeRotation(s.value, s.angle); break;
            case TransformStep::Kind::Scale: step = makeScale(s.value); break;
        }
        result = then(result, step);  // later steps act on the result of earlier ones
    }
    return result;
}

void translateSteps(std::vector<TransformStep>& steps, Vec3 delta) {
    auto isZero = [](Vec3 v) { return v.x == 0.0f && v.y == 0.0f && v.z == 0.0f; };
    if (!steps.empty() && steps.back().kind == TransformStep::Kind::Translation) {
        steps.back().value += delta;
        if (isZero(steps.back().value)) steps.pop_back();  // exactly zero: the map without it is the same
    } else if (!isZero(delta)) {
        steps.push_back({TransformStep::Kind::Translation, delta, 0.0f});
    }
}

}  // namespace trazo
