// Indirect(P) of SPEC §5: one bounce of diffuse inter-reflection. Directions about the shading normal with
// θ uniform in [0, π/2) and φ uniform in [0, 2π), stratified q θ-bins × 2q φ-bins; a pass takes a block of
// jittered strata (strata.h). What a direction finds at Q is Q's direct light plus its emission, carried back
// through P's Oren–Nayar term: Kd·ON(N, ω, V, σ) ⊙ (Direct(Q) + Ke(Q)).
#pragma once

#include "integrator/direct_light.h"
#include "integrator/scattering.h"
#include "integrator/surface.h"

namespace trazo {

template <FeatureMask F>
TRAZO_HD Vec3 indirectLight(const SceneView& scene, const ShadingPoint& sp, const MaterialData& m,
                            const StrataKey& strata, const StrataBlocks& blocks, SampleStream& rng,
                            uint32_t& rays) {
    const RenderSettings& settings = scene.settings;
    const uint32_t q = settings.indirectQuality;
    if (q == 0 || !(settings.colorBleeding > 0.0f) || isBlack(m.diffuse) || dot(sp.n, sp.v) <= 0.0f) return Vec3(0.0f);
    const StrataBlock directions = strata.block(kGridIndirect, 2 * q * q, blocks.indirect);
    const StrataKey atQ = strata.child(kBranchIndirect);
#if !TRAZO_DEVICE_PATHS
    const OrenNayarView view = orenNayarView(sp.n, sp.v, m.roughness);  // the device: per direction, as PointBrdf
#endif
    Vec3 sum(0.0f);
    for (uint32_t j = 0; j < directions.size; ++j) {
        const uint32_t k = directions.stratum(j);
        const float theta = (float(k % q) + rng.next()) / float(q) * 1.57079632679f;
        const float phi = (float(k / q) + rng.next()) / float(2 * q) * 6.28318530718f;
        const Vec3 w = directionInCone(sp.n, theta, phi);
        if (dot(w, sp.ng) <= 0.0f) continue;  // below the geometric surface: contributes 0
        const Ray ray{sp.rayOrigin(w), w};
        ++rays;
        SurfaceHit hit;
        if (!intersectScene(scene, ray, INFINITY, hit) || hit.object == kNoObject) continue;  // sky or a light
        const ObjectRef& o = scene.objects[hit.object];
        MaterialData mq = scene.materials[o.material];
        SurfacePoint sq = surfaceAt(scene, o, hit, pointAt(ray, hit.t), materialHasTextures(mq));
        applyTextures(scene, mq, sq);
        const ShadingPoint spq = facingShadingPoint(pointAt(ray, hit.t), hitPointError(ray, hit.t), w, sq);
        const Vec3 arriving = directLight<F>(scene, spq, mq, atQ, blocks.lightAtIndirect, j, rng, rays) + mq.emissive;
#if !TRAZO_DEVICE_PATHS
        sum += m.diffuse * evalOrenNayar(view, sp.n, w) * arriving;
#else
        sum += m.diffuse * evalOrenNayar(sp.n, w, sp.v, m.roughness) * arriving;
#endif
    }
    return sum * (settings.colorBleeding / float(directions.size));
}

}  // namespace trazo
