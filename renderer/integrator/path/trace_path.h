// tracePath(): the radiance arriving along one camera ray under SPEC §7, by unidirectional path tracing with
// next-event estimation and multiple importance sampling (the power heuristic), Russian roulette, and
// `LightSampling` choosing the estimator; written once for the CPU backend and the CUDA kernel (a loop, no
// recursion, no stack of pending rays: a path is one ray at a time).
#pragma once

#include "integrator/path/path_lights.h"
#include "integrator/path/path_sampler.h"
#include "integrator/subsurface.h"
#include "integrator/surface.h"
#include "shading/bsdf.h"
#include "shading/dispersion.h"

namespace trazo {

// Russian roulette starts after this many scatterings: the first bounces carry most of an image's light.
constexpr uint32_t kRouletteStart = 3;

// What a path carries from one scattering to the next.
struct PathState {
    Vec3 radiance{0.0f};  // gathered so far
    Vec3 beta{1.0f};      // throughput: the product of f·|cos|/pdf so far
    float bsdfPdf = 0.0f;  // the density of the last scattering's direction (for MIS at the light it finds)
    bool delta = true;    // the last direction could not have been found by a light sample (camera, mirror, walk)
    int channel = -1;     // the one colour channel a dispersing path carries (SPEC §6), −1 none yet
    bool lightSampled = false;  // the light the next ray finds was sampled at every point it could come from
};

// The weight of light found by a scattered ray whose light sample density would have been lightPdf.
TRAZO_HD float foundLightWeight(const RenderSettings& s, const PathState& path, float lightPdf) {
    if (path.lightSampled) return 0.0f;
    if (path.delta || s.lightSampling == LightSampling::Bsdf) return 1.0f;
    if (s.lightSampling == LightSampling::Nee) return 0.0f;
    return powerHeuristic(path.bsdfPdf, lightPdf);
}

// Whether the BSDF has a lobe a light sample can meet (not only mirrors, sharp glass and the subsurface walk).
TRAZO_HD bool hasSmoothLobe(const Bsdf& b) {
    return (b.pick[0] > 0.0f && !b.subsurface) || b.pick[1] > 0.0f ||
           (b.pick[2] > 0.0f && b.reflectionHalfAngle > 0.0f) || (b.pick[3] > 0.0f && b.refractionHalfAngle > 0.0f);
}

// Next-event estimation at sp: one light chosen uniformly, one sample of it, its shadow ray. pointOnly: among
// the point lights alone (LightSampling bsdf, where every other light is found by scattered rays).
TRAZO_HD Vec3 sampleOneLight(const SceneView& scene, const ShadingPoint& sp, const Bsdf& bsdf, bool pointOnly,
                             const StrataKey& vertexStrata, const PathSampler& sampler, uint32_t vertex,
                             uint32_t& rays) {
    const float u = sampler.get1D(lightChoiceDimension(vertex));
    float u1, u2;
    sampler.get2D(lightPointDimension(vertex), u1, u2);
    uint32_t areaLight;
    const LightSample ls = chooseLightSample(scene, pointOnly, sp.p, vertexStrata, u, u1, u2, areaLight);
    if (!(ls.pdf > 0.0f)) return Vec3(0.0f);
    const Vec3 f = bsdf.evalCos(sp.v, ls.wi);
    if (maxComponent(f) <= 0.0f) return Vec3(0.0f);
    const Ray shadow{sp.rayOrigin(ls.wi), ls.wi};
    ++rays;
    if (pathOccluded(scene, shadow, ls.distance * (1.0f - 1e-4f), areaLight)) return Vec3(0.0f);
    const bool weighted = !ls.delta && scene.settings.lightSampling == LightSampling::Mis;
    const float w = weighted ? powerHeuristic(ls.pdf, bsdf.pdf(sp.v, ls.wi)) : 1.0f;
    return f * ls.radiance * (w / ls.pdf);
}

// The BSDF of SPEC §7 at a hit: the material's, with the path's dispersion channel (drawn at its first dispersing
// interface) and subsurface scattering in place of the diffuse lobe.
TRAZO_HD Bsdf pathBsdf(const MaterialData& m, const ShadingPoint& sp, bool entering, PathState& path,
                       SampleStream& rng) {
    Bsdf b = makeBsdf(m, sp, entering);
    if (m.dispersion > 0.0f && b.transmission > 0.0f) {
        if (path.channel < 0) {
            path.channel = minOf(int(3.0f * rng.next()), 2);
            path.beta = heroChannelWeight(path.beta, uint32_t(path.channel));
        }
        b.ior = dispersedIndex(m.refractionIndex, m.dispersion, path.channel);
        b.eta = entering ? 1.0f / b.ior : b.ior;
    }
    b.subsurface = maxComponent(m.scatteringDistance) > 0.0f;
    if (b.subsurface) b.diffuse = Vec3(m.opacity * (1.0f - m.reflectionAmount));  // the walk's albedo is Kd
    return b;
}

// Light reaching a scattering point `at` inside `object` (an index-matched medium of mean free paths d): one
// light sample, through the medium to its surface (each channel's transmittance e^(−t/d_c)) and on to the light,
// with the isotropic phase function 1/4π. The walk's own exits then find no light that this samples.
TRAZO_HD Vec3 lightInsideMedium(const SceneView& scene, uint32_t object, Vec3 at, Vec3 d, bool pointOnly,
                                const StrataKey& strata, SampleStream& rng, ClosestStack& stack, uint32_t& rays) {
    const float u = rng.next(), u1 = rng.next(), u2 = rng.next();
    uint32_t areaLight;
    const LightSample ls = chooseLightSample(scene, pointOnly, at, strata, u, u1, u2, areaLight);
    if (!(ls.pdf > 0.0f)) return Vec3(0.0f);
    const Ray toLight{at, ls.wi};
    ShapeHit shape;
    ++rays;
    if (!intersectObject(scene, scene.objects[object], toLight, ls.distance, stack, shape)) return Vec3(0.0f);
    const SurfaceHit surface{shape.t, shape.normal, object, 0, shape.triangle, shape.b1, shape.b2};
    MaterialData m;
    const ShadingPoint exit = shadingPointAt(scene, toLight, surface, m);
    const Ray shadow{exit.rayOrigin(ls.wi), ls.wi};
    ++rays;
    if (pathOccluded(scene, shadow, (ls.distance - shape.t) * (1.0f - 1e-4f), areaLight)) return Vec3(0.0f);
    const Vec3 transmittance = freePathDensity(d, shape.t, false);
    return transmittance * ls.radiance / (4.0f * kPi * ls.pdf);
}

// The path after a subsurface walk from sp (SPEC §7): the ray leaving where the walk first crosses the object's
// surface, along its last segment; false where the walk ends inside (absorbed by the model's bound). Each
// scattering inside samples a light (lightInsideMedium): under LightSampling mis and nee, the light an exit
// after a scattering finds is then already counted (the walk's own direction is the medium's BSDF sample).
TRAZO_HD bool leaveAfterWalk(const SceneView& scene, const SurfaceHit& hit, const ShadingPoint& sp,
                             const MaterialData& m, const StrataKey& strata, PathState& path, SampleStream& rng,
                             uint32_t& rays, Ray& ray) {
    const ObjectRef& object = scene.objects[hit.object];
    const bool pointOnly = scene.settings.lightSampling == LightSampling::Bsdf;
    bool scattered = false;
    Vec3 inside(0.0f);
    auto atScattering = [&](Vec3 at, Vec3 weight, ClosestStack& stack) {
        scattered = true;
        inside += weight * lightInsideMedium(scene, hit.object, at, m.scatteringDistance, pointOnly, strata, rng,
                                             stack, rays);
    };
    Ray last;
    Vec3 weight;
    const bool left = subsurfaceWalk(scene, object, sp, m, rng, rays, last, weight, atScattering);
    path.radiance += path.beta * inside;  // light sampled at scatterings counts even if the walk is later cut
    if (!left) return false;
    SurfaceHit exit;
    ++rays;
    if (!intersectScene(scene, last, INFINITY, exit) || exit.object != hit.object) return false;
    MaterialData me;
    const ShadingPoint out = shadingPointAt(scene, last, exit, me);
    path.beta *= weight;
    path.delta = true;
    path.lightSampled = scattered && !pointOnly;
    ray = Ray{out.rayOrigin(last.direction), last.direction};
    return true;
}

// pixelStrata: the pixel's strata in this pass; each vertex of the path draws its own (its child by depth). sampler:
// the pass's point of the pixel's sequence (light and BSDF samples); rng: the other draws (roulette, walks).
TRAZO_HD Vec3 tracePath(const SceneView& scene, Ray ray, const StrataKey& pixelStrata, const PathSampler& sampler,
                        SampleStream& rng, uint32_t& rays) {
    const RenderSettings& s = scene.settings;
    PathState path;
    for (uint32_t scatterings = 0;; ++scatterings) {
        SurfaceHit hit;
        ++rays;
        if (!intersectScene(scene, ray, INFINITY, hit)) {
            if (hasEnvironment(scene)) {
                const float lightPdf = lightChoicePdf(scene) * pdfEnvironment(scene, ray.direction);
                path.radiance += path.beta * environmentRadiance(scene, ray.direction) *
                                 foundLightWeight(s, path, lightPdf);
            }
            break;
        }
        if (hit.object == kNoObject) {  // an area light: its front emits, and it is black and opaque
            const AreaLightData& light = scene.areaLights[hit.areaLight];
            const float lightPdf = lightChoicePdf(scene) * areaLightPdf(light, ray.direction, hit.t);
            path.radiance += path.beta * areaLightRadiance(light, -ray.direction) * foundLightWeight(s, path, lightPdf);
            break;
        }
        MaterialData m;
        const ShadingPoint sp = shadingPointAt(scene, ray, hit, m);
        path.radiance += path.beta * m.emissive;  // both sides; emissive surfaces are found, not sampled
        if (scatterings > s.maxBounces) break;    // SPEC §7: at most MaxBounces + 1 scatterings

        const bool entering = dot(ray.direction, hit.normal) < 0.0f;
        const Bsdf bsdf = pathBsdf(m, sp, entering, path, rng);
        const StrataKey vertexStrata = pixelStrata.child(scatterings);
        if (hasSmoothLobe(bsdf)) {  // point lights are sampled whatever LightSampling says: no ray finds them
            const bool pointOnly = s.lightSampling == LightSampling::Bsdf;
            path.radiance +=
                path.beta * sampleOneLight(scene, sp, bsdf, pointOnly, vertexStrata, sampler, scatterings, rays);
        }

        const float uLobe = sampler.get1D(lobeDimension(scatterings));
        float u1, u2;
        sampler.get2D(directionDimension(scatterings), u1, u2);
        BsdfSample bs;
        if (!bsdf.sample(sp.v, uLobe, u1, u2, bs)) break;
        path.beta *= bs.weight;
        if (bs.subsurface) {
            if (!leaveAfterWalk(scene, hit, sp, m, vertexStrata, path, rng, rays, ray)) break;
        } else {
            path.bsdfPdf = bs.pdf;
            path.delta = bs.delta;
            path.lightSampled = false;
            ray = Ray{sp.rayOrigin(bs.wi), bs.wi};
        }
        if (scatterings + 1 >= kRouletteStart) {
            // The square root (Cycles' choice) keeps dim paths alive longer than β itself would: on the Cornell
            // box 16 % less relMSE for 11 % more time.
            const float survive = minOf(1.0f, sqrtf(maxComponent(path.beta)));
            if (!(rng.next() < survive)) break;
            path.beta = path.beta / survive;
        }
    }
    return path.radiance;
}

}  // namespace trazo
