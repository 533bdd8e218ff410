// The thesis's integrator (SPEC §5 and §6): Color(0) of each antialiasing position, its tree of reflected and
// transmitted rays with direct and one-bounce indirect light at each surface (trace_camera_ray.h), and the
// kernel instances it is compiled in: one per combination of the coarse feature bits below, chosen at upload
// from the scene's FeatureMask.
#pragma once

#include "integrator/camera_ray.h"
#include "integrator/frame_params.h"
#include "integrator/thesis/trace_camera_ray.h"

namespace trazo {

// Bits worth a separate instance (each guards a loop or a branch with ray work behind it): 16 instances.
constexpr FeatureMask kSpecialisedFeatures =
    kFeatureAreaLights | kFeatureReflection | kFeatureRefraction | kFeatureIndirect;
// SPEC §6's dispersion and subsurface scattering: a scene that uses either takes one more instance, with every
// feature on. The 16 instances of the other features compile exactly as without them (the same code,
// registers and spills), and a bit each would have doubled the instances, and the CUDA build, twice over.
// SPEC §7's EnvironmentMap, which a missed ray reads under the thesis's model too, joins them.
constexpr FeatureMask kRareFeatures = kFeatureDispersion | kFeatureSubsurface | kFeatureEnvironmentMap;
constexpr FeatureMask kAllSampleFeatures = kSpecialisedFeatures | kRareFeatures;

// One sample of one pixel: the pass's block of antialiasing positions, averaged. `given` (host x86 only, else
// null): the scene's antialiasing side is 1, and this is the camera ray of the pixel's one position, traced.
template <FeatureMask F>
TRAZO_HD Vec3 thesisSample(const SceneView& scene, const FrameParams& frame, uint32_t px, uint32_t py,
                           uint32_t pass, uint32_t& rays, const TracedRay* given = nullptr) {
    const uint32_t pixelIndex = py * frame.camera.width + px;
    SampleStream rng(frame.seed, pixelIndex, pass);
    const StrataKey pixelStrata{frame.strataSeed(pass), pixelIndex, pass, kSampleTreeRoot};
#if TRAZO_HOST_PACKETS
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
        const Ray ray = cameraRay(frame.camera, scene.settings, x, y, pixelStrata, j, rng);
        color += traceCameraRay<F>(scene, ray, pixelStrata, frame.blocks, rng, rays);
    }
    return positions.size == 1 ? color : color / float(positions.size);
}

struct ThesisIntegrator {
    // Constants as enumerators: the CPU kernels' -fno-weak makes static constexpr members misbehave.
    enum : uint32_t {
        kInstances = 17,
        kAllFeaturesInstance = kInstances - 1,  // every feature on: the oracle every other instance must match
    };

    static constexpr FeatureMask instanceFeatures(uint32_t i) {
        if (i == kAllFeaturesInstance) return kAllSampleFeatures;
        return ((i & 1u) ? kFeatureAreaLights : 0u) | ((i & 2u) ? kFeatureReflection : 0u) |
               ((i & 4u) ? kFeatureRefraction : 0u) | ((i & 8u) ? kFeatureIndirect : 0u);
    }

    static constexpr uint32_t instanceFor(FeatureMask mask) {
        if (mask & kRareFeatures) return kAllFeaturesInstance;
        return ((mask & kFeatureAreaLights) ? 1u : 0u) | ((mask & kFeatureReflection) ? 2u : 0u) |
               ((mask & kFeatureRefraction) ? 4u : 0u) | ((mask & kFeatureIndirect) ? 8u : 0u);
    }

    template <FeatureMask F>
    static TRAZO_HD Vec3 sample(const SceneView& scene, const FrameParams& frame, uint32_t px, uint32_t py,
                                uint32_t pass, uint32_t& rays, const TracedRay* given) {
        return thesisSample<F>(scene, frame, px, py, pass, rays, given);
    }
};

static_assert(ThesisIntegrator::instanceFeatures(ThesisIntegrator::kAllFeaturesInstance) == kAllSampleFeatures);
static_assert(ThesisIntegrator::instanceFor(kAllSampleFeatures) == ThesisIntegrator::kAllFeaturesInstance);
static_assert(ThesisIntegrator::instanceFeatures(ThesisIntegrator::kAllFeaturesInstance - 1) == kSpecialisedFeatures);

}  // namespace trazo
