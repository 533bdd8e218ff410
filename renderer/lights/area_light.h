// An area light as kernels read it (SceneView::areaLights): its rectangle, colour and Subdivision grid. SPEC §5
// samples it by jittered cells of the grid (cellPoint); SPEC §7 reads it as a one-sided emitter of radiance Color
// from the side its normal points to, sampled uniformly over its area (sampleLi, pdfLi).
#pragma once

#include <cstdint>

#include "core/aabb.h"
#include "core/rng.h"
#include "lights/light_sample.h"
#include "lights/rectangle.h"

namespace trazo {

struct AreaLightData {
    RectangleShape rect;
    Vec3 color;
    uint32_t cellsU, cellsV;  // Subdivision: strata of the light's surface
};

// The point at (su, sv) ∈ [0, 1]² of the rectangle, u along halfU.
TRAZO_HD Vec3 areaLightPoint(const AreaLightData& light, float su, float sv) {
    return light.rect.center + light.rect.halfU * (2.0f * su - 1.0f) + light.rect.halfV * (2.0f * sv - 1.0f);
}

// The jittered point of cell s of the light's grid (two draws of rng, u first): SPEC §5's area-light samples.
TRAZO_HD Vec3 cellPoint(const AreaLightData& light, uint32_t s, SampleStream& rng) {
    const float su = (float(s % light.cellsU) + rng.next()) / float(light.cellsU);
    const float sv = (float(s / light.cellsU) + rng.next()) / float(light.cellsV);
    return areaLightPoint(light, su, sv);
}

TRAZO_HD float areaLightArea(const AreaLightData& light) {
    return 4.0f * length(cross(light.rect.halfU, light.rect.halfV));
}

// Radiance leaving the light towards direction w (from the light): Color on its front, black behind (SPEC §7).
TRAZO_HD Vec3 areaLightRadiance(const AreaLightData& light, Vec3 w) {
    return dot(light.rect.normal, w) > 0.0f ? light.color : Vec3(0.0f);
}

// The solid-angle density at p of a uniform point of the light at `distance` along unit wi.
TRAZO_HD float areaLightPdf(const AreaLightData& light, Vec3 wi, float distance) {
    const float cosine = fabsf(dot(light.rect.normal, wi));
    const float area = areaLightArea(light);
    if (!(cosine > 0.0f) || !(area > 0.0f)) return 0.0f;
    return distance * distance / (area * cosine);
}

// A uniform point of the rectangle from (u1, u2), seen from p.
TRAZO_HD LightSample sampleLi(const AreaLightData& light, Vec3 p, float u1, float u2) {
    const Vec3 toLight = areaLightPoint(light, u1, u2) - p;
    const float distance = length(toLight);
    if (!(distance > 0.0f)) return noLightSample();
    const Vec3 wi = toLight / distance;
    const float pdf = areaLightPdf(light, wi, distance);
    if (!(pdf > 0.0f)) return noLightSample();
    return LightSample{wi, areaLightRadiance(light, -wi), pdf, distance, false};
}

// The density sampleLi would give direction wi from p: 0 unless the ray p + t·wi meets the rectangle.
TRAZO_HD float pdfLi(const AreaLightData& light, Vec3 p, Vec3 wi) {
    ShapeHit hit;
    if (!intersectRectangle(light.rect, Ray{p, wi}, 0.0f, INFINITY, hit)) return 0.0f;
    return areaLightPdf(light, wi, hit.t);
}

// The radiance arriving at p from direction wi: Color where the ray p + t·wi meets the rectangle's front.
TRAZO_HD Vec3 arrivingLi(const AreaLightData& light, Vec3 p, Vec3 wi) {
    ShapeHit hit;
    if (!intersectRectangle(light.rect, Ray{p, wi}, 0.0f, INFINITY, hit)) return Vec3(0.0f);
    return areaLightRadiance(light, -wi);
}

inline Aabb lightBounds(const AreaLightData& light) {
    Aabb b;
    const RectangleShape& r = light.rect;
    for (const Vec3 corner : {r.center - r.halfU - r.halfV, r.center + r.halfU - r.halfV, r.center - r.halfU + r.halfV,
                              r.center + r.halfU + r.halfV})
        b.grow(corner);
    return b;
}

}  // namespace trazo
