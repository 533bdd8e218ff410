// Direct(P) of SPEC §5: point lights with hard shadows, area lights by a block of jittered cells per pass.
#pragma once

#include "core/rng.h"
#include "integrator/strata.h"
#include "integrator/scene_intersect.h"
#include "shading/cook_torrance.h"
#include "shading/oren_nayar.h"

namespace trazo {

// The material's Shade of SPEC §5 at one shading point: what depends only on the viewer is computed once,
// and a black lobe is never evaluated (a matte surface pays no Cook–Torrance, σ = 0 no Oren–Nayar azimuth).
struct PointBrdf {
    Vec3 n, v;
    Vec3 diffuse, specular;
    float roughness;
    OrenNayarView diffuseView;
    bool hasDiffuse, hasSpecular;

    TRAZO_HD PointBrdf(Vec3 nIn, Vec3 vIn, const MaterialData& m)
        : n(nIn), v(vIn), diffuse(m.diffuse), specular(m.specular), roughness(m.roughness),
          diffuseView(orenNayarView(nIn, vIn, m.roughness)), hasDiffuse(!isBlack(m.diffuse)),
          hasSpecular(!isBlack(m.specular)) {}

    TRAZO_HD bool reflects() const { return (hasDiffuse || hasSpecular) && dot(n, v) > 0.0f; }
    // Kd·ON(N, L, V, σ) + Ks·CT(N, L, V, σ); N·L > 0 and N·V > 0 assumed.
    TRAZO_HD Vec3 eval(Vec3 l) const {
        Vec3 f(0.0f);
        if (hasDiffuse) f = diffuse * evalOrenNayar(diffuseView, n, l);
        if (hasSpecular) f += specular * evalCookTorrance(n, l, v, roughness);
        return f;
    }
};

// Everything a shading point needs to send shadow rays and draw its strata.
struct ShadingPoint {
    Vec3 p;
    Vec3 pError;
    Vec3 ng;  // geometric normal turned towards the viewer
    Vec3 n;   // shading normal turned towards the viewer
    Vec3 v;   // towards the viewer
};

// One light sample X seen from the shading point: visible ⇒ Shade(P, L, C) = C ⊙ brdf(L). Counts the
// shadow ray.
TRAZO_HD Vec3 shadeFromPoint(const SceneView& scene, const ShadingPoint& sp, const PointBrdf& brdf, Vec3 x,
                             Vec3 color, uint32_t& rays) {
    Vec3 toLight = x - sp.p;
    const float dist = length(toLight);
    if (!(dist > 0.0f)) return Vec3(0.0f);
    const Vec3 l = toLight / dist;
    if (dot(sp.n, l) <= 0.0f) return Vec3(0.0f);  // Shade would be 0: skip the shadow ray
    const Vec3 origin = offsetRayOrigin(sp.p, sp.pError, sp.ng, l);
    ++rays;
    if (occluded(scene, Ray{origin, l}, length(x - origin))) return Vec3(0.0f);
    return color * brdf.eval(l);
}

// F: the scene's specialised feature bits (sample_variants.h); without kFeatureAreaLights the area-light
// loop is compiled out. lightBlock: the StrataBlocks target for the area lights' cells at this point;
// rotation: StrataKey::block's (the index of the indirect direction that found this point).
template <FeatureMask F>
TRAZO_HD Vec3 directLight(const SceneView& scene, const ShadingPoint& sp, const MaterialData& m,
                          const StrataKey& strata, uint32_t lightBlock, uint32_t rotation, SampleStream& rng,
                          uint32_t& rays) {
    Vec3 sum(0.0f);
    const PointBrdf brdf(sp.n, sp.v, m);
    if (!brdf.reflects()) return sum;  // Shade is 0 for every light: no shadow rays
    for (uint32_t i = 0; i < scene.pointLights.count; ++i) {
        const PointLightData& light = scene.pointLights[i];
        sum += shadeFromPoint(scene, sp, brdf, light.position, light.color, rays);
    }
    if constexpr ((F & kFeatureAreaLights) != 0) {
    for (uint32_t i = 0; i < scene.areaLights.count; ++i) {
        const AreaLightData& light = scene.areaLights[i];
        const StrataBlock cells = strata.block(kGridAreaLightBase + i, light.cellsU * light.cellsV, lightBlock, rotation);
        Vec3 lightSum(0.0f);
        for (uint32_t j = 0; j < cells.size; ++j) {
            const uint32_t s = cells.stratum(j);
            const float su = (float(s % light.cellsU) + rng.next()) / float(light.cellsU);
            const float sv = (float(s / light.cellsU) + rng.next()) / float(light.cellsV);
            const Vec3 x = light.rect.center + light.rect.halfU * (2.0f * su - 1.0f) + light.rect.halfV * (2.0f * sv - 1.0f);
            lightSum += shadeFromPoint(scene, sp, brdf, x, light.color, rays);
        }
        sum += cells.size == 1 ? lightSum : lightSum / float(cells.size);
    }
    }
    return sum;
}

}  // namespace trazo
