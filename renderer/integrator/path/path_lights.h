// What the path tracer asks of the scene's lights (SPEC §7): one light chosen per shading point for next-event
// estimation, its sample, and the density the same choice gives a direction a BSDF sample found, for multiple
// importance sampling. Lights: the point and area lights (lights/), and the environment (importance-sampled by
// its radiance where it has a map).
#pragma once

#include "integrator/scene_intersect.h"
#include "integrator/strata.h"
#include "lights/environment.h"
#include "lights/visit_light.h"

namespace trazo {

// The environment is a light where the scene stores one (lights/environment.h: not where it is black).
TRAZO_HD bool hasEnvironment(const SceneView& scene) { return scene.environment.count > 0; }

// How many lights next-event estimation chooses among: point lights, area lights, then the environment.
TRAZO_HD uint32_t sampledLightCount(const SceneView& scene) {
    return scene.pointLights.count + scene.areaLights.count + (hasEnvironment(scene) ? 1u : 0u);
}

// The probability of choosing any one light (uniform: every light is chosen as often).
TRAZO_HD float lightChoicePdf(const SceneView& scene) {
    const uint32_t n = sampledLightCount(scene);
    return n > 0 ? 1.0f / float(n) : 0.0f;
}

// A light sample towards light `index` of that order. An area light's point lies in this pass's cell of its
// Subdivision grid (SPEC §7: its strata), the cells visited in an order of their own at each path vertex.
TRAZO_HD LightSample sampleLightAt(const SceneView& scene, uint32_t index, Vec3 p, const StrataKey& vertexStrata,
                                   float u1, float u2, uint32_t& areaLight) {
    areaLight = kNoObject;
    if (index < scene.pointLights.count) return sampleLi(scene.pointLights[index], p, u1, u2);
    index -= scene.pointLights.count;
    if (index < scene.areaLights.count) {
        areaLight = index;
        const AreaLightData& light = scene.areaLights[index];
        const uint32_t cell = vertexStrata.stratum(kGridAreaLightBase + index, light.cellsU * light.cellsV);
        return sampleLi(light, p, (float(cell % light.cellsU) + u1) / float(light.cellsU),
                        (float(cell / light.cellsU) + u2) / float(light.cellsV));
    }
    return sampleEnvironment(scene, u1, u2);
}

// One light chosen uniformly by u (among the point lights alone when pointOnly) and a sample of it from p, its
// density including the choice; a zero pdf where it carries nothing. areaLight: the light's index, or kNoObject.
TRAZO_HD LightSample chooseLightSample(const SceneView& scene, bool pointOnly, Vec3 p, const StrataKey& vertexStrata,
                                       float u, float u1, float u2, uint32_t& areaLight) {
    const uint32_t count = pointOnly ? scene.pointLights.count : sampledLightCount(scene);
    areaLight = kNoObject;
    if (count == 0) return noLightSample();
    const uint32_t index = minOf(uint32_t(u * float(count)), count - 1);
    LightSample ls = sampleLightAt(scene, index, p, vertexStrata, u1, u2, areaLight);
    if (!(ls.pdf > 0.0f) || maxComponent(ls.radiance) <= 0.0f) return noLightSample();
    ls.pdf /= float(count);
    return ls;
}

// True when something opaque lies on the ray within (0, tMax): an object, or under SPEC §7 an area light's
// rectangle (black and opaque from both sides) other than `skipLight`, the one the ray is aimed at.
TRAZO_HD bool pathOccluded(const SceneView& scene, const Ray& ray, float tMax, uint32_t skipLight) {
    ShapeHit hit;
    for (uint32_t i = 0; i < scene.areaLights.count; ++i)
        if (i != skipLight && intersectRectangle(scene.areaLights[i].rect, ray, 0.0f, tMax, hit)) return true;
    return occluded(scene, ray, tMax);
}

// The power heuristic (β = 2) weight of a strategy of density a against one of density b.
TRAZO_HD float powerHeuristic(float a, float b) {
    const float a2 = a * a, b2 = b * b;
    return a2 > 0.0f ? a2 / (a2 + b2) : 0.0f;
}

}  // namespace trazo
