// composeTransforms (host): a Box/Mesh/CSG transform list, in written order, as one affine map.
#include "scene/scene.h"

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

}  // namespace trazo
