// A point light as kernels read it (SceneView::pointLights): SPEC §5 reads Color as the light's colour with no
// falloff (the thesis's integrator uses position and colour directly); SPEC §7 as radiant intensity.
#pragma once

#include "core/aabb.h"
#include "lights/light_sample.h"

namespace trazo {

struct PointLightData {
    Vec3 position;
    Vec3 color;
};

// SPEC §7: the direction to the light, and the radiance-equivalent I / r² (a delta light: pdf 1).
TRAZO_HD LightSample sampleLi(const PointLightData& light, Vec3 p, float u1, float u2) {
    (void)u1, (void)u2;
    const Vec3 toLight = light.position - p;
    const float distance2 = dot(toLight, toLight);
    if (!(distance2 > 0.0f)) return noLightSample();
    const float distance = sqrtf(distance2);
    return LightSample{toLight / distance, light.color / distance2, 1.0f, distance, true};
}

// No direction drawn from a BSDF finds a point: no density, no radiance.
TRAZO_HD float pdfLi(const PointLightData&, Vec3, Vec3) { return 0.0f; }
TRAZO_HD Vec3 arrivingLi(const PointLightData&, Vec3, Vec3) { return Vec3(0.0f); }

inline Aabb lightBounds(const PointLightData& light) { return Aabb{light.position, light.position}; }

}  // namespace trazo
