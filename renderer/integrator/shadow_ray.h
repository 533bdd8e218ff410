// Shadow rays from a shading point towards a point of a light, for every integrator's direct light.
#pragma once

#include "shading/shading_point.h"

namespace trazo {

// The shadow ray from the shading point towards a light sample X: l the unit vector to X, leaving from origin
// over (0, |X − origin|); false where Shade is 0 without one (X at the point, or not above its shading normal).
TRAZO_HD bool aimShadowRay(const ShadingPoint& sp, Vec3 x, Vec3& l, Vec3& origin) {
    Vec3 toLight = x - sp.p;
    const float dist = length(toLight);
    if (!(dist > 0.0f)) return false;
    l = toLight / dist;
    if (dot(sp.n, l) <= 0.0f) return false;
    origin = sp.rayOrigin(l);
    return true;
}

}  // namespace trazo
