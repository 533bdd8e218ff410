// Shade(P, L, C) of SPEC §5 for one point of a light: the thesis's reflectance towards it, if it is visible.
#pragma once

#include "core/rng.h"
#include "integrator/scene_intersect.h"
#include "integrator/shadow_ray.h"
#include "lights/area_light.h"
#include "lights/point_light.h"
#include "shading/thesis_brdf.h"

namespace trazo {

// One light sample X seen from the shading point: visible ⇒ Shade(P, L, C) = C ⊙ brdf(L). Counts the
// shadow ray.
TRAZO_HD Vec3 shadeFromPoint(const SceneView& scene, const ShadingPoint& sp, const PointBrdf& brdf, Vec3 x,
                             Vec3 color, uint32_t& rays) {
    Vec3 l, origin;
    if (!aimShadowRay(sp, x, l, origin)) return Vec3(0.0f);  // Shade would be 0: no shadow ray
    ++rays;
    if (occluded(scene, Ray{origin, l}, length(x - origin))) return Vec3(0.0f);
    return color * brdf.eval(l);
}

}  // namespace trazo
