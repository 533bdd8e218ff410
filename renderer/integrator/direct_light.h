// Direct(P) of SPEC §5: point lights with hard shadows, area lights by one jittered stratum per pass.
#pragma once

#include "core/rng.h"
#include "integrator/scene_intersect.h"
#include "shading/cook_torrance.h"
#include "shading/oren_nayar.h"

namespace trazo {

// Shade(P, L, C) = C ⊙ [Kd·ON + Ks·CT] when N·L > 0 and N·V > 0, else 0.
TRAZO_HD Vec3 shade(Vec3 n, Vec3 l, Vec3 v, Vec3 lightColor, const MaterialData& m) {
    if (dot(n, l) <= 0.0f || dot(n, v) <= 0.0f) return Vec3(0.0f);
    return lightColor * (m.diffuse * evalOrenNayar(n, l, v, m.roughness) +
                         m.specular * evalCookTorrance(n, l, v, m.roughness));
}

// Everything a shading point needs to send shadow rays and draw its strata.
struct ShadingPoint {
    Vec3 p;
    Vec3 pError;
    Vec3 ng;  // geometric normal turned towards the viewer
    Vec3 n;   // shading normal turned towards the viewer
    Vec3 v;   // towards the viewer
};

// Identifies one stratified grid of one shading point in the pixel's sample tree, for stratumForPass.
struct StrataKey {
    uint32_t seed, pixelIndex, pass, node;
    bool fixedGrid;  // the thesis's estimator: every stratum in every pass
    TRAZO_HD uint32_t stratum(uint32_t grid, uint32_t count) const {
        return stratumForPass(seed, pixelIndex, hashCombine(node, grid), pass, count);
    }
    // The strata of a grid of `count` this pass visits: [first, first + visited). One, cycling over passes;
    // or all of them with the fixed grid.
    TRAZO_HD void strata(uint32_t grid, uint32_t count, uint32_t& first, uint32_t& visited) const {
        first = fixedGrid ? 0u : stratum(grid, count);
        visited = fixedGrid ? count : 1u;
    }
    TRAZO_HD StrataKey child(uint32_t branch) const {
        return StrataKey{seed, pixelIndex, pass, hashCombine(node, branch), fixedGrid};
    }
};

constexpr uint32_t kGridGlossy = 1;
constexpr uint32_t kGridAreaLightBase = 16;  // + light index

// One light sample X seen from the shading point: visible ⇒ Shade(P, L, C). Counts the shadow ray.
TRAZO_HD Vec3 shadeFromPoint(const SceneView& scene, const ShadingPoint& sp, const MaterialData& m, Vec3 x,
                             Vec3 color, uint32_t& rays) {
    Vec3 toLight = x - sp.p;
    const float dist = length(toLight);
    if (!(dist > 0.0f)) return Vec3(0.0f);
    const Vec3 l = toLight / dist;
    if (dot(sp.n, l) <= 0.0f) return Vec3(0.0f);  // Shade would be 0: skip the shadow ray
    const Vec3 origin = offsetRayOrigin(sp.p, sp.pError, sp.ng, l);
    ++rays;
    if (occluded(scene, Ray{origin, l}, length(x - origin))) return Vec3(0.0f);
    return shade(sp.n, l, sp.v, color, m);
}

// F: the scene's specialised feature bits (sample_variants.h); without kFeatureAreaLights the area-light
// loop is compiled out.
template <FeatureMask F>
TRAZO_HD Vec3 directLight(const SceneView& scene, const ShadingPoint& sp, const MaterialData& m,
                          const StrataKey& strata, SampleStream& rng, uint32_t& rays) {
    Vec3 sum(0.0f);
    for (uint32_t i = 0; i < scene.pointLights.count; ++i) {
        const PointLightData& light = scene.pointLights[i];
        sum += shadeFromPoint(scene, sp, m, light.position, light.color, rays);
    }
    if constexpr ((F & kFeatureAreaLights) != 0) {
    for (uint32_t i = 0; i < scene.areaLights.count; ++i) {
        const AreaLightData& light = scene.areaLights[i];
        uint32_t first, visited;
        strata.strata(kGridAreaLightBase + i, light.cellsU * light.cellsV, first, visited);
        Vec3 lightSum(0.0f);
        for (uint32_t s = first; s < first + visited; ++s) {
            const float su = (float(s % light.cellsU) + rng.next()) / float(light.cellsU);
            const float sv = (float(s / light.cellsU) + rng.next()) / float(light.cellsV);
            const Vec3 x = light.rect.center + light.rect.halfU * (2.0f * su - 1.0f) + light.rect.halfV * (2.0f * sv - 1.0f);
            lightSum += shadeFromPoint(scene, sp, m, x, light.color, rays);
        }
        sum += visited == 1 ? lightSum : lightSum / float(visited);
    }
    }
    return sum;
}

}  // namespace trazo
