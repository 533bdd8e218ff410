// What next-event estimation asks of a light (SPEC §7's reading of the light: radiance, or for a point light
// radiant intensity with inverse-square falloff): sampleLi draws a direction towards the light from a point,
// pdfLi gives the density with which sampleLi would have drawn a direction, and arrivingLi the radiance a
// direction found by other means (a BSDF sample) receives from the light, for multiple importance sampling.
#pragma once

#include "core/hd.h"
#include "core/vec3.h"

namespace trazo {

struct LightSample {
    Vec3 wi;         // unit direction from the shading point towards the light
    Vec3 radiance;   // arriving along -wi (0: the sample carries nothing, e.g. the light's back)
    float pdf;       // in solid angle at the shading point; 1 for a delta light
    float distance;  // to the sampled point, for the shadow ray
    bool delta;      // a point light: no direction of a BSDF sample finds it, so no MIS weight
};

// A light that gives nothing from this point (the zero pdf tells an estimator to skip it).
TRAZO_HD LightSample noLightSample() { return LightSample{Vec3(0.0f, 0.0f, 1.0f), Vec3(0.0f), 0.0f, 0.0f, false}; }

}  // namespace trazo
