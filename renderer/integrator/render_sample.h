// renderSample(): one sample of one pixel, (scene, frame, pixel, pass) -> RGB. The whole integrator of
// SPEC §5, written once for the CPU backend and the CUDA kernel. The recursion of Color(depth) becomes
// an explicit, bounded stack of pending rays, each carrying the weight its colour enters the pixel with.
// Template parameter F: the feature bits the code is specialised for (sample_variants.h); code for a
// feature outside F is compiled out, and the all-features instance is the oracle every variant must match.
#pragma once

#include "integrator/direct_light.h"
#include "integrator/frame_params.h"
#include "integrator/indirect_light.h"
#include "integrator/scattering.h"
#include "integrator/surface.h"

namespace trazo {

constexpr int kMaxPendingRays = 32;                 // a branch that would overflow contributes 0
constexpr uint32_t kMaxTransmissionSegments = 16;   // SPEC §5: longer chains contribute 0
constexpr uint32_t kMaxReflectionDepth = (1u << 27) - 1;  // what PendingRay::reflectionDepth holds

struct PendingRay {
    Ray ray;
    Vec3 weight;
    uint32_t reflectionDepth : 27;  // ≤ kMaxReflectionDepth, which bounds ReflectionSteps
    uint32_t segments : 5;          // transmission segments in the current chain (≤ kMaxTransmissionSegments)
    uint32_t node;                  // identifies this ray in the pixel's sample tree (decorrelates its strata)
};
static_assert(sizeof(PendingRay) == 44, "pending rays are a GPU thread's largest array: keep them packed");
static_assert(kMaxTransmissionSegments < 32, "PendingRay::segments has 5 bits");

// A slot of the pending-ray stack, left uninitialised: Vec3 zero-initialises its members, and zeroing every slot
// for each camera ray cost more than the camera ray's traversal; a slot is always written before it is read.
union PendingSlot {
    PendingRay ray;
    TRAZO_HD PendingSlot() {}
};

// Antialiasing position s of the k×k sub-pixel centres (SPEC §5 Pixel).
TRAZO_HD void antialiasingPosition(uint32_t k, uint32_t s, uint32_t px, uint32_t py, float& x, float& y) {
    x = float(px) + (float(s % k) + 0.5f) / float(k);
    y = float(py) + (float(s / k) + 0.5f) / float(k);
}

TRAZO_HD bool materialReflects(const MaterialData& m, const RenderSettings& s, uint32_t depth) {
    return materialCanReflect(m, s) && depth < s.reflectionSteps && depth < kMaxReflectionDepth;
}

// The reflected direction of this pass: the mirror direction, or one jittered stratum of the glossy cone
// (θ uniform in [0, half-angle), φ uniform; q θ-bins × 2q φ-bins).
TRAZO_HD Vec3 sampleReflection(const ShadingPoint& sp, Vec3 d, const MaterialData& m, uint32_t quality,
                               const StrataKey& strata, SampleStream& rng) {
    const Vec3 mirror = reflectDirection(d, sp.n);
    if (m.reflectionHalfAngle <= 0.0f) return mirror;
    // One stratum per pass even with the fixed grid: the thesis's full fan at every bounce would need a stack
    // of (2q²)^ReflectionSteps rays.
    const uint32_t s = strata.stratum(kGridGlossy, 2 * quality * quality);
    const float theta = (float(s % quality) + rng.next()) / float(quality) * m.reflectionHalfAngle;
    const float phi = (float(s / quality) + rng.next()) / float(2 * quality) * 6.28318530718f;
    return directionInCone(mirror, theta, phi);
}

// A camera ray and its intersectScene answer, when the caller traced the ray already (the CPU's tile loop traces
// a block of camera rays together: integrator/camera_packet.h).
struct CameraHit {
    Ray ray;
    SurfaceHit hit;
    bool found;
};

// Color(0) along a camera ray: the whole tree of reflected and transmitted rays, as an explicit stack.
// `given`: the camera ray's intersectScene answer, or null (host x86 only: the device never passes one).
template <FeatureMask F>
TRAZO_HD Vec3 traceCameraRay(const SceneView& scene, const Ray& cameraRay, const StrataKey& pixelStrata,
                             const StrataBlocks& blocks, SampleStream& rng, uint32_t& rays,
                             const CameraHit* given = nullptr) {
#if !TRAZO_SHADOW_PACKETS
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
#if TRAZO_SHADOW_PACKETS
        if (given) {  // the first ray popped is the camera ray
            hit = given->hit;
            found = given->found;
            given = nullptr;
        } else
#endif
        found = intersectScene(scene, r.ray, INFINITY, hit);
        if (!found) {
            color += r.weight * settings.background;
            continue;
        }
        if (hit.object == kNoObject) {  // area-light rectangles are visible and return their colour
            color += r.weight * scene.areaLights[hit.areaLight].color;
            continue;
        }
        const ObjectRef& object = scene.objects[hit.object];
        MaterialData m = scene.materials[object.material];
        const Vec3 d = r.ray.direction;
        const Vec3 p = pointAt(r.ray, hit.t);
        const Vec3 pError = hitPointError(r.ray, hit.t);
        SurfacePoint surface = surfaceAt(scene, object, hit, p, materialHasTextures(m));
        applyTextures(scene, m, surface);
        const bool frontFacing = dot(d, surface.ng) < 0.0f;

        constexpr bool kRefraction = (F & kFeatureRefraction) != 0;
        constexpr bool kReflection = (F & kFeatureReflection) != 0;
        constexpr bool kIndirect = (F & kFeatureIndirect) != 0;
        if (kRefraction && !frontFacing && m.opacity < 1.0f) {
            // Leaving a transparent solid: refract out (η = n/1) or reflect internally; nothing is shaded.
            if (r.segments >= kMaxTransmissionSegments) continue;
            const Vec3 nInside = -surface.n;
            Vec3 out;
            if (!refractDirection(d, nInside, m.refractionIndex, out)) out = reflectDirection(d, nInside);
            push(PendingRay{Ray{offsetRayOrigin(p, pError, surface.ng, out), out}, r.weight, r.reflectionDepth,
                            r.segments + 1u, hashCombine(r.node, kBranchRefractedOut)});
            continue;
        }

        const ShadingPoint sp = facingShadingPoint(p, pError, d, surface);
        const StrataKey strata{pixelStrata.seed, pixelStrata.pixelIndex, pixelStrata.pass, r.node};

        // The reflected and transmitted rays go on the stack before this point is shaded, so that nothing but
        // the colour's weight stays live across the shadow and indirect rays (on a GPU, registers decide how
        // many threads run at once).
        const float a = kReflection && materialReflects(m, settings, r.reflectionDepth) ? m.reflectionAmount : 0.0f;
        if (kReflection && a > 0.0f) {
            const Vec3 dir = sampleReflection(sp, d, m, settings.reflectionQuality, strata, rng);
            if (dot(dir, sp.ng) > 0.0f) {  // directions below the geometric surface contribute 0
                push(PendingRay{Ray{offsetRayOrigin(p, pError, sp.ng, dir), dir}, r.weight * m.specular * (a * m.opacity),
                                r.reflectionDepth + 1u, 0u, hashCombine(r.node, kBranchReflected)});
            }
        }
        if (kRefraction && m.opacity < 1.0f && r.segments < kMaxTransmissionSegments) {
            // Entering: η = 1/n; total internal reflection is possible only when n < 1.
            Vec3 dir;
            if (!refractDirection(d, sp.n, 1.0f / m.refractionIndex, dir)) dir = reflectDirection(d, sp.n);
            push(PendingRay{Ray{offsetRayOrigin(p, pError, sp.ng, dir), dir}, r.weight * (1.0f - m.opacity),
                            r.reflectionDepth, r.segments + 1u, hashCombine(r.node, kBranchRefractedIn)});
        }
        color += r.weight * m.emissive;
        const float directWeight = (1.0f - a) * m.opacity;  // 0 for pure mirrors and clear glass: no shadow rays
        if (directWeight > 0.0f) {
            Vec3 local = directLight<F>(scene, sp, m, strata, blocks.areaLight, 0u, rng, rays);
            if constexpr (kIndirect) local += indirectLight<F>(scene, sp, m, strata, blocks, rng, rays);
            color += r.weight * (local * directWeight);
        }
    }
    return color;
}

// One sample of one pixel: the pass's block of antialiasing positions, averaged. `given` (host x86 only, else
// null): the scene's antialiasing side is 1, and this is the camera ray of the pixel's one position, traced.
template <FeatureMask F>
TRAZO_HD Vec3 renderSample(const SceneView& scene, const FrameParams& frame, uint32_t px, uint32_t py,
                           uint32_t pass, uint32_t& rays, const CameraHit* given = nullptr) {
    const uint32_t pixelIndex = py * frame.camera.width + px;
    SampleStream rng(frame.seed, pixelIndex, pass);
    const StrataKey pixelStrata{frame.strataSeed(pass), pixelIndex, pass, kSampleTreeRoot};
#if TRAZO_SHADOW_PACKETS
    if (given) {
        Vec3 color(0.0f);  // the sum below, of one position
        color += traceCameraRay<F>(scene, given->ray, pixelStrata, frame.blocks, rng, rays, given);
        return color;
    }
#else
    (void)given;  // only the host's tile loop passes one
#endif
    const uint32_t k = antialiasingSide(scene.settings.antialiasing);
    const StrataBlock positions = pixelStrata.block(kGridAntialiasing, k * k, frame.blocks.antialiasing);
    Vec3 color(0.0f);
    for (uint32_t j = 0; j < positions.size; ++j) {
        float x, y;
        antialiasingPosition(k, positions.stratum(j), px, py, x, y);
        color += traceCameraRay<F>(scene, generateCameraRay(frame.camera, x, y), pixelStrata, frame.blocks, rng, rays);
    }
    return positions.size == 1 ? color : color / float(positions.size);
}

}  // namespace trazo
