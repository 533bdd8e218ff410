// Indirect(P) of SPEC §5: one bounce of diffuse inter-reflection. Directions about the shading normal with
// θ uniform in [0, π/2) and φ uniform in [0, 2π), stratified q θ-bins × 2q φ-bins; a pass takes a block of
// jittered strata (strata.h). What a direction finds at Q is Q's direct light plus its emission, carried back
// through P's Oren–Nayar term: Kd·ON(N, ω, V, σ) ⊙ (Direct(Q) + Ke(Q)).
#pragma once

#include "integrator/direct_light.h"
#include "integrator/scattering.h"
#include "integrator/surface.h"
#if TRAZO_SHADOW_PACKETS
#include <new>

#include "integrator/nearest_packet.h"
#endif

namespace trazo {

// The shading point at Q, an object's `hit` along `ray`, and in mq its material with textures applied.
TRAZO_HD ShadingPoint shadingPointAt(const SceneView& scene, const Ray& ray, const SurfaceHit& hit, MaterialData& mq) {
    const ObjectRef& o = scene.objects[hit.object];
    mq = scene.materials[o.material];
    SurfacePoint sq = surfaceAt(scene, o, hit, pointAt(ray, hit.t), materialHasTextures(mq));
    applyTextures(scene, mq, sq);
    return facingShadingPoint(pointAt(ray, hit.t), hitPointError(ray, hit.t), ray.direction, sq);
}

// What a direction's ray found at Q, an object's `hit` (j: the direction's index in the pass's block): Q's direct
// light plus its emission, Direct(Q) + Ke(Q).
template <FeatureMask F>
TRAZO_HD Vec3 lightArrivingFrom(const SceneView& scene, const Ray& ray, const SurfaceHit& hit, const StrataKey& atQ,
                                const StrataBlocks& blocks, uint32_t j, SampleStream& rng, uint32_t& rays) {
    MaterialData mq;
    const ShadingPoint spq = shadingPointAt(scene, ray, hit, mq);
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

#if TRAZO_SHADOW_PACKETS
constexpr uint32_t kMinIndirectPacket = 4;  // fewer directions a pass are traced one by one (as kMinShadowPacket)

// Whether indirectLightTogether serves the scene: objects the packet lanes test (no meshes or CSG solids, whose
// rays would all be traced again) and, F without area lights, a direct light of point lights only, which draws
// no random numbers (so every direction's two draws can come before any Q is shaded and still be the loop's)
// and whose shadow rays from the Qs can be traced together (directPointLightsTogether).
template <FeatureMask F>
inline bool indirectPacketsApply(const SceneView& scene, uint32_t directions) {
    if constexpr ((F & kFeatureAreaLights) != 0) return false;
    return directions >= kMinIndirectPacket && scene.meshes.count == 0 && scene.csgs.count == 0;
}

// Host: indirectLightOneByOne with the directions traced kPacketRays at a time as one packet (tracePacket: every
// direction above the geometric surface leaves from sp.above), and the shadow rays of the points Q they find
// towards each point light as another (directPointLightsTogether). The same draws, rays and sum, bit for bit,
// where indirectPacketsApply.
// What the traced directions of `traced` (bit k of `active`: ray k) found, where they found an object (not the
// sky, nor a light): Q's shading point and material, and fromQ[k] = Direct(Q) + Ke(Q) with point lights only, the
// Qs' shadow rays traced together (directPointLightsTogether). Returns those rays. lightArrivingFrom's values.
inline uint64_t lightFromFoundPoints(const SceneView& scene, PerRay<TracedRay>& traced, uint64_t active,
                                     PerRay<ShadingPoint>& points, PerRay<MaterialData>& materials,
                                     PerRay<Vec3>& fromQ, uint32_t& rays) {
    uint64_t atObject = 0;
    for (uint64_t left = active; left; left &= left - 1) {
        const int k = __builtin_ctzll(left);
        const TracedRay& r = traced[k];
        if (!r.found || r.hit.object == kNoObject) continue;
        new (points.data() + k) ShadingPoint(shadingPointAt(scene, r.ray, r.hit, materials[k]));
        atObject |= 1ull << k;
    }
    // GCC takes the const arrays for read whole (a -Wmaybe-uninitialized false positive), where only the
    // elements of atObject are read, all written above.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
    directPointLightsTogether(scene, points.data(), materials.data(), atObject, fromQ.data(), rays);  // Direct(Q)
#pragma GCC diagnostic pop
    for (uint64_t left = atObject; left; left &= left - 1) {
        const int k = __builtin_ctzll(left);
        fromQ[k] = fromQ[k] + materials[k].emissive;  // Direct(Q) + Ke(Q)
    }
    return atObject;
}

template <FeatureMask F>
inline Vec3 indirectLightTogether(const SceneView& scene, const ShadingPoint& sp, const MaterialData& m,
                                  const StrataBlock& directions, SampleStream& rng, uint32_t& rays) {
    static_assert((F & kFeatureAreaLights) == 0, "Direct(Q) of point lights only: directPointLightsTogether");
    const OrenNayarView view = orenNayarView(sp.n, sp.v, m.roughness);
    RayPacket packet;
    PerRay<TracedRay> traced;
    PerRay<ShadingPoint> points;     // Q, where atObject
    PerRay<MaterialData> materials;  // Q's, where atObject
    PerRay<Vec3> fromQ;
    const ConeFrame about = coneFrame(sp.n);
    Vec3 sum(0.0f);
    for (uint32_t start = 0; start < directions.size; start += kPacketRays) {
        const uint32_t count = directions.size - start < kPacketRays ? directions.size - start : kPacketRays;
        uint64_t active = 0;
        for (uint32_t i = 0; i < (uint32_t)kPacketRays; ++i) {
            Vec3 w(0.0f, 0.0f, 1.0f);  // lanes past count are never traced
            if (i < count) {
                w = indirectDirection(about, directions.stratum(start + i), scene.settings.indirectQuality, rng);
                if (dot(w, sp.ng) > 0.0f) active |= 1ull << i;  // below the geometric surface: contributes 0
            }
            packet.dx[i] = w.x;
            packet.dy[i] = w.y;
            packet.dz[i] = w.z;
            packet.tMax[i] = INFINITY;
        }
        rays += (uint32_t)__builtin_popcountll(active);
        tracePacket(scene, sp.above, packet, active, traced.data());
        const uint64_t atObject = lightFromFoundPoints(scene, traced, active, points, materials, fromQ, rays);
        for (uint64_t left = atObject; left; left &= left - 1) {
            const int i = __builtin_ctzll(left);
            sum += m.diffuse * evalOrenNayar(view, sp.n, traced[i].ray.direction) * fromQ[i];
        }
    }
    return sum;
}
#endif

template <FeatureMask F>
TRAZO_HD Vec3 indirectLight(const SceneView& scene, const ShadingPoint& sp, const MaterialData& m,
                            const StrataKey& strata, const StrataBlocks& blocks, SampleStream& rng,
                            uint32_t& rays) {
    const RenderSettings& settings = scene.settings;
    const uint32_t q = settings.indirectQuality;
    if (q == 0 || !(settings.colorBleeding > 0.0f) || isBlack(m.diffuse) || dot(sp.n, sp.v) <= 0.0f) return Vec3(0.0f);
    const StrataBlock directions = strata.block(kGridIndirect, 2 * q * q, blocks.indirect);
    const StrataKey atQ = strata.child(kBranchIndirect);
#if TRAZO_SHADOW_PACKETS
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
