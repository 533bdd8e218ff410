// FrameParams: the per-render values a pass needs besides the scene (camera, image size, seed).
#pragma once

#include <cstdint>

#include "integrator/camera_frame.h"

namespace trazo {

struct FrameParams {
    CameraFrame camera;
    uint32_t seed = 0;
    // The thesis's estimator (--fixed-grid): every pass evaluates every stratum of every grid instead of one.
    bool fixedGrid = false;
};

// Accumulation: float RGB sums and the number of samples added, per pixel.
struct AccumPixel {
    Vec3 sum;
    float count;
    TRAZO_HD void add(Vec3 sample, uint32_t /*pass*/) {
        sum += sample;
        count += 1.0f;
    }
};

}  // namespace trazo
