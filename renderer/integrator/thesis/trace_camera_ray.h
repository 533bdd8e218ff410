// traceCameraRay(): Color(0) along one camera ray, the thesis's model of SPEC §5 and §6, written once for the
// CPU backend and the CUDA kernel. The recursion of Color(depth) becomes an explicit, bounded stack of pending
// rays, each carrying the weight its colour enters the pixel with. Template parameter F: the feature bits the
// code is specialised for (thesis_integrator.h); code for a feature outside F is compiled out, and the
// all-features instance is the oracle every variant must match.
#pragma once

#include "shading/scattering.h"
#include "integrator/subsurface.h"
#include "integrator/surface.h"
#include "integrator/thesis/direct_light.h"
#include "integrator/thesis/indirect_light.h"
#include "lights/environment.h"
#include "shading/dispersion.h"
#include "shading/fresnel.h"

namespace trazo {

// What a ray that leaves the scene returns (SPEC §5, and §7's Environment): BackgroundColor, times the
// EnvironmentMap's texel where the scene has one (only the instance with every feature reads it).
template <FeatureMask F>
TRAZO_HD Vec3 missRadiance(const SceneView& scene, Vec3 d) {
    if constexpr ((F & kFeatureEnvironmentMap) != 0)
        if (scene.features & kFeatureEnvironmentMap) return environmentRadiance(scene, d);
    return scene.settings.background;
}

constexpr int kMaxPendingRays = 32;                 // a branch that would overflow contributes 0
constexpr uint32_t kMaxTransmissionSegments = 16;   // SPEC §5: longer chains contribute 0
// PendingRay::segments of the last segment of a subsurface walk (SPEC §6), traced again to light the point where
// it leaves its object as a white Lambertian surface, through the integrator's own direct-light code.
constexpr uint32_t kSubsurfaceExit = 31;
constexpr uint32_t kMaxReflectionDepth = (1u << 27) - 1;  // what PendingRay::reflectionDepth holds

struct PendingRay {
    Ray ray;
    Vec3 weight;
    uint32_t reflectionDepth : 27;  // ≤ kMaxReflectionDepth, which bounds ReflectionSteps
    uint32_t segments : 5;          // transmission segments in the current chain (≤ kMaxTransmissionSegments)
    uint32_t node;                  // identifies this ray in the pixel's sample tree (decorrelates its strata)
};
static_assert(sizeof(PendingRay) == 44, "pending rays are a GPU thread's largest array: keep them packed");
static_assert(kMaxTransmissionSegments < kSubsurfaceExit && kSubsurfaceExit < 32, "PendingRay::segments has 5 bits");

// A slot of the pending-ray stack, left uninitialised: Vec3 zero-initialises its members, and zeroing every slot
// for each camera ray cost more than the camera ray's traversal; a slot is always written before it is read.
union PendingSlot {
    PendingRay ray;
    TRAZO_HD PendingSlot() {}
};

// Whether a ray at this reflection depth may still send a reflected one (ReflectionSteps, and what the
// pending ray's depth field holds).
TRAZO_HD bool belowReflectionLimit(const RenderSettings& s, uint32_t depth) {
    return depth < s.reflectionSteps && depth < kMaxReflectionDepth;
}

TRAZO_HD bool materialReflects(const MaterialData& m, const RenderSettings& s, uint32_t depth) {
    return materialCanReflect(m, s) && belowReflectionLimit(s, depth);
}

// This pass's direction within the cone of `halfAngle` about `axis`: the axis itself for a cone of 0, else one
// jittered stratum of the cone's grid (θ uniform in [0, half-angle), φ uniform; q θ-bins × 2q φ-bins). One
// stratum per pass even with the fixed grid: the thesis's full fan at every bounce would need a stack of
// (2q²)^ReflectionSteps rays.
TRAZO_HD Vec3 sampleCone(Vec3 axis, float halfAngle, uint32_t quality, uint32_t grid, const StrataKey& strata,
                         SampleStream& rng) {
    if (halfAngle <= 0.0f) return axis;
    const uint32_t s = strata.stratum(grid, 2 * quality * quality);
    const float theta = (float(s % quality) + rng.next()) / float(quality) * halfAngle;
    const float phi = (float(s / quality) + rng.next()) / float(2 * quality) * 6.28318530718f;
    return directionInCone(axis, theta, phi);
}

// The reflected direction of this pass: the mirror direction, or a stratum of the glossy cone about it.
TRAZO_HD Vec3 sampleReflection(const ShadingPoint& sp, Vec3 d, const MaterialData& m, uint32_t quality,
                               const StrataKey& strata, SampleStream& rng) {
    return sampleCone(reflectDirection(d, sp.n), m.reflectionHalfAngle, quality, kGridGlossy, strata, rng);
}

// The transmitted direction through an interface whose normal n faces the incoming d, with η = n_in / n_out:
// Snell's direction, or with RefractionAngle > 0 (SPEC §6) a stratum of the cone about it; total internal
// reflection is a mirror either way. False when a direction of the cone does not cross the geometric surface
// (normal ng, facing d too), which contributes 0.
TRAZO_HD bool sampleTransmission(Vec3 d, Vec3 n, Vec3 ng, float eta, float halfAngle, uint32_t quality,
                                 const StrataKey& strata, SampleStream& rng, Vec3& out) {
    if (!refractDirection(d, n, eta, out)) {
        out = reflectDirection(d, n);
        return true;
    }
    if (halfAngle <= 0.0f) return true;
    out = sampleCone(out, halfAngle, quality, kGridGlossyTransmission, strata, rng);
    return dot(out, ng) < 0.0f;
}

// Leaving a transparent solid (η = n/1): with Fresnel (SPEC §6), F reflects back inside and 1 − F leaves, one
// of the two with those probabilities so the stack does not grow (total internal reflection has F = 1).
TRAZO_HD bool leaveSolid(Vec3 d, Vec3 nInside, Vec3 ngOutward, const MaterialData& m, uint32_t quality,
                         const StrataKey& strata, SampleStream& rng, Vec3& out) {
    if (m.fresnel != 0u && rng.next() < dielectricFresnel(dot(d, nInside), m.refractionIndex, 1.0f)) {
        out = reflectDirection(d, nInside);
        return true;
    }
    return sampleTransmission(d, nInside, -ngOutward, m.refractionIndex, m.refractionHalfAngle, quality, strata, rng,
                              out);
}

// SPEC §6 dispersion: a ray that carries one channel (its weight is 0 in the others) refracts with that
// channel's index; at a dispersing surface a ray of several channels first picks one to carry on (the three in
// turn over three passes), for itself and every ray it sends on.
TRAZO_HD_HOT void disperse(MaterialData& m, Vec3& weight, const StrataKey& strata) {
    if (!(m.dispersion > 0.0f)) return;
    int channel = soleChannel(weight);
    if (channel < 0 && m.opacity < 1.0f) {
        channel = int(strata.stratum(kGridDispersionChannel, 3u));
        weight = heroChannelWeight(weight, uint32_t(channel));
    }
    if (channel >= 0) m.refractionIndex = dispersedIndex(m.refractionIndex, m.dispersion, channel);
}

// Where a subsurface walk left the object: §6 lights it as a white Lambertian surface (Oren–Nayar with σ = 0 is
// exactly N·L), its normal map included; nothing else.
TRAZO_HD_HOT void becomeWalkExit(MaterialData& m) {
    m.diffuse = Vec3(1.0f);
    m.specular = m.emissive = m.scatteringDistance = Vec3(0.0f);
    m.roughness = 0.0f;
    m.opacity = 1.0f;
    m.fresnel = 0u;
}

// Pushes the rays the point sends on, reflected and transmitted (entering the solid), and returns the share a
// of reflection, which the point's own shading leaves to the reflected ray. SPEC §6 Fresnel: the reflectance F
// of the interface scales the reflection (a = ReflectionAmount·F) and splits the transmitted part T into
// (1 − F)·T and F·R′, R′ the reflection without its Ks tint, traced as one ray with R (the same cone and strata).
template <FeatureMask F, class Push>
TRAZO_HD_HOT float pushReflectedAndTransmitted(const ShadingPoint& sp, Vec3 p, float offset, const PendingRay& r, Vec3 d, Vec3 weight,
                                               const MaterialData& m, const RenderSettings& settings,
                                               const StrataKey& strata, SampleStream& rng, Push& push) {
    constexpr bool kRefraction = (F & kFeatureRefraction) != 0;
    constexpr bool kReflection = (F & kFeatureReflection) != 0;
    const bool fresnel = m.fresnel != 0u;
    const float f = fresnel ? dielectricFresnel(dot(d, sp.n), 1.0f, m.refractionIndex) : 0.0f;
    const float a = kReflection && materialReflects(m, settings, r.reflectionDepth)
                        ? m.reflectionAmount * (fresnel ? f : 1.0f)
                        : 0.0f;
    const bool reflectsTransmitted = kReflection && kRefraction && f > 0.0f &&
                                     materialReflectsTransmitted(m, settings) &&
                                     belowReflectionLimit(settings, r.reflectionDepth);
    if (kReflection && (a > 0.0f || reflectsTransmitted)) {
        const Vec3 dir = sampleReflection(sp, d, m, settings.reflectionQuality, strata, rng);
        if (dot(dir, sp.ng) > 0.0f) {  // directions below the geometric surface contribute 0
            Vec3 reflected = weight * m.specular * (a * m.opacity);
            if (reflectsTransmitted) reflected += weight * (f * (1.0f - m.opacity));
            push(PendingRay{Ray{offsetRayOrigin(p, offset, sp.ng, dir), dir}, reflected,
                            r.reflectionDepth + 1u, 0u, hashCombine(r.node, kBranchReflected)});
        }
    }
    if (kRefraction && m.opacity < 1.0f && r.segments < kMaxTransmissionSegments && f < 1.0f) {
        // Entering: η = 1/n; total internal reflection is possible only when n < 1.
        Vec3 dir;
        if (sampleTransmission(d, sp.n, sp.ng, 1.0f / m.refractionIndex, m.refractionHalfAngle,
                               settings.reflectionQuality, strata, rng, dir)) {
            const Vec3 transmitted =
                fresnel ? weight * ((1.0f - m.opacity) * (1.0f - f)) : weight * (1.0f - m.opacity);
            push(PendingRay{Ray{offsetRayOrigin(p, offset, sp.ng, dir), dir}, transmitted, r.reflectionDepth,
                            r.segments + 1u, hashCombine(r.node, kBranchRefractedIn)});
        }
    }
    return a;
}

// Direct(P) + Indirect(P) at the point, before the weight of its directly lit share. m.diffuse is 0 for a
// scattering material, whose walk takes that light; Indirect(P) uses its own diffuse colour kd, restored here.
template <FeatureMask F>
TRAZO_HD_HOT Vec3 litByLights(const SceneView& scene, const ShadingPoint& sp, bool walkExit, Vec3 kd, MaterialData& m,
                              const StrataKey& strata, const StrataBlocks& blocks, SampleStream& rng, uint32_t& rays) {
    Vec3 local = directLight<F>(scene, sp, m, strata, blocks.areaLight, 0u, rng, rays);
    m.diffuse = kd;
    if constexpr ((F & kFeatureIndirect) != 0) {
        if (!walkExit) local += indirectLight<F>(scene, sp, m, strata, blocks, rng, rays);
    }
    return local;
}

// Color(0) along a camera ray: the whole tree of reflected and transmitted rays, as an explicit stack.
// `given`: the camera ray's intersectScene answer, or null (host x86 only: the device never passes one).
template <FeatureMask F>
TRAZO_HD Vec3 traceCameraRay(const SceneView& scene, const Ray& cameraRay, const StrataKey& pixelStrata,
                             const StrataBlocks& blocks, SampleStream& rng, uint32_t& rays,
                             const TracedRay* given = nullptr) {
#if !TRAZO_HOST_PACKETS
    (void)given;  // only the host's tile loop passes one
#endif
    const RenderSettings& settings = scene.settings;
    PendingSlot stack[kMaxPendingRays];
    int pending = 0;
    stack[pending++].ray = PendingRay{cameraRay, Vec3(1.0f), 0u, 0u, kSampleTreeRoot};
    auto push = [&](const PendingRay& r) {
        if (pending < kMaxPendingRays) stack[pending++].ray = r;
    };

    Vec3 color(0.0f);
    while (pending > 0) {
        const PendingRay r = stack[--pending].ray;
        ++rays;
        SurfaceHit hit;
        bool found;
#if TRAZO_HOST_PACKETS
        if (given) {  // the first ray popped is the camera ray
            hit = given->hit;
            found = given->found;
            given = nullptr;
        } else
#endif
        found = intersectScene(scene, r.ray, INFINITY, hit);
        constexpr bool kSubsurface = (F & kFeatureSubsurface) != 0;
        const bool walkExit = kSubsurface && r.segments == kSubsurfaceExit;
        if (walkExit && (!found || hit.object == kNoObject)) continue;  // the walk's exit not found again: 0
        if (!found) {
            color += r.weight * missRadiance<F>(scene, r.ray.direction);
            continue;
        }
        if (hit.object == kNoObject) {  // area-light rectangles are visible and return their colour
            color += r.weight * scene.areaLights[hit.areaLight].color;
            continue;
        }
        const ObjectRef& object = scene.objects[hit.object];
        MaterialData m = scene.materials[object.material];
        const StrataKey strata{pixelStrata.seed, pixelStrata.pixelIndex, pixelStrata.pass, r.node};
        constexpr bool kRefraction = (F & kFeatureRefraction) != 0;
        Vec3 weight = r.weight;
        if constexpr ((F & kFeatureDispersion) != 0) disperse(m, weight, strata);
        const Vec3 d = r.ray.direction;
        const HitPoint at = hitPointOn(scene, object, r.ray, hit);
        const Vec3 p = at.p;
        const float offset = at.offset;
        SurfacePoint surface = surfaceAt(scene, object, hit, p, materialHasTextures(m));
        applyTextures(scene, m, surface);
        const bool frontFacing = dot(d, surface.ng) < 0.0f;
        if (walkExit) becomeWalkExit(m);

        if (kRefraction && !frontFacing && m.opacity < 1.0f) {
            // Leaving a transparent solid: refract out or reflect internally; nothing is shaded.
            if (r.segments >= kMaxTransmissionSegments) continue;
            Vec3 out;
            if (!leaveSolid(d, -surface.n, surface.ng, m, settings.reflectionQuality, strata, rng, out)) continue;
            push(PendingRay{Ray{offsetRayOrigin(p, offset, surface.ng, out), out}, weight, r.reflectionDepth,
                            r.segments + 1u, hashCombine(r.node, kBranchRefractedOut)});
            continue;
        }

        // (A walk's exit point faces the way the walk leaves: outwards, towards the lights.)
        const ShadingPoint sp = facingShadingPoint(p, offset, walkExit ? -d : d, surface);

        // The reflected and transmitted rays go on the stack before this point is shaded, so that nothing but
        // the colour's weight stays live across the shadow and indirect rays (on a GPU, registers decide how
        // many threads run at once).
        const float a = pushReflectedAndTransmitted<F>(sp, p, offset, r, d, weight, m, settings, strata, rng, push);
        color += weight * m.emissive;
        const float directWeight = (1.0f - a) * m.opacity;  // 0 for pure mirrors and clear glass: no shadow rays
        if (directWeight > 0.0f)
        {
            // SPEC §6 subsurface scattering: Direct(P) is the Ks·CT part of Shade at P plus S(P), the Direct of the
            // point where P's walk leaves the object, which the walk's last segment, pushed, evaluates.
            const Vec3 kd = m.diffuse;
            if ((F & kFeatureSubsurface) != 0 && materialScatters(m)) {
                Ray last;
                Vec3 walkWeight;
                if (subsurfaceWalk(scene, object, sp, m, rng, rays, last, walkWeight)) {
                    push(PendingRay{last, weight * walkWeight * directWeight, r.reflectionDepth, kSubsurfaceExit,
                                    hashCombine(r.node, kBranchSubsurface)});
                }
                m.diffuse = Vec3(0.0f);
            }
            color += weight * (litByLights<F>(scene, sp, walkExit, kd, m, strata, blocks, rng, rays) * directWeight);
        }
    }
    return color;
}

}  // namespace trazo
