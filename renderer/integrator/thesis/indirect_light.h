// Indirect(P) of SPEC §5: one bounce of diffuse inter-reflection. Directions about the shading normal with
// θ uniform in [0, π/2) and φ uniform in [0, 2π), stratified q θ-bins × 2q φ-bins; a pass takes a block of
// jittered strata (strata.h). What a direction finds at Q is Q's direct light plus its emission, carried back
// through P's Oren–Nayar term: Kd·ON(N, ω, V, σ) ⊙ (Direct(Q) + Ke(Q)).
#pragma once

#include "core/host_simd.h"
#include "shading/scattering.h"
#include "integrator/surface.h"
#include "integrator/thesis/direct_light.h"
#if TRAZO_HOST_PACKETS
#include "integrator/thesis/indirect_light_lanes.h"
#endif

namespace trazo {

// What a direction's ray found at Q, an object's `hit` (j: the direction's index in the pass's block): Q's direct
// light plus its emission, Direct(Q) + Ke(Q).
template <FeatureMask F>
TRAZO_HD Vec3 lightArrivingFrom(const SceneView& scene, const Ray& ray, const SurfaceHit& hit, const StrataKey& atQ,
                                const StrataBlocks& blocks, uint32_t j, SampleStream& rng, uint32_t& rays) {
    MaterialData mq;
    const ShadingPoint spq = shadingPointAlong(scene, ray, hit, mq);
    return directLight<F>(scene, spq, mq, atQ, blocks.lightAtIndirect, j, rng, rays) + mq.emissive;
}

// The direction of stratum k of the q θ-bins × 2q φ-bins about sp.n, jittered by two draws of rng (θ first).
// about: coneFrame(sp.n), made once for all of a point's directions.
TRAZO_HD Vec3 indirectDirection(const ConeFrame& about, uint32_t k, uint32_t q, SampleStream& rng) {
    const float theta = (float(k % q) + rng.next()) / float(q) * 1.57079632679f;
    const float phi = (float(k / q) + rng.next()) / float(2 * q) * 6.28318530718f;
    return directionInCone(about, theta, phi);
}
TRAZO_HD Vec3 indirectDirection(const ShadingPoint& sp, uint32_t k, uint32_t q, SampleStream& rng) {
    return indirectDirection(coneFrame(sp.n), k, q, rng);
}

// indirectLight's sum over its block of directions (before the ColorBleeding / size factor), one ray at a time.
template <FeatureMask F>
TRAZO_HD Vec3 indirectLightOneByOne(const SceneView& scene, const ShadingPoint& sp, const MaterialData& m,
                                    const StrataBlock& directions, const StrataKey& atQ, const StrataBlocks& blocks,
                                    SampleStream& rng, uint32_t& rays) {
#if !TRAZO_DEVICE_PATHS  // the device: both per direction (as PointBrdf), fewer live registers
    const OrenNayarView view = orenNayarView(sp.n, sp.v, m.roughness);
    const ConeFrame about = coneFrame(sp.n);
#else
    const ShadingPoint& about = sp;
#endif
    Vec3 sum(0.0f);
    for (uint32_t j = 0; j < directions.size; ++j) {
        const Vec3 w = indirectDirection(about, directions.stratum(j), scene.settings.indirectQuality, rng);
        if (dot(w, sp.ng) <= 0.0f) continue;  // below the geometric surface: contributes 0
        const Ray ray{sp.rayOrigin(w), w};
        ++rays;
        SurfaceHit hit;
        if (!intersectScene(scene, ray, INFINITY, hit) || hit.object == kNoObject) continue;  // sky or a light
        const Vec3 arriving = lightArrivingFrom<F>(scene, ray, hit, atQ, blocks, j, rng, rays);
#if !TRAZO_DEVICE_PATHS
        sum += m.diffuse * evalOrenNayar(view, sp.n, w) * arriving;
#else
        sum += m.diffuse * evalOrenNayar(sp.n, w, sp.v, m.roughness) * arriving;
#endif
    }
    return sum;
}

template <FeatureMask F>
TRAZO_HD Vec3 indirectLight(const SceneView& scene, const ShadingPoint& sp, const MaterialData& m,
                            const StrataKey& strata, const StrataBlocks& blocks, SampleStream& rng,
                            uint32_t& rays) {
    const RenderSettings& settings = scene.settings;
    const uint32_t q = settings.indirectQuality;
    if (q == 0 || !(settings.colorBleeding > 0.0f) || isBlack(m.diffuse) || dot(sp.n, sp.v) <= 0.0f) return Vec3(0.0f);
    const StrataBlock directions = strata.block(kGridIndirect, 2 * q * q, blocks.indirect);
    const StrataKey atQ = strata.child(kBranchIndirect);
#if TRAZO_HOST_PACKETS
    if constexpr ((F & kFeatureAreaLights) == 0) {
        if (indirectPacketsApply<F>(scene, directions.size))
            return indirectLightTogether<F>(scene, sp, m, directions, rng, rays) *
                   (settings.colorBleeding / float(directions.size));
    }
#endif
    const Vec3 sum = indirectLightOneByOne<F>(scene, sp, m, directions, atQ, blocks, rng, rays);
    return sum * (settings.colorBleeding / float(directions.size));
}

}  // namespace trazo
