// From the host scene and a render size to what passes need, and from a backend back to an image:
// the two ends every render shares (the CLI, the benchmarks and the tests).
#pragma once

#include "backends/backend.h"
#include "flatten/flatten.h"
#include "render/resolve.h"
#include "render/strata_plan.h"
#include "scene/scene.h"

namespace trazo {

inline FrameParams makeFrameParams(const Scene& scene, uint32_t width, uint32_t height, uint32_t seed,
                                   const StrataBlocks& blocks = StrataBlocks::ones()) {
    const Camera& c = scene.camera;
    return FrameParams{makeCameraFrame(c.pov, c.poi, c.fovDegrees, width, height), seed, blocks};
}

// The backend's current estimate, sum / count per pixel (row 0 = top).
inline std::vector<Vec3> readImage(Backend& backend) {
    std::vector<AccumPixel> accum;
    backend.readAccumulation(accum);
    return resolveImage(accum);
}

}  // namespace trazo
