// The path tracer (SPEC §7): light transport by unidirectional path tracing (trace_path.h) and the kernel
// instances it is compiled in. One instance serves every scene: a path is one ray at a time, so features a
// scene lacks cost a branch each, not a stack of pending rays as in the thesis's integrator.
#pragma once

#include "integrator/camera_ray.h"
#include "integrator/frame_params.h"
#include "integrator/path/trace_path.h"

namespace trazo {

// One sample of one pixel: a camera ray through a uniform point of the pixel (SPEC §7's box filter; the
// antialiasing grid's k×k cells are its strata) and its path.
TRAZO_HD Vec3 pathSample(const SceneView& scene, const FrameParams& frame, uint32_t px, uint32_t py, uint32_t pass,
                         uint32_t& rays) {
    const uint32_t pixelIndex = py * frame.camera.width + px;
    SampleStream rng(frame.seed, pixelIndex, pass);
    const StrataKey pixelStrata{frame.strataSeed(pass), pixelIndex, pass, kSampleTreeRoot};
    const uint32_t k = antialiasingSide(scene.settings.antialiasing);
    const uint32_t cell = pixelStrata.stratum(kGridAntialiasing, k * k);
    const float x = float(px) + (float(cell % k) + rng.next()) / float(k);
    const float y = float(py) + (float(cell / k) + rng.next()) / float(k);
    const Ray ray = cameraRay(frame.camera, scene.settings, x, y, pixelStrata, 0, rng);
    return tracePath(scene, ray, pixelStrata, rng, rays);
}

struct PathIntegrator {
    enum : uint32_t { kInstances = 1 };

    // Its F is unused: the kernel is named renderPassKernel<path, 0>.
    static constexpr FeatureMask instanceFeatures(uint32_t) { return 0; }
    static constexpr uint32_t instanceFor(FeatureMask) { return 0; }

    template <FeatureMask F>
    static TRAZO_HD Vec3 sample(const SceneView& scene, const FrameParams& frame, uint32_t px, uint32_t py,
                                uint32_t pass, uint32_t& rays, const TracedRay*) {
        return pathSample(scene, frame, px, py, pass, rays);
    }
};

}  // namespace trazo
