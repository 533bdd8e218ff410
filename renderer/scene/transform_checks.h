// What float cannot draw of a transformed object, checked where transforms are set: by the scene reader (an
// error at the block's line) and by the viewer's editor (an edit it refuses). Host code. Each check returns ""
// when the object is drawable, else the reason (docs/LIMITS.md, Geometry).
#pragma once

#include <string>
#include <vector>

#include "core/aabb.h"
#include "scene/scene.h"

namespace trazo {

// The widest a mesh may span: its kernel normal, cross(p1 − p0, p2 − p0), is squared to normalise and
// overflows float for triangles beyond about 2.4e9 a side.
inline constexpr double kMaxMeshExtent = 1e9;

// The box holding `object`'s eight corners after the steps (a rotation may widen it by √3).
Aabb transformedBox(const Aabb& object, const std::vector<TransformStep>& steps);
Aabb meshObjectBounds(const MeshData& data);  // its positions' box, before the Mesh block's transforms

// Each Scale is non-zero as written, but a value below 1e-45 rounds to 0 in float and scales multiply: a
// composed map that float cannot invert (or hold) would reach the renderer as NaN.
std::string invertibleProblem(const std::vector<TransformStep>& steps);
// A box's face normal is normalize(row of objectFromWorld): that row's squared length, 1/scale², must be a
// normal float (with an ulp's margin for the device's fused arithmetic), or the normal is inf or NaN.
std::string boxNormalsProblem(const std::vector<TransformStep>& steps);
// The mesh's span after the steps, at most kMaxMeshExtent ("spans 2e+09 after its transforms; ...").
std::string meshExtentProblem(const MeshData& data, const std::vector<TransformStep>& steps);

}  // namespace trazo
