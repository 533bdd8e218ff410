// The random walk of SPEC §6's subsurface scattering: from where light enters a scattering object to where it
// leaves. The thesis integrator (thesis/trace_camera_ray.h) lights the exit point through its own direct-light code.
#pragma once

#include "core/rng.h"
#include "integrator/random_walk.h"
#include "integrator/scene_intersect.h"
#include "shading/shading_point.h"
#include "shading/material.h"

namespace trazo {

// §6: a walk that scatters more often than this contributes 0 (the model's bound, not an estimator's cut).
constexpr uint32_t kMaxSubsurfaceScatterings = 256;

// Per channel of mean free path d_c: the chance e^(−s/d_c) of a free path longer than s, or with `collision`
// the density e^(−s/d_c)/d_c of one ending at s. A channel of d_c = 0 has neither (0).
TRAZO_HD float freePathDensity(float d, float s, bool collision) {
    if (!(d > 0.0f)) return 0.0f;
    const float survival = expf(-s / d);
    return collision ? survival / d : survival;
}
TRAZO_HD Vec3 freePathDensity(Vec3 d, float s, bool collision) {
    return Vec3(freePathDensity(d.x, s, collision), freePathDensity(d.y, s, collision),
                freePathDensity(d.z, s, collision));
}

// One walk of SPEC §6's S(P): it enters at P along a cosine-distributed direction about −N, takes exponential
// free paths and isotropic scatterings inside the object until it crosses the object's surface at P_out. True
// when it does within the bound, with `last` the walk's last segment, the ray from its last scattering point
// that finds P_out (the integrator traces it again, to shade P_out as a hit of its own), and `weight` what
// the lights' Direct at P_out enters S with: Kd^k, times each channel's MIS weight.
// Channels of different mean free paths: the walk draws its free paths with one channel's, chosen uniformly,
// and each channel c is weighted by its own path density over the mean of the channels' (the one-sample
// balance heuristic of spectral MIS), so every channel is unbiased and none is ever sampled with a density
// that misses its paths. The densities are kept relative (divided by their largest) so a long walk cannot
// underflow them. A channel of mean free path 0 among others scatters without end at P: the bound of 256
// scatterings makes its S 0, so it takes no part (nor is it drawn).
// atScattering(point, weight, stack), where given, is called at each scattering inside with the walk's weight
// there (Kd^k with the channels' MIS weights, the scattering's albedo included) and the walk's traversal stack,
// free between its queries: the path tracer's light samples.
struct NoScatteringVisit {
    TRAZO_HD void operator()(Vec3, Vec3, ClosestStack&) const {}
};

template <class AtScattering = NoScatteringVisit>
TRAZO_HD bool subsurfaceWalk(const SceneView& scene, const ObjectRef& object, const ShadingPoint& sp,
                             const MaterialData& m, SampleStream& rng, uint32_t& rays, Ray& last, Vec3& weight,
                             AtScattering&& atScattering = AtScattering{}) {
    const Vec3 meanPath = m.scatteringDistance;
    const bool grey = meanPath.x == meanPath.y && meanPath.y == meanPath.z;
    float heroPath = meanPath.x;
    Vec3 density(1.0f);  // per channel, the walk's density with that channel's free paths (relative)
    int channels = 3;    // those of a positive mean free path
    if (!grey) {
        for (int c = 0; c < 3; ++c) density[c] = meanPath[c] > 0.0f ? 1.0f : 0.0f;
        channels = int(density.x + density.y + density.z);
        int pick = int(float(channels) * rng.next());  // the pick-th positive channel
        if (pick >= channels) pick = channels - 1;
        for (int c = 0; c < 3; ++c)
            if (density[c] > 0.0f && pick-- == 0) heroPath = meanPath[c];
    }
    const float u1 = rng.next();
    const Vec3 entry = sampleCosineAbout(-sp.n, u1, rng.next());
    if (dot(entry, sp.ng) >= 0.0f) return false;  // a shading normal's direction that does not go inside
    Ray segment{sp.rayOrigin(entry), entry};
    Vec3 albedoPower(1.0f);  // Kd^k
    // The walk's queries go to its object alone, on a stack of the scene queries' size (the upload's check of
    // the device's stack covers every tree, so any one object's fits).
    bvh_detail::StackEntry entries[kTraversalStackSize];
    ClosestStack stack{entries, kTraversalStackSize, 0};
    for (uint32_t k = 0;; ++k) {
        const float s = sampleFreePath(heroPath, rng.next());
        ShapeHit hit;
        ++rays;
        if (intersectObject(scene, object, segment, s, stack, hit)) {
            last = segment;
            if (grey) {
                weight = albedoPower;
                return true;
            }
            density *= freePathDensity(meanPath, hit.t, false);
            const float mean = (density.x + density.y + density.z) / float(channels);
            weight = mean > 0.0f ? albedoPower * (density / mean) : Vec3(0.0f);
            return true;
        }
        if (k == kMaxSubsurfaceScatterings) return false;
        if (!grey) {
            density *= freePathDensity(meanPath, s, true);
            const float largest = maxComponent(density);
            if (largest > 0.0f) density = density / largest;
        }
        albedoPower *= m.diffuse;
        const Vec3 at = pointAt(segment, s);
        if (grey) {
            atScattering(at, albedoPower, stack);
        } else {
            const float mean = (density.x + density.y + density.z) / float(channels);
            atScattering(at, mean > 0.0f ? albedoPower * (density / mean) : Vec3(0.0f), stack);
        }
        const float v1 = rng.next();
        segment = Ray{at, sampleIsotropic(v1, rng.next())};
    }
}

}  // namespace trazo
